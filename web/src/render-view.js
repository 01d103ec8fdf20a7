// The ray-traced canvas: the coarse image scaled up first, then each band
// of the full-size passes drawn over it, with a progress bar over all passes.

const MARKS = { coarse: 'scenefile-first-image', '1spp': 'scenefile-1spp-image', final: 'scenefile-final-image' };

export class RenderView {
  constructor({ canvas, progress, status }) {
    this.canvas = canvas;
    this.context = canvas.getContext('2d');
    this.progress = progress;
    this.status = status;
    this.marked = new Set();
    this.coarse = null; // a canvas holding the coarse pass
  }

  // A render's settings are known: size the canvas and plan the progress.
  begin(status, progressive) {
    if (this.canvas.width !== status.width || this.canvas.height !== status.height) {
      this.canvas.width = status.width;
      this.canvas.height = status.height;
    }
    const full = status.width * status.height;
    const passSamples = { coarse: progressive ? full / 64 : 0, '1spp': progressive ? full : 0 };
    passSamples.final = progressive && status.spp === 1 && !status.adaptive ? 0 : full * status.spp;
    this.passSamples = passSamples;
    this.total = passSamples.coarse + passSamples['1spp'] + passSamples.final;
    this.done = 0;
    this.setProgress(0);
    const adaptive = status.adaptive ? ', adaptive' : '';
    this.say(`Rendering ${status.width}×${status.height}, ${status.spp} spp${adaptive}, depth ${status.depth}…`);
    this.settings = status;
  }

  band(message) {
    const { pass, width, height, y0, y1, pixels } = message;
    const image = new ImageData(new Uint8ClampedArray(pixels.buffer, pixels.byteOffset, pixels.byteLength), width, y1 - y0);
    if (pass === 'coarse') this.drawCoarse(image, width, height, y0);
    else this.context.putImageData(image, 0, y0);
    this.done += (y1 - y0) * width * (pass === 'final' ? this.settings.spp : 1);
    this.setProgress(this.total ? this.done / this.total : 1);
    if (y1 === height) this.passDone(pass);
  }

  drawCoarse(image, width, height, y0) {
    if (!this.coarse || this.coarse.width !== width || this.coarse.height !== height) {
      this.coarse = document.createElement('canvas');
      this.coarse.width = width;
      this.coarse.height = height;
    }
    this.coarse.getContext('2d').putImageData(image, 0, y0);
    this.context.imageSmoothingEnabled = true;
    this.context.drawImage(this.coarse, 0, 0, this.canvas.width, this.canvas.height);
  }

  passDone(pass) {
    const mark = MARKS[pass];
    if (mark && !this.marked.has(mark)) {
      this.marked.add(mark);
      performance.mark(mark);
    }
    // Without a final pass the 1 spp image is the final one.
    if (pass === '1spp' && !this.passSamples.final) this.passDone('final');
  }

  finish(ms) {
    this.setProgress(1);
    const s = this.settings;
    this.say(`${s.width}×${s.height}, ${s.spp} spp${s.adaptive ? ', adaptive' : ''}: ${(ms / 1000).toFixed(2)} s on ${s.threads} thread${s.threads === 1 ? '' : 's'}`);
  }

  fail(message) {
    this.setProgress(0);
    this.say(`Not rendered: ${message}`, true);
  }

  say(text, isError = false) {
    this.status.textContent = text;
    this.status.classList.toggle('error', isError);
  }

  setProgress(fraction) {
    this.progress.value = Math.min(1, fraction);
  }
}
