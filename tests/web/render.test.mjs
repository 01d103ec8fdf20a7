// window.scenefile.render(text, options) against sfrender's PNG of the same
// scene and options: the default scene, every scene of examples/ and of the
// guide, a POV-Ray and a glTF scene; at least 99.9% of the channels
// identical and none off by more than 1/255. Served cross-origin isolated
// the page renders on every core (window.scenefile.threads > 1), served
// without COOP/COEP on one thread; a bad scene or option is refused with
// sfrender's words.
// Usage: node run.mjs render.test.mjs BUILD_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, before, test } from 'node:test';
import {
  assertClean, launchBrowser, openPage, relative, root, sampleScenes, startServer,
} from './harness.mjs';
import { compareImages, defaultSceneText, sfcheck, sfrender, sfrenderArgs } from './native.mjs';

let browser;
const served = {};
before(async () => {
  browser = await launchBrowser();
  for (const isolation of [true, false]) {
    const server = await startServer({ isolation });
    served[isolation] = { server, ...(await openPage(browser, server.url)) };
  }
});
after(async () => {
  await browser?.close();
  for (const s of Object.values(served)) await s.server.close();
});

// The page's render: {width, height, threads, data} or {message, diagnostics}.
async function renderInPage(page, text, options) {
  const r = await page.evaluate(async ({ text, options }) => {
    try {
      const pixels = await window.scenefile.render(text, options);
      return { width: pixels.width, height: pixels.height, threads: pixels.threads,
               length: pixels.length, isClamped: pixels instanceof Uint8ClampedArray,
               b64: window.__base64(pixels) };
    } catch (e) {
      return { rejected: true, message: e.message, diagnostics: e.diagnostics ?? null };
    }
  }, { text, options });
  if (r.b64 !== undefined) r.data = Buffer.from(r.b64, 'base64');
  return r;
}

// Renders FILE (null: the default scene) in the page and with sfrender and
// compares them; returns the page's result.
async function compareRender(page, file, options = {}) {
  const text = file ? fs.readFileSync(file, 'utf8') : defaultSceneText();
  const what = file ? relative(file) : 'the default scene';
  const want = sfrender(file, options);
  const got = await renderInPage(page, text, options);
  if (want.status !== 0) {
    assert.ok(got.rejected, `sfrender refuses ${what}; the page must too`);
    const first = sfcheck(file).diagnostics.find((d) => d.severity === 'error');
    assert.equal(got.message, first.message, `the rejection of ${what}`);
    assert.ok(Array.isArray(got.diagnostics) && got.diagnostics.length > 0, 'its diagnostics');
    console.log(`${what}: refused, as sfrender refuses it: ${got.message}`);
    return got;
  }
  assert.ok(!got.rejected, `render of ${what} rejected: ${got.message}`);
  assert.ok(got.isClamped, 'a Uint8ClampedArray');
  assert.equal(got.length, got.width * got.height * 4);
  const c = compareImages(got, want.image);
  assert.equal(c.sizeDiffers, false,
               `${what}: ${got.width}x${got.height}, sfrender ${want.image.width}x${want.image.height}`);
  const share = c.identical / c.total;
  console.log(`${what} ${sfrenderArgs(options).join(' ')}: ${c.identical} of ${c.total} channels ` +
              `identical (${(100 * share).toFixed(3)}%), largest difference ${c.maxDiff}/255, ` +
              `${got.threads} thread(s)`);
  assert.ok(share >= 0.999, `${what}: only ${(100 * share).toFixed(3)}% of the channels identical`);
  assert.ok(c.maxDiff <= 1, `${what}: a channel differs by ${c.maxDiff}/255`);
  return got;
}

test('cross-origin isolated: every core', async () => {
  const { page } = served[true];
  const [isolated, cores, threads] = await page.evaluate(
    () => [self.crossOriginIsolated, navigator.hardwareConcurrency, window.scenefile.threads]);
  assert.equal(isolated, true);
  assert.ok(cores > 1, `Chromium reports ${cores} core(s)`);
  assert.equal(threads, cores);
  assert.equal(await page.textContent('#threads'), `${cores} threads`, 'the page says so');
});

for (const file of sampleScenes) {
  test(file ? relative(file) : 'the default scene', async () => {
    const got = await compareRender(served[true].page, file);
    if (!got.rejected) assert.ok(got.threads > 1, `rendered on ${got.threads} thread(s)`);
  });
}

test('options: width, height, spp, adaptive, depth, fov', async () => {
  const scene = path.join(root, 'docs/guide/reflectivity.txt');
  await compareRender(served[true].page, scene,
                      { width: 320, height: 200, spp: 4, adaptive: 0.05, depth: 2, fov: 40 });
  await compareRender(served[true].page, scene, { width: 200, spp: 16, adaptive: 0.1, seed: 3 });
});

test('options: threads', async () => {
  const scene = path.join(root, 'examples/red-sphere.sf');
  for (const threads of [1, 2]) {
    const got = await compareRender(served[true].page, scene, { width: 160, height: 120, threads });
    assert.equal(got.threads, threads);
  }
});

// sfrender's refusal of OPTIONS, without its "sfrender: error: --".
function sfrenderRefusal(options) {
  const native = sfrender(null, options);
  assert.notEqual(native.status, 0, `sfrender ${JSON.stringify(options)}`);
  return /^sfrender: error: (?:--)?(.*)$/m.exec(native.stderr)[1];
}

test('a bad option is refused with sfrender\'s words', async () => {
  const scene = fs.readFileSync(path.join(root, 'examples/red-sphere.sf'), 'utf8');
  const refused = async (options) => {
    const got = await renderInPage(served[true].page, scene, options);
    assert.ok(got.rejected, `${JSON.stringify(options)} rendered`);
    return got.message;
  };
  for (const [option, value] of [['width', 0], ['height', 100000], ['fov', 200], ['adaptive', 2],
                                 ['threads', -1], ['seed', -1], ['width', 1.5]]) {
    assert.equal(await refused({ [option]: value }), sfrenderRefusal({ [option]: value }));
  }
  // Samples and bounces: sfrender holds them to --max-spp and --max-depth,
  // which the page has not; its range ends at their defaults.
  for (const [option, low, over] of [['spp', 0, 2000], ['depth', -1, 100]]) {
    const limit = /more than the limit of (\d+)/.exec(sfrenderRefusal({ [option]: over }))[1];
    const range = sfrenderRefusal({ [option]: low }).replace(/and \d+$/, `and ${limit}`);
    assert.equal(await refused({ [option]: low }), range);
    assert.equal(await refused({ [option]: over }), `${option}: ${over} is not between ${low + 1} and ${limit}`);
  }
  // Too many pixels for the memory: refused, not tried.
  assert.match(await refused({ width: 20000, height: 20000 }), /more than the limit of/);
});

test('not cross-origin isolated: one thread', async () => {
  const { page } = served[false];
  const [isolated, threads] = await page.evaluate(
    () => [self.crossOriginIsolated, window.scenefile.threads]);
  assert.equal(isolated, false);
  assert.equal(threads, 1);
  assert.match(await page.textContent('#threads'), /^1 thread: the page is not cross-origin isolated/);
  for (const file of [null, path.join(root, 'examples/blue-cube.txt')]) {
    const got = await compareRender(page, file);
    assert.equal(got.threads, 1);
  }
});

test('the pages stayed clean', () => {
  for (const s of Object.values(served)) assertClean(assert, s.watch);
});
