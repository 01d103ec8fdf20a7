// The page: the editor, the progressive render, the glTF view, the problems
// list, open and download, and window.scenefile. Everything the page needs
// is in its own folder: nothing is fetched from elsewhere.
import { Library } from './library.js';
import { RenderClient } from './render-client.js';
import { RenderView } from './render-view.js';
import { showProblems } from './problems.js';
import { readSettings, watchSettings } from './settings.js';
import { readSceneFile, fileNameFor, materialLibraryNameFor, saveBlob, acceptDrops } from './files.js';
import { spanToRange } from './positions.js';
import { createScenefileApi } from './scenefile-api.js';
import { compileWasm, instantiateModule } from './wasm-loader.js';
import { drawFirstPasses } from './first-passes.js';

/* global SCENEFILE_VERSION */
const RENDER_DEBOUNCE_MS = 100;
const GLTF_DEBOUNCE_MS = 300;
// The glTF view converts on the main thread: a scene of 150,000 spheres
// (10 MB) takes seconds and makes a 60 MB .glb. Larger texts than this are
// left out of it.
const GLTF_MAX_TEXT = 1 << 20;

const $ = (id) => document.getElementById(id);

// The editor (CodeMirror, most of the page's script) loads while the first
// image renders.
const editorModule = import('./editor.js');
// boot.js started the main module's compile and the render worker.
const boot = self.scenefileBoot ?? { mainWasm: compileWasm('scenefile.wasm'), worker: null };
const mainWasm = boot.mainWasm;
const renderer = new RenderClient(mainWasm, boot.worker ? boot : null);
const library = new Library(await instantiateModule(self.createScenefileModule, mainWasm));

// The document: its name (diagnostics' file, downloads' names) and, for a
// file that is not UTF-8, its bytes, checked until the text is edited.
const documentState = { name: 'default.sf', bytes: null, loadedDoc: null };
const view = new RenderView({ canvas: $('canvas'), progress: $('progress'), status: $('status') });
let editor = null;
let cm = null; // editor.js, once loaded

function notice(text, isError = false) {
  const node = $('notice');
  node.textContent = text;
  node.classList.toggle('error', isError);
  node.hidden = !text;
}

function documentInput(state) {
  return documentState.bytes && state.doc === documentState.loadedDoc ? documentState.bytes : state.doc.toString();
}

function selectDiagnostic(d) {
  const range = spanToRange(editor.state.doc, d.line, d.column, d.length) ?? spanToRange(editor.state.doc, 1, 0, 0);
  cm.goTo(editor, range);
}

// ---- the render: coarse, 1 spp, then the settings; every edit restarts it
let renderTimer = 0;
let renderStarted = 0;
// Counts edits: a first render drawn by the page stops at the next one.
let renderGeneration = 0;

function renderHandlers() {
  return {
    status: ({ status }) => { if (status.ok) view.begin(status, true); },
    band: (message) => view.band(message),
    done: () => view.finish(performance.now() - renderStarted),
    error: ({ message }) => view.fail(message),
  };
}

function startRender() {
  renderStarted = performance.now();
  renderer.render(documentInput(editor.state), documentState.name, readSettings($('settings')), true, renderHandlers());
}

// The page's first image: the main module draws what it can while the
// render worker loads its own (first-passes.js); the worker goes on from there.
async function startFirstRender(input) {
  renderStarted = performance.now();
  const generation = renderGeneration;
  const options = readSettings($('settings'));
  const drawn = await drawFirstPasses(library.module, input, documentState.name, options, view,
    () => renderer.threads !== null, () => generation === renderGeneration);
  if (generation !== renderGeneration) return;
  const handlers = renderHandlers();
  // The worker's status keeps the progress the page's passes made.
  if (drawn > 0) handlers.status = ({ status }) => { if (status.ok) view.settings = status; };
  renderer.render(input, documentState.name, options, true, handlers, drawn);
}

function scheduleRender() {
  renderGeneration += 1;
  renderer.cancel();
  clearTimeout(renderTimer);
  renderTimer = setTimeout(startRender, RENDER_DEBOUNCE_MS);
}

// ---- the glTF view, refreshed after a check without errors
let gltfTimer = 0;
let gltfView = null;
// The first full image, or 2 s where an edit or an error comes first.
const firstImage = new Promise((resolve) => {
  new PerformanceObserver((list, observer) => {
    if (list.getEntriesByName('scenefile-1spp-image').length) { observer.disconnect(); resolve(); }
  }).observe({ type: 'mark', buffered: true });
  setTimeout(resolve, 2000);
});

async function refreshGltf() {
  // three.js loads after the first full image: it would compete with it.
  await firstImage;
  let glb;
  try {
    glb = library.convert(documentInput(editor.state), documentState.name, 'glb');
  } catch {
    return;
  }
  if (!gltfView) {
    const { GltfView } = await import('./gltf-view.js');
    try {
      gltfView = new GltfView($('gltf-view'));
    } catch (error) {
      $('gltf-view').textContent = `The 3D view needs WebGL: ${error.message}`;
      return;
    }
  }
  gltfView.show(glb.buffer.slice(glb.byteOffset, glb.byteOffset + glb.byteLength)).catch((error) => {
    $('gltf-view').dataset.error = String(error.message ?? error);
  });
}

