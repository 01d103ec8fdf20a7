// The page as a whole: the progressive render arrives (its marks in order,
// the canvas at the end as window.scenefile.render draws the scene), an
// edit during a render cancels it and the edited scene's image comes; the
// download menu gives each format (sfconvert's bytes; an .obj with its
// .mtl, as sfconvert writes them) and the render as a PNG; the examples
// menu loads each scene; no request leaves the page and nothing is logged
// as an error.
// Usage: node run.mjs page.test.mjs BUILD_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { PNG } from 'pngjs';
import { assertClean, root, servedPage, webDir } from './harness.mjs';
import { compareImages, sfconvert, sfconvertToFiles, sfrender } from './native.mjs';
import { canvasPixels, editorText, marks } from './page.mjs';

const opened = servedPage({ acceptDownloads: true });

// The render options of the settings form, as the page reads them.
function settings(page) {
  return page.evaluate(() => {
    const options = {};
    const fields = { width: 'width', height: 'height', spp: 'spp', depth: 'depth', fov: 'fov' };
    for (const [option, id] of Object.entries(fields)) {
      const input = document.getElementById(id);
      if (!input.disabled && input.value.trim() !== '') options[option] = Number(input.value);
    }
    const adaptive = document.getElementById('adaptive').value.trim().toLowerCase();
    if (adaptive === 'on' || adaptive === 'true') options.adaptive = true;
    else if (adaptive !== '' && adaptive !== 'off' && adaptive !== 'false') options.adaptive = Number(adaptive);
    return options;
  });
}

// window.scenefile.render's image of the editor's text with OPTIONS (the
// form's settings unless given): {width, height, data}.
async function expectedImage(page, options) {
  const r = await page.evaluate(async ({ text, options }) => {
    const pixels = await window.scenefile.render(text, options);
    return { width: pixels.width, height: pixels.height, b64: window.__base64(pixels) };
  }, { text: await editorText(page), options: options ?? await settings(page) });
  return { width: r.width, height: r.height, data: Buffer.from(r.b64, 'base64') };
}

function same(got, want) {
  const c = compareImages(got, want);
  return !c.sizeDiffers && c.identical / c.total >= 0.999 && c.maxDiff <= 1;
}

// Waits until the canvas shows WANT (within 1/255 on 99.9% identical).
async function waitForCanvas(page, want, timeout = 20000) {
  const deadline = Date.now() + timeout;
  let got;
  while (Date.now() < deadline) {
    got = await canvasPixels(page);
    if (same(got, want)) return got;
    await new Promise((r) => setTimeout(r, 100));
  }
  const c = compareImages(got, want);
  assert.fail(`the canvas (${got.width}x${got.height}) is not the render (${want.width}x${want.height}) ` +
              `after ${timeout} ms: ${c.identical} of ${c.total} channels identical`);
}

test('the progressive render arrives', async () => {
  const { page } = opened;
  await page.waitForFunction(() => performance.getEntriesByName('scenefile-final-image').length > 0,
                             null, { timeout: 20000 });
  const m = await marks(page);
  const first = m['scenefile-first-image'];
  const onespp = m['scenefile-1spp-image'];
  const final = m['scenefile-final-image'];
  console.log(`marks (ms since navigation start): first image ${first?.toFixed(0)}, ` +
              `1 spp ${onespp?.toFixed(0)}, final ${final?.toFixed(0)}`);
  assert.ok(first > 0 && onespp >= first && final >= onespp, JSON.stringify(m));
  // The editor starts with the default scene, and the canvas ends with its image.
  await waitForCanvas(page, await expectedImage(page));
});

test('an edit cancels the render and the new scene\'s image comes', async () => {
  const { page } = opened;
  // A render long enough to be interrupted: 16 samples a pixel.
  await page.fill('#spp', '16');
  await page.fill('#adaptive', 'off');
  await page.waitForFunction(() => {
    const p = document.getElementById('progress');
    return p.value > 0 && p.value < 0.5;
  }, null, { timeout: 10000, polling: 10 });
  const example = fs.readFileSync(path.join(root, 'examples/blue-cube.txt'), 'utf8');
  await page.click('#editor .cm-content');
  await page.keyboard.press('Control+A');
  await page.keyboard.insertText(example);
  assert.equal(await editorText(page), example);
  const want = await expectedImage(page);
  await waitForCanvas(page, want);
  // Nothing of the cancelled render is drawn over it later.
  await new Promise((r) => setTimeout(r, 1500));
  assert.ok(same(await canvasPixels(page), want), 'the canvas changed after the edited scene\'s image');
});

// The download control's entries: [format, how to pick it].
async function downloadChoices(page) {
  return page.evaluate(() => {
    const control = document.getElementById('download');
    if (control.tagName === 'SELECT') {
      return [...control.options].filter((o) => o.value).map((o) => [o.value, 'select']);
    }
    return [...control.querySelectorAll('[data-format]')].map((b) => [b.dataset.format, 'button']);
  });
}

