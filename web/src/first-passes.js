// The page's first image: while the render worker still loads its module
// (its threads take a while to start), the main module draws the coarse
// pass at once and the 1 spp pass in bands, yielding between them so that
// the editor loads and an edit stops it. The worker then renders the rest.
import { planPasses, BandSizer, yielder } from './render-passes.js';

function bytesOf(answer) {
  return new Uint8Array(answer.buffer, answer.byteOffset, answer.byteLength).slice();
}

// Draws into `view` the passes the main module renders before the worker
// is ready; `stillWanted()` false stops it. Answers how many were drawn.
export async function drawFirstPasses(module, input, name, options, view, workerReady, stillWanted) {
  const session = new module.RenderSession(input, name, JSON.stringify(options));
  const yieldToEvents = yielder();
  let drawn = 0;
  try {
    const status = JSON.parse(session.status());
    if (!status.ok) return 0;
    view.begin(status, true);
    const sizer = new BandSizer();
    for (const pass of planPasses(status, true).slice(0, 2)) {
      // Once the worker is ready, its threads render the rest.
      if (drawn > 0 && workerReady()) break;
      const overrides = JSON.stringify(pass.overrides);
      for (let y0 = 0; y0 < pass.height;) {
        if (drawn > 0 || y0 > 0) await yieldToEvents();
        if (!stillWanted()) return drawn;
        const y1 = Math.min(pass.height, y0 + sizer.rows(pass));
        const started = performance.now();
        const pixels = bytesOf(session.renderRows(y0, y1, overrides));
        sizer.record(pass, y1 - y0, performance.now() - started);
        view.band({ pass: pass.name, width: pass.width, height: pass.height, y0, y1, pixels });
        y0 = y1;
      }
      drawn += 1;
    }
    return drawn;
  } finally {
    session.delete();
  }
}
