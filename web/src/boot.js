// The first script the page runs, before the editor's large bundle loads:
// it starts what the first image waits for, the main module's compile and
// the render worker (which loads its own module at once). app.js takes
// them over from self.scenefileBoot.
import { compileWasm } from './wasm-loader.js';

const worker = new Worker('render-worker.js', { name: 'render' });
// A worker's messages are not queued for a handler set later: they are
// kept here until app.js takes the worker.
const messages = [];
worker.onmessage = (event) => messages.push(event.data);
self.scenefileBoot = { mainWasm: compileWasm('scenefile.wasm'), worker, messages };
