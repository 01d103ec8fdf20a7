// window.scenefile.convert(text, to) writes byte for byte what
// `sfconvert --to TO` writes, for every output format and the scenes that
// render.test.mjs renders, and an OBJ; where sfconvert refuses, convert
// throws with the first error's message. Each .glb passes the Khronos glTF Validator
// (tests/gltf's, installed by scripts/install-deps.sh) without an error.
// Usage: node run.mjs convert.test.mjs BUILD_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { test } from 'node:test';
import { assertClean, relative, root, sampleScenes, servedPage } from './harness.mjs';
import { defaultSceneText, sfconvert } from './native.mjs';

const formats = ['sf', 'instructions', 'gltf', 'glb', 'obj', 'pov'];
const scenes = [
  ...sampleScenes, path.join(root, 'testdata/valid/all-primitives.sf'),
  path.join(root, 'testdata/obj/all-primitives.obj'),
];

const validatorPath = path.join(root, 'tests/gltf/node_modules/gltf-validator');
const validator = fs.existsSync(validatorPath) ? createRequire(import.meta.url)(validatorPath) : null;

const opened = servedPage();

// The page's conversion: {bytes (a Buffer), isBytes} or {message, diagnostics}.
async function convertInPage(text, to) {
  const r = await opened.page.evaluate(({ text, to }) => {
    try {
      const out = window.scenefile.convert(text, to);
      if (typeof out === 'string') return { text: out };
      return { isBytes: out instanceof Uint8Array, type: out.constructor.name, b64: window.__base64(out) };
    } catch (e) {
      return { thrown: true, message: e.message, diagnostics: e.diagnostics ?? null };
    }
  }, { text, to });
  if (r.text !== undefined) r.bytes = Buffer.from(r.text, 'utf8');
  if (r.b64 !== undefined) r.bytes = Buffer.from(r.b64, 'base64');
  return r;
}

async function validate(glb, what) {
  const report = await validator.validateBytes(new Uint8Array(glb), { uri: what, maxIssues: 0 });
  const errors = report.issues.messages.filter((m) => m.severity === 0);
  assert.deepEqual(errors.map((m) => `${m.code}: ${m.message} (${m.pointer ?? ''})`), [],
                   `the validator's errors on ${what}`);
  return report.issues;
}

for (const file of scenes) {
  const what = file ? relative(file) : 'the default scene';
  test(what, async (t) => {
    const text = file ? fs.readFileSync(file, 'utf8') : defaultSceneText();
    for (const to of formats) {
      await t.test(to, async (t) => {
        const want = sfconvert(Buffer.from(text, 'utf8'), to);
        const got = await convertInPage(text, to);
        if (want.status !== 0) {
          assert.ok(got.thrown, `sfconvert refuses ${what} to ${to}; so must convert`);
          assert.ok(want.stderr.includes(got.message), `"${got.message}" in sfconvert's:\n${want.stderr}`);
          assert.ok(Array.isArray(got.diagnostics) && got.diagnostics.length > 0, 'its diagnostics');
          return;
        }
        assert.ok(!got.thrown, `convert threw: ${got.message}`);
        assert.ok(got.bytes.equals(want.output),
                  `${what} to ${to}: ${got.bytes.length} bytes, sfconvert's ${want.output.length}`);
        if (to === 'glb' && !validator) t.diagnostic('tests/gltf/node_modules/gltf-validator is not installed');
        if (to === 'glb' && validator) {
          const issues = await validate(got.bytes, `${path.basename(file ?? 'default')}.glb`);
          console.log(`${what}.glb: ${issues.numErrors} errors, ${issues.numWarnings} warnings`);
        }
        assert.equal(got.isBytes === true, to === 'glb',
                     `a Uint8Array for glb, a string for the others: ${got.type ?? 'string'}`);
      });
    }
  });
}

test('an unknown format is refused', async () => {
  const got = await convertInPage(fs.readFileSync(path.join(root, 'examples/red-sphere.sf'), 'utf8'),
                                  'ply');
  assert.ok(got.thrown);
});

test('the page stayed clean', () => assertClean(assert, opened.watch));
