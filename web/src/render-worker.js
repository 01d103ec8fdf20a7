// The render worker: hosts a module and renders in bands of rows, posting
// each band to the page. Between bands it yields to its event loop so that
// a cancel, or a newer render, stops the running one within a band.
//
// Protocol (page → worker): {type:'init', wasmModule?}, {type:'render', id,
// text, name, options, progressive, drawn}, {type:'cancel', id}.
// Worker → page: {type:'ready', threads, wasmModule}, then per render
// {id, type:'status', status}, {id, type:'band', pass, width, height, y0,
// y1, pixels}..., {id, type:'done'} or {id, type:'error', message,
// diagnostics}.
import { planPasses, BandSizer, yielder } from './render-passes.js';
import { compileWasm } from './wasm-loader.js';

// Threads need SharedArrayBuffer, which only a cross-origin isolated page
// has; otherwise the single-thread module renders.
const threaded = self.crossOriginIsolated === true;
const scriptName = threaded ? 'scenefile-threads.js' : 'scenefile.js';
const wasmName = threaded ? 'scenefile-threads.wasm' : 'scenefile.wasm';

// Settles with the module once it is loaded; a render sent before 'init'
// waits for it.
let startedModule = false;
let resolveModule;
const modulePromise = new Promise((resolve) => { resolveModule = resolve; });
let currentId = null;

async function loadModule(given) {
  importScripts(scriptName);
  const wasmModule = given ?? await compileWasm(new URL(wasmName, self.location).href);
  const options = {
    instantiateWasm(imports, receive) {
      WebAssembly.instantiate(wasmModule, imports).then((instance) => receive(instance, wasmModule));
      return {};
    },
    locateFile: (path) => new URL(path, self.location).href,
    // The pthreads' workers load this script, not the render worker's.
    mainScriptUrlOrBlob: new URL(scriptName, self.location).href,
  };
  const factory = threaded ? self.createScenefileThreadsModule : self.createScenefileModule;
  const module = await factory(options);
  self.postMessage({ type: 'ready', threads: threaded ? navigator.hardwareConcurrency : 1, wasmModule });
  return module;
}

const yieldToEvents = yielder();

function renderPass(session, pass, id, sizer) {
  return (async () => {
    const overrides = JSON.stringify(pass.overrides);
    for (let y0 = 0; y0 < pass.height;) {
      await yieldToEvents();
      if (currentId !== id) return false;
      const y1 = Math.min(pass.height, y0 + sizer.rows(pass));
      const started = performance.now();
      const view = session.renderRows(y0, y1, overrides);
      sizer.record(pass, y1 - y0, performance.now() - started);
      // The bytes as a Uint8Array, whatever typed array the module answers;
      // a view of its memory (a SharedArrayBuffer with threads) is copied
      // before it is sent, a copy of its own is handed over.
      const bytes = new Uint8Array(view.buffer, view.byteOffset, view.byteLength);
      const own = bytes.buffer instanceof ArrayBuffer && bytes.byteOffset === 0 && bytes.byteLength === bytes.buffer.byteLength;
      const pixels = own ? bytes : bytes.slice();
      self.postMessage({ id, type: 'band', pass: pass.name, width: pass.width, height: pass.height, y0, y1, pixels },
        [pixels.buffer]);
      y0 = y1;
    }
    return true;
  })();
}

function errorMessage(error) {
  return error?.message ?? String(error);
}

async function render({ id, text, name, options, progressive, drawn }) {
  currentId = id;
  let session = null;
  try {
    const module = await modulePromise;
    await yieldToEvents();
    if (currentId !== id) return;
    session = new module.RenderSession(text, name, JSON.stringify(options ?? {}));
    const status = JSON.parse(session.status());
    self.postMessage({ id, type: 'status', status });
    if (!status.ok) {
      self.postMessage({ id, type: 'error', message: status.error, diagnostics: status.diagnostics ?? [] });
      return;
    }
    const sizer = new BandSizer();
    for (const pass of planPasses(status, progressive, drawn ?? 0)) {
      if (!(await renderPass(session, pass, id, sizer))) return;
    }
    self.postMessage({ id, type: 'done' });
  } catch (error) {
    self.postMessage({ id, type: 'error', message: errorMessage(error), diagnostics: [] });
  } finally {
    if (session) session.delete();
    if (currentId === id) currentId = null;
  }
}

function startModule(given) {
  startedModule = true;
  const loading = loadModule(given);
  loading.catch((error) => self.postMessage({ type: 'failed', message: errorMessage(error) }));
  resolveModule(loading);
}

// The threads module starts as soon as the worker does: the page's first
// render waits only for it. The single-thread one is the page's own,
// compiled once there and handed over with 'init'.
if (threaded) startModule(null);

self.onmessage = (event) => {
  const message = event.data;
  if (message.type === 'init') {
    if (!startedModule) startModule(message.wasmModule);
  } else if (message.type === 'render') {
    render(message);
  } else if (message.type === 'cancel' && currentId === message.id) {
    currentId = null;
  }
};
