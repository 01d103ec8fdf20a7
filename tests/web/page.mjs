// The page's elements as the tests read them (web/index.html's ids).
import assert from 'node:assert/strict';

// The editor's whole text.
export function editorText(page) {
  return page.evaluate(() => window.__editorView().state.doc.toString());
}

// The problems list: {line, column, code, message} of each item.
export function problems(page) {
  return page.$$eval('#problems [data-code]', (items) => items.map((i) => ({
    line: Number(i.dataset.line),
    column: Number(i.dataset.column),
    code: i.dataset.code,
    message: i.querySelector('.message')?.textContent ?? null,
  })));
}

// The canvas's pixels: {width, height, data (a Buffer of RGBA)}.
export async function canvasPixels(page) {
  const r = await page.evaluate(() => {
    const canvas = document.querySelector('#canvas');
    const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    return { width: canvas.width, height: canvas.height, b64: window.__base64(data) };
  });
  return { width: r.width, height: r.height, data: Buffer.from(r.b64, 'base64') };
}

// The time of each of the page's marks since navigation start, in ms.
export function marks(page) {
  return page.evaluate(() => Object.fromEntries(
    performance.getEntriesByType('mark').map((m) => [m.name, m.startTime])));
}

// Waits until the problems list is WANT (as problems() gives it, or only
// the fields WANT's items have); fails with the difference after TIMEOUT ms.
export async function waitForProblems(page, want, what, timeout = 5000) {
  const pick = (list) => list.map((p, i) => (want[i]
    ? Object.fromEntries(Object.keys(want[i]).map((k) => [k, p[k]])) : p));
  const deadline = Date.now() + timeout;
  let got;
  for (;;) {
    got = pick(await problems(page));
    if (JSON.stringify(got) === JSON.stringify(want) || Date.now() > deadline) break;
    await new Promise((r) => setTimeout(r, 25));
  }
  assert.deepEqual(got, want, `${what} after ${timeout} ms`);
}

// The editor's place of an LSP position (0-based line, character): its
// offset, and the middle of the character there on the screen.
export function editorPlace(page, { line, character }) {
  return page.evaluate(({ line, character }) => {
    const view = window.__editorView();
    const offset = view.state.doc.line(line + 1).from + character;
    const box = view.coordsAtPos(offset);
    return { offset, x: (box.left + box.right) / 2 + 2, y: (box.top + box.bottom) / 2 };
  }, { line, character });
}
