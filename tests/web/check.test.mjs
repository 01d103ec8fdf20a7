// window.scenefile.check(text, name) gives exactly sfcheck --format json's
// diagnostics for every scene of testdata/ (the valid ones, the diagnostics
// corpus, glTF, OBJ, POV-Ray, the extreme numbers), the examples and the
// guide's scenes. A file in valid UTF-8 goes in as a string (as the editor
// holds it), any other as its bytes.
// Usage: node run.mjs check.test.mjs BUILD_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { isDeepStrictEqual } from 'node:util';
import { assertClean, base64, filesIn, relative, root, servedPage } from './harness.mjs';
import { sfcheck } from './native.mjs';
import { sameAsNative } from './platform_differences.mjs';

const scene = /\.(sf|txt|gltf|glb|obj|pov)$/;
const folders = [
  'testdata/valid', 'testdata/invalid', 'testdata/gltf', 'testdata/obj', 'testdata/pov/valid',
  'testdata/pov/invalid', 'testdata/pov/tutorial', 'testdata/pov/export', 'testdata/extreme',
  'testdata/view', 'testdata/render-cost', 'examples', 'docs/guide',
];

// sfcheck's names of the formats against --to's, which check() gives.
const toName = {
  'scene-file': 'sf', 'instruction-file': 'instructions', gltf: 'gltf', glb: 'glb', obj: 'obj',
  pov: 'pov', unknown: null,
};

const opened = servedPage();

// The page's check of each file: {format, diagnostics} or {thrown}.
async function checkInPage(files) {
  const inputs = files.map((file) => {
    const bytes = fs.readFileSync(file);
    const text = bytes.toString('utf8');
    const isUtf8 = Buffer.from(text, 'utf8').equals(bytes);
    return { name: path.basename(file), text: isUtf8 ? text : null, bytes: base64(file) };
  });
  return opened.page.evaluate((inputs) => inputs.map(({ name, text, bytes }) => {
    try {
      const diagnostics = window.scenefile.check(text ?? window.__bytes(bytes), name);
      return { format: diagnostics.format, diagnostics: JSON.parse(JSON.stringify(diagnostics)) };
    } catch (e) {
      return { thrown: String(e) };
    }
  }), inputs);
}

for (const folder of folders) {
  test(folder, async (t) => {
    const files = filesIn(path.join(root, folder), scene);
    assert.ok(files.length > 0, `${folder} holds no scene`);
    const results = await checkInPage(files);
    let same = 0;
    for (const [i, file] of files.entries()) {
      await t.test(path.basename(file), () => {
        const want = sfcheck(file);
        const got = results[i];
        assert.equal(got.thrown, undefined, `check threw on ${relative(file)}`);
        const name = path.basename(file);
        assert.ok(isDeepStrictEqual(got.diagnostics, want.diagnostics) ||
                  sameAsNative(name, JSON.stringify(got.diagnostics), JSON.stringify(want.diagnostics)),
                  `${relative(file)}: ${JSON.stringify(got.diagnostics)}\n` +
                  `sfcheck: ${JSON.stringify(want.diagnostics)}`);
        assert.equal(got.format, toName[want.format], `the format of ${relative(file)}`);
        ++same;
      });
    }
    console.log(`${folder}: ${same} of ${files.length} files give sfcheck's diagnostics`);
  });
}

test('the page stayed clean', () => assertClean(assert, opened.watch));
