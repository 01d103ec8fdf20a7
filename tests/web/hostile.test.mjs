// Every file of the hostile corpus (testdata/hostile/{sf,instructions,gltf,
// obj,pov}, testdata/gltf-hostile), opened in the page through its file input,
// ends in its diagnostics in the problems list within 10 s, with the page
// alive and no error thrown; and window.scenefile.check of its bytes gives
// exactly the diagnostics of its .expect (tests/hostile/check_hostile.sh),
// or sfcheck's of the file alone where its neighbours change them.
// Usage: node run.mjs hostile.test.mjs BUILD_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { assertClean, base64, filesIn, relative, root, servedPage } from './harness.mjs';
import { sfcheck, shortForm } from './native.mjs';
import { sameAsNative } from './platform_differences.mjs';
import { waitForProblems } from './page.mjs';

const boundMs = 10000;
const corpus = [
  ...['sf', 'instructions', 'gltf', 'obj', 'pov'].flatMap((kind) =>
    filesIn(path.join(root, 'testdata/hostile', kind), /^(?!.*\.expect$)/)),
  ...filesIn(path.join(root, 'testdata/gltf-hostile'), /\.(gltf|glb)$/),
];
// A scene without a diagnostic, opened between two hostile files so that
// the problems list is seen to change for each.
const clean = path.join(root, 'examples/red-sphere.sf');

const opened = servedPage();

async function open(page, file) {
  await page.setInputFiles('#file-input', {
    name: path.basename(file), mimeType: 'application/octet-stream', buffer: fs.readFileSync(file),
  });
}

test('the hostile corpus is there', () => assert.ok(corpus.length >= 100, `${corpus.length} files`));

for (const file of corpus) {
  test(relative(file), { timeout: 3 * boundMs + 5000 }, async () => {
    const { page } = opened;
    const name = path.basename(file);
    const expected = fs.readFileSync(`${file}.expect`, 'utf8');

    const diagnostics = await page.evaluate(
      ({ bytes, name }) => JSON.parse(JSON.stringify(window.scenefile.check(window.__bytes(bytes), name))),
      { bytes: base64(file), name });
    await open(page, clean);
    await waitForProblems(page, [], `the problems list of ${path.basename(clean)}`, boundMs);
    const start = Date.now();
    await open(page, file);
    const want = diagnostics.map((d) => ({ line: d.line, column: d.column, code: d.code }));
    await waitForProblems(page, want, `the problems list of ${name}`, boundMs);
    const ms = Date.now() - start;
    assert.equal(await page.evaluate(() => 6 * 7), 42, 'the page answers');
    console.log(`${name}: ${diagnostics.length} diagnostics in the page in ${ms} ms`);
    assert.ok(diagnostics.length > 0, 'a diagnostic');
    // The page holds a file without its neighbours: where they change its
    // diagnostics (a link beside a glTF), those of the file alone count.
    const alone = shortForm(sfcheck(file).diagnostics);
    if (alone !== expected) console.log(`${name}: its neighbours change its diagnostics; checked alone`);
    const native = alone === expected ? expected : alone;
    assert.ok(sameAsNative(name, shortForm(diagnostics), native),
              `check() of ${name} against its .expect:\n${shortForm(diagnostics)}\n${native}`);
  });
}

test('the page stayed clean', () => assertClean(assert, opened.watch));
