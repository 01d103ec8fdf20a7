// What the page's tests share: the page served by scripts/web-serve.py on a
// free port, Debian's Chromium driven by playwright-core (which downloads no
// browser of its own), and a page watched for errors and for requests that
// leave it.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import net from 'node:net';
import path from 'node:path';
import { after, before } from 'node:test';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

// Every test script is run as node run.mjs SCRIPT BUILD_DIR.
export const buildDir = path.resolve(process.argv[2] ?? path.join(root, 'build'));
export const webDir = path.join(buildDir, 'web');
export const bin = path.join(buildDir, 'bin');

export const chromiumPath = '/usr/bin/chromium';
// Headless without a GPU, and none of the background requests Chromium
// makes to its vendor's hosts (refused here, and no business of a test).
export const chromiumArgs = [
  '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync',
];

function freePort() {
  return new Promise((resolve, reject) => {
    const server = net.createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => resolve(port));
    });
  });
}

function get(url) {
  return new Promise((resolve, reject) => {
    http.get(url, (res) => {
      res.resume();
      res.on('end', () => resolve(res));
    }).on('error', reject);
  });
}

// Serves DIR (the built page) on a free port of 127.0.0.1, cross-origin
// isolated (COOP/COEP: the threads module) unless isolation is false.
export async function startServer({ dir = webDir, isolation = true } = {}) {
  for (let attempt = 0; ; ++attempt) {
    const port = await freePort();
    const args = [path.join(root, 'scripts/web-serve.py'), dir, '--port', String(port)];
    if (!isolation) args.push('--no-isolation');
    const child = spawn('python3', args, { stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr.on('data', (d) => (stderr += d));
    const url = `http://127.0.0.1:${port}`;
    const deadline = Date.now() + 10000;
    while (Date.now() < deadline && child.exitCode === null) {
      try {
        await get(url + '/');
        return {
          url,
          headers: async (file) => (await get(`${url}/${file}`)).headers,
          close: () => new Promise((resolve) => {
            if (child.exitCode !== null) return resolve();
            child.once('exit', resolve);
            child.kill();
          }),
        };
      } catch {
        await new Promise((r) => setTimeout(r, 50));
      }
    }
    child.kill();
    // Another program may have taken the port between freePort and the bind.
    if (attempt < 2) continue;
    throw new Error(`web-serve.py did not answer on ${url}: ${stderr}`);
  }
}

export function launchBrowser() {
  return chromium.launch({ executablePath: chromiumPath, args: chromiumArgs });
}

// Opens the page at URL in a new context and waits for window.scenefile.
// The returned watch lists the page's uncaught errors, console errors,
// crashes, its requests, and those to another origin than the page's.
export async function openPage(browser, url, { wait = true, acceptDownloads = false } = {}) {
  const context = await browser.newContext({ acceptDownloads });
  await context.addInitScript(pageHelpers);
  const page = await context.newPage();
  const origin = new URL(url).origin;
  const watch = { errors: [], consoleErrors: [], requests: [], foreignRequests: [], crashed: false };
  page.on('pageerror', (e) => watch.errors.push(String(e)));
  page.on('console', (m) => {
    if (m.type() === 'error') watch.consoleErrors.push(m.text());
  });
  page.on('crash', () => (watch.crashed = true));
  // Requests of the page and of its workers (the render worker's module).
  context.on('request', (r) => {
    const u = r.url();
    watch.requests.push(u);
    if (!u.startsWith(origin + '/') && !u.startsWith('data:') && !u.startsWith('blob:')) {
      watch.foreignRequests.push(u);
    }
  });
  await page.goto(url + '/');
  if (wait) await waitForModule(page);
  return { page, context, watch };
}

// The page that a test file's tests share: served, opened in its own
// browser before the first test and closed after the last. Its page,
// context and watch (openPage's) are filled in by then.
export function servedPage(pageOptions = {}) {
  const opened = {};
  let server;
  let browser;
  before(async () => {
    server = await startServer();
    browser = await launchBrowser();
    Object.assign(opened, await openPage(browser, server.url, pageOptions));
  });
  after(async () => {
    await browser?.close();
    await server?.close();
  });
  return opened;
}

export function waitForModule(page, timeout = 30000) {
  return page.waitForFunction(() => window.scenefile !== undefined, null, { timeout });
}

// What a test asserts of every page once it is done with it.
export function assertClean(assert, watch, what = 'the page') {
  assert.equal(watch.crashed, false, `${what} crashed`);
  assert.deepEqual(watch.errors, [], `${what} threw`);
  assert.deepEqual(watch.consoleErrors, [], `${what} logged errors`);
  assert.deepEqual(watch.foreignRequests, [], `${what} requested something outside its origin`);
}

// A file's bytes for page.evaluate, which carries strings: base64, which
// the page turns back into a Uint8Array with window.__bytes.
export function base64(file) {
  return fs.readFileSync(file).toString('base64');
}

// Bytes through page.evaluate: window.__bytes(base64) in the page gives a
// Uint8Array, window.__base64(typedArray) the base64 of its bytes.
// window.__editorView() is the editor's CodeMirror view: CodeMirror keeps
// the text in its state, not in the DOM (it draws only the lines in view),
// and @codemirror/view (pinned by web/package-lock.json) hangs the view on
// its content element.
const pageHelpers = `
  window.__editorView = () => {
    const content = document.querySelector('#editor .cm-content');
    const view = content?.cmTile?.view ?? content?.cmView?.view;
    if (!view) throw new Error('no CodeMirror view under #editor');
    return view;
  };
  window.__bytes = (b64) => Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
  window.__base64 = (array) => {
    const bytes = new Uint8Array(array.buffer, array.byteOffset, array.byteLength);
    let s = '';
    for (let i = 0; i < bytes.length; i += 0x8000)
      s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
    return btoa(s);
  };`;

// The files of a folder (not recursive) whose names match RE, sorted.
export function filesIn(dir, re = /./) {
  return fs.readdirSync(dir)
    .filter((n) => re.test(n) && fs.statSync(path.join(dir, n)).isFile())
    .sort()
    .map((n) => path.join(dir, n));
}

// The scenes the page renders and converts against sfrender and sfconvert:
// the default scene (null), the examples, the guide's, a POV-Ray and a glTF
// scene.
export const sampleScenes = [
  null,
  ...filesIn(path.join(root, 'examples'), /\.(sf|txt)$/),
  ...filesIn(path.join(root, 'docs/guide'), /\.(sf|txt)$/),
  path.join(root, 'testdata/pov/tutorial/tutorial-first-scene.pov'),
  path.join(root, 'testdata/gltf/own-all-primitives.gltf'),
];

export function relative(file) {
  return path.relative(root, file);
}
