// The native tools' answers, which the page's must equal: sfcheck's JSON
// diagnostics, sfconvert's bytes, sfrender's PNG.
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import { bin } from './harness.mjs';

function run(tool, args, { cwd, input } = {}) {
  const r = spawnSync(path.join(bin, tool), args, {
    cwd, input, maxBuffer: 1 << 30, timeout: 120000,
  });
  if (r.error) throw r.error;
  return { status: r.status, stdout: r.stdout, stderr: r.stderr.toString() };
}

// sfcheck --format json on FILE alone: a copy in an empty folder, as the
// page holds a file opened in it, without the files beside it (a glTF's
// .bin, an OUTPUT_FILE's links); run there, so that `file` is its name, as
// the page names an opened file. {format, diagnostics}.
export function sfcheck(file) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'web-check-'));
  try {
    fs.copyFileSync(file, path.join(dir, path.basename(file)));
    const r = run('sfcheck', ['--format', 'json', path.basename(file)], { cwd: dir });
    return JSON.parse(r.stdout.toString()).files[0];
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// sfcheck --fix on a copy of TEXT: the fixed text.
export function sfcheckFix(text, name = 'scene.txt') {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'web-fix-'));
  try {
    const file = path.join(dir, name);
    fs.writeFileSync(file, text);
    run('sfcheck', ['--fix', name], { cwd: dir });
    return fs.readFileSync(file, 'utf8');
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// sfconvert --to TO of BYTES from standard input to standard output, as the
// page converts the editor's text (named "<stdin>"): {status, output, stderr}.
export function sfconvert(bytes, to) {
  const r = run('sfconvert', ['-q', '--to', to, '-', '-'], { input: bytes });
  return { status: r.status, output: r.stdout, stderr: r.stderr };
}

// sfconvert of BYTES from standard input to a file named OUTPUT in an empty
// folder: {status, stderr, files: {name: bytes} of every file it wrote}
// (an .obj's MTL beside it).
export function sfconvertToFiles(bytes, output) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'web-convert-'));
  try {
    const r = run('sfconvert', ['-q', '-', output], { cwd: dir, input: bytes });
    const files = {};
    for (const name of fs.readdirSync(dir)) files[name] = fs.readFileSync(path.join(dir, name));
    return { status: r.status, stderr: r.stderr, files };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// sfrender's options for the page's render() options.
export function sfrenderArgs(options) {
  const args = [];
  for (const key of ['width', 'height', 'spp', 'depth', 'fov', 'threads', 'seed']) {
    if (options[key] !== undefined) args.push(`--${key}`, String(options[key]));
  }
  if (typeof options.adaptive === 'number') args.push('--adaptive', String(options.adaptive));
  return args;
}

// sfrender of FILE (the default scene when null) with OPTIONS, to a PNG:
// {status, stderr, image: {width, height, data (RGBA)} or null}.
export function sfrender(file, options = {}) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'web-render-'));
  try {
    const png = path.join(dir, 'render.png');
    const args = ['-q', ...sfrenderArgs(options), '-o', png];
    if (file) args.push(file);
    const r = run('sfrender', args);
    const image = r.status === 0 ? PNG.sync.read(fs.readFileSync(png)) : null;
    return { status: r.status, stderr: r.stderr, image };
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// The default scene's text as write_default_scene (tests/gltf) writes it.
export function defaultSceneText() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'web-default-'));
  try {
    const file = path.join(dir, 'default.txt');
    const r = spawnSync(path.join(bin, 'write_default_scene'), [file]);
    if (r.status !== 0) throw new Error(`write_default_scene failed: ${r.stderr}`);
    return fs.readFileSync(file, 'utf8');
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

// Channel by channel: how many are identical and the largest difference.
export function compareImages(got, want) {
  if (got.width !== want.width || got.height !== want.height) {
    return { sizeDiffers: true, identical: 0, total: want.width * want.height * 4, maxDiff: 255 };
  }
  let identical = 0;
  let maxDiff = 0;
  const n = want.width * want.height * 4;
  for (let i = 0; i < n; ++i) {
    const d = Math.abs(got.data[i] - want.data[i]);
    if (d === 0) ++identical;
    else if (d > maxDiff) maxDiff = d;
  }
  return { sizeDiffers: false, identical, total: n, maxDiff };
}

// The short form of sfcheck's diagnostics (what the .expect files hold,
// tools/common/diagnostic_printer.cpp) from their JSON.
export function shortForm(diagnostics) {
  const place = (file, s) => (s.endLine !== undefined ? `${file}:${s.line}:${s.column}:` : `${file}:`);
  let out = '';
  for (const d of diagnostics) {
    const file = d.file === '' ? '<input>' : d.file;
    out += `${place(file, d)} ${d.severity}: ${d.message} [${d.code}]\n`;
    if (d.hint !== undefined) out += `  hint: ${d.hint}\n`;
    for (const note of d.notes ?? []) out += `${place(file, note)} note: ${note.message}\n`;
  }
  return out;
}

// sfls's answers for TEXT (opened as file:///scene.txt): REQUESTS is a list
// of [method, position] (LSP, 0-based, UTF-16); resolves to their results.
export function sflsAnswers(text, requests) {
  return new Promise((resolve, reject) => {
    const server = spawn(path.join(bin, 'sfls'), [], { stdio: ['pipe', 'pipe', 'ignore'] });
    const uri = 'file:///scene.txt';
    const send = (message) => {
      const body = Buffer.from(JSON.stringify({ jsonrpc: '2.0', ...message }));
      server.stdin.write(`Content-Length: ${body.length}\r\n\r\n`);
      server.stdin.write(body);
    };
    const results = new Map();
    let done = false;
    let buffer = Buffer.alloc(0);
    server.stdout.on('data', (chunk) => {
      buffer = Buffer.concat([buffer, chunk]);
      for (;;) {
        const end = buffer.indexOf('\r\n\r\n');
        if (end < 0) return;
        const length = Number(/Content-Length: *(\d+)/i.exec(buffer.subarray(0, end).toString())[1]);
        if (buffer.length < end + 4 + length) return;
        const message = JSON.parse(buffer.subarray(end + 4, end + 4 + length).toString());
        buffer = buffer.subarray(end + 4 + length);
        if (message.id !== undefined && message.id > 0) results.set(message.id, message.result);
        if (results.size === requests.length && !done) {
          done = true;
          send({ id: 0, method: 'shutdown' });
          send({ method: 'exit' });
          resolve(requests.map((_, i) => results.get(i + 1)));
        }
      }
    });
    server.on('error', reject);
    server.stdin.on('error', () => {});  // the server gone after exit
    // A client that takes snippets, as the page's editor does.
    const capabilities = { textDocument: { completion: { completionItem: { snippetSupport: true } } } };
    send({ id: 0, method: 'initialize', params: { processId: null, rootUri: null, capabilities } });
    send({ method: 'initialized', params: {} });
    send({ method: 'textDocument/didOpen',
           params: { textDocument: { uri, languageId: 'scenefile', version: 1, text } } });
    requests.forEach(([method, position], i) =>
      send({ id: i + 1, method, params: { textDocument: { uri }, position } }));
  });
}