// The files one pick downloads, {name: bytes}: an .obj and its .mtl for
// obj, one file for the others.
async function download(page, format, how) {
  const extensions = format === 'obj' ? ['.obj', '.mtl'] : [''];
  const [files] = await Promise.all([
    Promise.all(extensions.map((extension) => page.waitForEvent('download', {
      timeout: 10000, predicate: (d) => d.suggestedFilename().endsWith(extension),
    }))),
    how === 'select' ? page.selectOption('#download', format)
                     : page.click(`#download [data-format="${format}"]`),
  ]);
  const downloaded = {};
  for (const file of files) downloaded[file.suggestedFilename()] = fs.readFileSync(await file.path());
  if (how === 'select') await page.selectOption('#download', '');
  return downloaded;
}

test('the download menu gives each format and the PNG', async () => {
  const { page } = opened;
  const choices = await downloadChoices(page);
  const formats = choices.map(([f]) => f);
  for (const f of ['sf', 'instructions', 'gltf', 'glb', 'obj', 'pov', 'png']) {
    assert.ok(formats.includes(f), `no "${f}" in the download menu (${formats})`);
  }
  const text = await editorText(page);
  for (const [format, how] of choices) {
    const downloaded = await download(page, format, how);
    const [name, bytes] = Object.entries(downloaded)[0];
    if (format === 'png') {
      const png = PNG.sync.read(bytes);
      assert.ok(same(png, await canvasPixels(page)), `${name} is not the canvas`);
      continue;
    }
    if (format === 'obj') {
      // The files sfconvert writes for NAME.obj: NAME.obj and NAME.mtl.
      const objName = Object.keys(downloaded).find((n) => n.endsWith('.obj'));
      const want = sfconvertToFiles(Buffer.from(text, 'utf8'), objName);
      assert.equal(want.status, 0, want.stderr);
      assert.deepEqual(Object.keys(downloaded).sort(), Object.keys(want.files).sort());
      for (const [file, wanted] of Object.entries(want.files)) {
        assert.ok(downloaded[file].equals(wanted), `${file}: not sfconvert's ${file}`);
        console.log(`download obj: ${file}, ${wanted.length} bytes, sfconvert's`);
      }
      continue;
    }
    const want = sfconvert(Buffer.from(text, 'utf8'), format);
    assert.equal(want.status, 0);
    assert.ok(bytes.equals(want.output), `${name}: not sfconvert --to ${format}'s bytes`);
    console.log(`download ${format}: ${name}, ${bytes.length} bytes, sfconvert's`);
  }
});

// Waits until the editor holds TEXT.
async function waitForText(page, text, what) {
  const deadline = Date.now() + 5000;
  let got;
  while (Date.now() < deadline) {
    got = await editorText(page);
    if (got === text) return;
    await new Promise((r) => setTimeout(r, 50));
  }
  assert.equal(got, text, what);
}

test('the examples menu loads each scene, and the default scene', async () => {
  const { page } = opened;
  const index = JSON.parse(fs.readFileSync(path.join(webDir, 'examples/index.json'), 'utf8'));
  const sources = { examples: 'examples', guide: 'docs/guide' };
  const files = index.groups.flatMap((g) => g.files);
  for (const folder of Object.values(sources)) {
    for (const name of fs.readdirSync(path.join(root, folder)).filter((n) => /\.(sf|txt)$/.test(n))) {
      assert.ok(files.some((f) => f.endsWith(`/${name}`)), `${folder}/${name} is not in the menu`);
    }
  }
  const values = await page.$$eval('#examples option', (os) => os.map((o) => o.value));
  assert.deepEqual(values.filter((v) => v), files, 'the menu holds index.json\'s scenes');
  for (const file of files) {
    const [folder, name] = file.split('/');
    await page.selectOption('#examples', file);
    await waitForText(page, fs.readFileSync(path.join(root, sources[folder], name), 'utf8'), file);
  }
  // The first entry: the default scene, whose render is sfrender's without a scene.
  await page.selectOption('#examples', '');
  const size = { width: 160, height: 120 };
  assert.ok(same(await expectedImage(page, size), sfrender(null, size).image),
            'the menu\'s default scene is not sfrender\'s');
});

test('the glTF view draws the scene in three.js', async () => {
  const { page } = opened;
  await page.selectOption('#examples', 'examples/red-sphere.sf');
  const canvas = page.locator('#gltf-view canvas');
  await canvas.waitFor({ timeout: 10000 });
  // The export of the scene drawn: red (the sphere) among the pixels.
  const deadline = Date.now() + 10000;
  let red = 0;
  while (Date.now() < deadline && red === 0) {
    const png = PNG.sync.read(await canvas.screenshot());
    red = 0;
    for (let i = 0; i < png.data.length; i += 4) {
      if (png.data[i] > 100 && png.data[i] > 3 * png.data[i + 1] && png.data[i] > 3 * png.data[i + 2]) ++red;
    }
    if (red === 0) await new Promise((r) => setTimeout(r, 200));
  }
  assert.equal(await page.locator('#gltf-view').getAttribute('data-error'), null);
  assert.ok(red > 0, 'no red sphere in the glTF view');
  console.log(`the glTF view: ${red} red pixels`);
});

test('the page stayed clean', () => assertClean(assert, opened.watch));
