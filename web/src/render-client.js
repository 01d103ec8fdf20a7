// The page's side of a render worker (render-worker.js): starts renders,
// routes the worker's messages to each render's handlers, and cancels.

// A worker that has said nothing for this long while rendering is busy in
// one long call (a huge scene's preparation): a cancel then replaces it.
const STUCK_MS = 1000;

export class RenderClient {
  // wasmModule: a Promise of the single-thread module's compiled wasm,
  // handed to a worker that is not cross-origin isolated.
  // started: {worker, messages} of a worker already started (boot.js),
  // with the messages it has posted so far, or null.
  constructor(wasmModule, started = null) {
    this.wasmModule = wasmModule;
    this.started = started;
    this.nextId = 1;
    this.active = null; // {id, handlers}
    this.threads = null;
    this.ready = new Promise((resolve) => { this.resolveReady = resolve; });
    this.start();
  }

  start() {
    this.worker = this.started?.worker ?? new Worker('render-worker.js', { name: 'render' });
    this.lastHeard = performance.now();
    this.workerReady = false;
    this.worker.onmessage = (event) => this.receive(event.data);
    for (const message of this.started?.messages ?? []) this.receive(message);
    this.started = null;
    this.worker.onerror = (event) => this.fail(event.message ?? 'the render worker failed');
    if (!self.crossOriginIsolated) {
      const worker = this.worker;
      this.wasmModule.then((module) => worker.postMessage({ type: 'init', wasmModule: module }));
    }
  }

  receive(message) {
    this.lastHeard = performance.now();
    if (message.type === 'ready') {
      this.threads = message.threads;
      this.workerReady = true;
      this.resolveReady(message.threads);
      return;
    }
    if (message.type === 'failed') {
      this.fail(message.message);
      return;
    }
    if (!this.active || message.id !== this.active.id) return;
    const handlers = this.active.handlers;
    if (message.type === 'done' || message.type === 'error') this.active = null;
    handlers[message.type]?.(message);
  }

  fail(text) {
    const active = this.active;
    this.active = null;
    active?.handlers.error?.({ type: 'error', message: text, diagnostics: [] });
  }

  // Starts a render, cancelling the one running. handlers: {status, band,
  // done, error}, each given the worker's message. A progressive render
  // leaves out the first `drawn` passes (the page drew them).
  render(text, name, options, progressive, handlers, drawn = 0) {
    this.cancel();
    const id = this.nextId++;
    this.active = { id, handlers };
    this.worker.postMessage({ type: 'render', id, text, name, options, progressive, drawn });
    return id;
  }

  cancel() {
    if (!this.active) return;
    const { id } = this.active;
    this.active = null;
    if (this.workerReady && performance.now() - this.lastHeard > STUCK_MS) this.replaceWorker();
    else this.worker.postMessage({ type: 'cancel', id });
  }

  replaceWorker() {
    this.worker.terminate();
    this.start();
  }
}
