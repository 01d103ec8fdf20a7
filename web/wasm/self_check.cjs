// A self-check of the web module under Node, run by hand (the build does
// not run it; tests/web test the page in Chromium): the module's check,
// convert and render against the native tools' output, byte for byte.
//   node --no-experimental-fetch web/wasm/self_check.cjs BUILD_DIR [threads]
'use strict';
const { execFileSync } = require('child_process');
const fs = require('fs');
const path = require('path');

const root = path.resolve(__dirname, '..', '..');
const build = path.resolve(process.argv[2] || path.join(root, 'build'));
const threaded = process.argv[3] === 'threads';
const bin = (tool) => path.join(build, 'bin', tool);
let failures = 0;

function expect(what, ok, detail = '') {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}${detail ? ': ' + detail : ''}`);
  if (!ok) failures += 1;
}

// A native tool's standard output and status, its input on standard input.
function run(tool, args, input) {
  try {
    return { out: execFileSync(bin(tool), args, { input, maxBuffer: 1 << 30, stdio: ['pipe', 'pipe', 'ignore'] }), status: 0 };
  } catch (e) {
    return { out: e.stdout, status: e.status };
  }
}

// The pixels of a binary PPM (P6, 255) as RGBA.
function ppmPixels(bytes) {
  const header = bytes.toString('latin1', 0, 64).match(/^P6\s+(\d+)\s+(\d+)\s+255\s/);
  const [width, height] = [Number(header[1]), Number(header[2])];
  const rgb = bytes.subarray(header[0].length);
  const rgba = new Uint8Array(width * height * 4);
  for (let i = 0, j = 0; i < width * height * 3; i += 3, j += 4) {
    rgba.set(rgb.subarray(i, i + 3), j);
    rgba[j + 3] = 255;
  }
  return { width, height, rgba };
}

function compareRender(M, what, text, options, flags, input) {
  const session = new M.RenderSession(text, 'scene', JSON.stringify(options));
  const status = JSON.parse(session.status());
  if (!status.ok) {
    expect(what, false, status.error);
    session.delete();
    return;
  }
  const started = Date.now();
  const pixels = new Uint8Array(status.width * status.height * 4);
  const band = 16;
  for (let y = 0; y < status.height; y += band) {
    const rows = session.renderRows(y, Math.min(y + band, status.height), '{}');
    if (!(rows instanceof Uint8Array)) expect('a band is a Uint8Array', false, String(rows));
    pixels.set(rows, y * status.width * 4);
  }
  const seconds = (Date.now() - started) / 1000;
  session.delete();
  const out = path.join(fs.mkdtempSync('/tmp/self-check-'), 'native.ppm');
  run('sfrender', [...flags, '-o', out], input);
  const native = ppmPixels(fs.readFileSync(out));
  let same = 0;
  let most = 0;
  for (let i = 0; i < pixels.length; i += 1) {
    const d = Math.abs(pixels[i] - native.rgba[i]);
    if (d === 0) same += 1;
    most = Math.max(most, d);
  }
  expect(`${what} ${status.width}x${status.height} on ${status.threads} threads in ${seconds} s`,
         native.width === status.width && native.height === status.height && same === pixels.length,
         `${same} of ${pixels.length} channels identical, largest difference ${most}`);
}

async function main() {
  const name = threaded ? 'scenefile-threads.js' : 'scenefile.js';
  // The threaded module starts a worker for each of navigator's cores,
  // which Node 20 has no navigator to tell.
  if (typeof navigator === 'undefined') {
    globalThis.navigator = { hardwareConcurrency: require('os').cpus().length };
  }
  const create = require(path.join(build, 'web', name));
  const M = await create();
  const example = fs.readFileSync(path.join(root, 'examples/red-sphere.sf'));
  const invalid = 'CAMERA\n1 2 3\nSPHERE 1\n';
  for (const [what, text] of [['valid', example], ['invalid', invalid]]) {
    const mine = JSON.parse(M.check(new Uint8Array(text.length ? Buffer.from(text) : []), '<stdin>'));
    const native = JSON.parse(run('sfcheck', ['--format', 'json', '-'], text).out);
    expect(`check ${what}`,
           JSON.stringify(mine.diagnostics) === JSON.stringify(native.files[0].diagnostics),
           `${mine.diagnostics.length} diagnostics, format ${mine.format}`);
  }
  for (const format of JSON.parse(M.formats()).filter((f) => f.writes)) {
    for (const [what, text] of [['red-sphere.sf', example.toString()],
                                ['blue-cube.txt', fs.readFileSync(path.join(root, 'examples/blue-cube.txt'), 'utf8')]]) {
      const mine = M.convert(text, '<stdin>', format.name);
      const native = run('sfconvert', ['--to', format.name, '-', '-'], text);
      if (format.binary && !(mine.output instanceof Uint8Array)) expect('glb is a Uint8Array', false);
      const bytes = Buffer.from(mine.output);
      expect(`convert ${what} to ${format.name}`, native.status === 0 && bytes.equals(native.out),
             `${bytes.length} bytes`);
    }
  }
  expect('hover', M.hover(example.toString(), 0, 1) !== undefined, M.hover(example.toString(), 0, 1).slice(0, 80));
  expect('completion', JSON.parse(M.completion('', 0, 0)) !== null, M.completion('', 0, 0).slice(0, 80));
  const refused = new M.RenderSession(example, 'scene', '{"spp": 0}');
  expect('spp 0 refused', JSON.parse(refused.status()).error === 'spp: 0 is not between 1 and 1024',
         JSON.parse(refused.status()).error);
  refused.delete();
  compareRender(M, 'render red-sphere.sf', example, { width: 320, height: 240 },
                ['--width', '320', '--height', '240', '--threads', '1', '-'], example);
  compareRender(M, 'render red-sphere.sf adaptive', example, { width: 160, spp: 16, adaptive: 0.03 },
                ['--width', '160', '--spp', '16', '--adaptive', '0.03', '-'], example);
  compareRender(M, `render ${M.defaultSceneName()}`, M.defaultScene(), {}, [], '');
  process.exit(failures ? 1 : 0);
}

main();