function checkDocument(state) {
  const result = library.check(documentInput(state), documentState.name);
  showProblems($('problems'), result.diagnostics, selectDiagnostic);
  $('problems-count').textContent = String(result.diagnostics.length);
  const size = state.doc.length;
  $('gltf-pane').classList.toggle('too-large', size > GLTF_MAX_TEXT);
  if (size <= GLTF_MAX_TEXT && !result.diagnostics.some((d) => d.severity === 'error')) {
    clearTimeout(gltfTimer);
    gltfTimer = setTimeout(() => refreshGltf().catch((error) => { $('gltf-view').dataset.error = error.message; }), GLTF_DEBOUNCE_MS);
  }
  return result.diagnostics;
}

// ---- documents: the default scene, an example, an opened file
function loadDocument({ name, text, bytes = null }) {
  documentState.name = name;
  documentState.bytes = bytes;
  cm.replaceText(editor, text);
  documentState.loadedDoc = editor.state.doc;
  $('document-name').textContent = name;
  // The same text (an empty one) is no edit: the check and the render are
  // started here for the new name and bytes.
  cm.forceLinting(editor);
  scheduleRender();
}

async function openFile(file) {
  const opened = await readSceneFile(file, library);
  loadDocument(opened);
  notice(opened.notice, opened.bytes !== null && opened.text === '');
}

async function openExample(path) {
  if (path === '') {
    loadDocument(library.defaultScene());
  } else {
    const response = await fetch(`examples/${path}`);
    if (!response.ok) throw new Error(`examples/${path}: ${response.status} ${response.statusText}`);
    loadDocument({ name: path.split('/').pop(), text: await response.text() });
  }
  notice('');
}

async function fillExamples() {
  const select = $('examples');
  const index = await (await fetch('examples/index.json')).json();
  for (const group of index.groups) {
    const optgroup = document.createElement('optgroup');
    optgroup.label = group.label;
    for (const path of group.files) {
      const option = document.createElement('option');
      option.value = path;
      option.textContent = path.split('/').pop();
      optgroup.append(option);
    }
    select.append(optgroup);
  }
}

function download(to) {
  if (to === 'png') {
    $('canvas').toBlob((blob) => saveBlob(blob, fileNameFor([], documentState.name, 'png')), 'image/png');
    return;
  }
  try {
    const name = fileNameFor(library.formats, documentState.name, to);
    // An .obj comes with its MTL file, the two files sfconvert writes.
    const mtlName = to === 'obj' ? materialLibraryNameFor(name) : '';
    const { output, materialLibrary } = library.convertFiles(documentInput(editor.state), documentState.name, to, mtlName);
    const type = to === 'glb' ? 'model/gltf-binary' : 'text/plain';
    saveBlob(new Blob([output], { type }), name);
    // sfconvert writes no empty MTL file; nor does the page.
    if (materialLibrary) saveBlob(new Blob([materialLibrary], { type }), mtlName);
    notice('');
  } catch (error) {
    notice(`Not downloaded: ${error.message}`, true);
    if (error.diagnostics?.length) showProblems($('problems'), error.diagnostics, selectDiagnostic);
  }
}

function wireToolbar() {
  $('file-input').addEventListener('change', (event) => {
    const file = event.target.files?.[0];
    if (file) openFile(file).catch((error) => notice(`Not opened: ${error.message}`, true));
    event.target.value = '';
  });
  acceptDrops(window, (file) => openFile(file).catch((error) => notice(`Not opened: ${error.message}`, true)));
  $('examples').addEventListener('change', (event) => {
    openExample(event.target.value).catch((error) => notice(`Not opened: ${error.message}`, true));
  });
  $('download').addEventListener('change', (event) => {
    if (event.target.value) download(event.target.value);
    event.target.value = '';
  });
  watchSettings($('settings'), scheduleRender);
}

function showThreads(threads) {
  $('threads').textContent = self.crossOriginIsolated
    ? `${threads} thread${threads === 1 ? '' : 's'}`
    : '1 thread: the page is not cross-origin isolated';
  const setting = $('threads-setting');
  setting.max = String(threads);
  if (!self.crossOriginIsolated) {
    setting.value = '1';
    setting.disabled = true;
  }
}

const start = library.defaultScene();
documentState.name = start.name;
$('document-name').textContent = start.name;
startFirstRender(start.text).catch((error) => view.fail(error.message));
cm = await editorModule;
editor = cm.createEditor($('editor'), start.text, {
  check: checkDocument,
  hover: (text, line, character) => library.hover(text, line, character),
  completion: (text, line, character) => library.completion(text, line, character),
}, scheduleRender);
documentState.loadedDoc = editor.state.doc;
wireToolbar();
renderer.ready.then(showThreads);
window.scenefile = createScenefileApi(library, mainWasm, SCENEFILE_VERSION);
fillExamples().catch((error) => notice(`No examples: ${error.message}`, true));
document.body.dataset.ready = 'true';
