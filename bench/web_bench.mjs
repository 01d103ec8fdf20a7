// The page's speed in headless Chromium (bench/web_bench.sh runs it):
// node bench/web_bench.mjs BUILD_DIR RUNS SCENE...
// Prints "key: value" lines (seconds, bytes) for web_bench.sh's table:
// - load: navigation start to the first (coarse) image and to the 1 spp
//   image of the default scene at 640x480, served cross-origin isolated
//   (threads) and not (one thread), a fresh browser context each load;
// - the bytes of the first load (every file the page fetched before its
//   1 spp image, gzip -9 each) and of the whole folder;
// - window.scenefile.render of each SCENE ("default": the default scene)
//   at 640x480 on 1 and on 2 threads, at 1 and 16 spp, against sfrender
//   (the sum of the steps it reports with -v: read, prepare, render; no
//   process start, no file written).
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { launchBrowser, openPage, startServer } from '../tests/web/harness.mjs';
import { defaultSceneText } from '../tests/web/native.mjs';

const [buildDir, runsText, ...scenes] = process.argv.slice(2);
const runs = Number(runsText);
const webDir = path.join(buildDir, 'web');

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
};
const gzipSize = (file) => zlib.gzipSync(fs.readFileSync(file), { level: 9 }).length;
const say = (key, value) => console.log(`${key}: ${value}`);

function filesUnder(dir) {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((e) =>
    e.isDirectory() ? filesUnder(path.join(dir, e.name)) : [path.join(dir, e.name)]);
}

async function loads(browser, isolation) {
  const server = await startServer({ dir: webDir, isolation });
  const first = [];
  const onespp = [];
  let fetched = new Set();
  try {
    for (let i = 0; i < runs; ++i) {
      const { page, context, watch } = await openPage(browser, server.url, { wait: false });
      await page.waitForFunction(() => performance.getEntriesByName('scenefile-1spp-image').length > 0,
                                 null, { timeout: 30000, polling: 10 });
      const marks = await page.evaluate(() => Object.fromEntries(
        performance.getEntriesByType('mark').map((m) => [m.name, m.startTime])));
      first.push(marks['scenefile-first-image'] / 1000);
      onespp.push(marks['scenefile-1spp-image'] / 1000);
      if (isolation) fetched = new Set(watch.requests.map((u) => new URL(u).pathname));
      await context.close();
    }
  } finally {
    await server.close();
  }
  const key = isolation ? 'isolated' : 'not_isolated';
  say(`load_${key}_first_s`, median(first));
  say(`load_${key}_1spp_s`, median(onespp));
  say(`load_${key}_first_max_s`, Math.max(...first));
  say(`load_${key}_1spp_max_s`, Math.max(...onespp));
  return fetched;
}

function nativeSeconds(scene, threads, spp) {
  const dir = fs.mkdtempSync('/tmp/web-bench-');
  const args = ['-v', '--threads', String(threads), '--width', '640', '--height', '480',
                '--spp', String(spp), '-o', path.join(dir, 'render.ppm')];
  if (scene) args.push(scene);
  const times = [];
  try {
    for (let i = 0; i < runs; ++i) {
      const r = spawnSync(path.join(buildDir, 'bin/sfrender'), args);
      if (r.status !== 0) throw new Error(`sfrender ${args.join(' ')}: ${r.stderr}`);
      const steps = r.stderr.toString().matchAll(/(?:reading|preparing the scene|rendering) took ([0-9.]+) s/g);
      times.push([...steps].reduce((sum, m) => sum + Number(m[1]), 0));
    }
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
  return median(times);
}

async function wasmSeconds(page, text, threads, spp) {
  const times = await page.evaluate(async ({ text, threads, spp, runs }) => {
    const t = [];
    for (let i = 0; i < runs + 1; ++i) {
      const start = performance.now();
      await window.scenefile.render(text, { width: 640, height: 480, threads, spp });
      t.push((performance.now() - start) / 1000);
    }
    return t.slice(1);  // the first warms the worker up
  }, { text, threads, spp, runs });
  return median(times);
}

const browser = await launchBrowser();
try {
  const fetched = await loads(browser, true);
  await loads(browser, false);

  const all = filesUnder(webDir);
  say('bytes_total_gzip', all.reduce((sum, f) => sum + gzipSize(f), 0));
  say('files_total', all.length);
  const firstLoad = all.filter((f) => fetched.has('/' + path.relative(webDir, f)) ||
                                      (fetched.has('/') && path.relative(webDir, f) === 'index.html'));
  say('bytes_first_load_gzip', firstLoad.reduce((sum, f) => sum + gzipSize(f), 0));
  say('files_first_load', firstLoad.map((f) => path.relative(webDir, f)).join(' '));

  const server = await startServer({ dir: webDir, isolation: true });
  try {
    const { page } = await openPage(browser, server.url);
    say('threads_available', await page.evaluate(() => window.scenefile.threads));
    for (const scene of scenes) {
      const file = scene === 'default' ? null : scene;
      const text = file ? fs.readFileSync(file, 'utf8') : defaultSceneText();
      const name = file ? path.basename(file) : 'default';
      for (const spp of [1, 16]) {
        for (const threads of [1, 2]) {
          const key = `render_${name}_spp${spp}_t${threads}`;
          say(`${key}_wasm_s`, await wasmSeconds(page, text, threads, spp));
          say(`${key}_native_s`, nativeSeconds(file, threads, spp));
        }
      }
    }
  } finally {
    await server.close();
  }
} finally {
  await browser.close();
}
