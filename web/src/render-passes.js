// What the progressive render draws, and how many rows a band holds.

// A coarse image is this much smaller on each side than the final one.
export const COARSE_FACTOR = 8;
// A band should take about this long: short enough that a cancel is seen
// soon, long enough that posting bands costs little.
const BAND_TARGET_MS = 40;

// The passes for a session's settings (its status): coarse (1/8 size,
// 1 spp), 1 spp at full size, then the settings themselves where they ask
// for more; a single pass of the settings when not progressive. The first
// `drawn` passes are left out (the page drew them already).
export function planPasses(status, progressive, drawn = 0) {
  const { width, height } = status;
  const final = { name: 'final', width, height, samples: status.spp, overrides: {} };
  if (!progressive) return [final];
  const coarseWidth = Math.max(1, Math.floor(width / COARSE_FACTOR));
  const coarseHeight = Math.max(1, Math.floor(height / COARSE_FACTOR));
  const passes = [
    { name: 'coarse', width: coarseWidth, height: coarseHeight, samples: 1,
      overrides: { width: coarseWidth, height: coarseHeight, spp: 1, adaptive: false } },
    { name: '1spp', width, height, samples: 1, overrides: { spp: 1, adaptive: false } },
  ];
  if (status.spp > 1 || status.adaptive) passes.push(final);
  return passes.slice(drawn);
}

// Sizes bands from the time the last ones took per sample.
export class BandSizer {
  constructor() {
    this.msPerSample = null;
  }

  rows(pass) {
    // Unknown cost: the coarse pass is small enough to draw whole; a
    // larger first pass starts with a few rows to measure.
    if (this.msPerSample === null) return pass.name === 'coarse' ? pass.height : 4;
    const samplesPerRow = pass.width * pass.samples;
    return Math.max(1, Math.round(BAND_TARGET_MS / (this.msPerSample * samplesPerRow)));
  }

  record(pass, rows, ms) {
    const samples = rows * pass.width * pass.samples;
    if (samples > 0) this.msPerSample = Math.max(ms, 0.01) / samples;
  }
}

// A zero-delay yield: a MessageChannel's message is a task, so pending
// events (a cancel, an edit) run before the render goes on, without
// setTimeout's minimum delay.
export function yielder() {
  const channel = new MessageChannel();
  const waiting = [];
  channel.port1.onmessage = () => waiting.shift()();
  return () => new Promise((resolve) => {
    waiting.push(resolve);
    channel.port2.postMessage(null);
  });
}
