// The editor as a user meets it: a scene typed key by key with a typo gets
// its diagnostic in the problems list (line, column, message) and
// underlined in the text; the fix in the diagnostic's tooltip, one click,
// takes it away, and the text is then what `sfcheck --fix` makes of it.
// Hover and completion give what sfls gives at the same place.
// Usage: node run.mjs editor.test.mjs BUILD_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';
import { assertClean, servedPage } from './harness.mjs';
import { sfcheck, sfcheckFix, sflsAnswers } from './native.mjs';
import { editorPlace, editorText, waitForProblems } from './page.mjs';

// An instruction file whose object kind is in lower case (line 10): an
// error with a fix-it ("SPHERE").
const typed = [
  'OUTPUT_FILE out.ppm', 'START CAMERA', 'LOCATION 0 1 8', 'LOOK_AT 0 0 0', 'END CAMERA',
  'START LIGHT', 'LOCATION 5 5 5', 'COLOUR 1 1 1', 'END LIGHT', 'START OBJECT sphere',
  'END OBJECT',
];

const opened = servedPage();

// sfcheck's diagnostics of TEXT as a file.
function nativeCheck(text) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'web-editor-'));
  try {
    const file = path.join(dir, 'scene.txt');
    fs.writeFileSync(file, text);
    return sfcheck(file).diagnostics;
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

test('a typo typed, seen, and fixed in one click', async () => {
  const { page } = opened;
  await page.click('#editor .cm-content');
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Delete');
  for (const line of typed) {
    await page.keyboard.type(line, { delay: 5 });
    // Escape closes the completion list, so that Enter starts a new line
    // rather than taking a completion.
    await page.keyboard.press('Escape');
    await page.keyboard.press('Enter');
  }
  const text = await editorText(page);
  assert.equal(text, typed.join('\n') + '\n', 'the typed text');

  // The problems list: exactly sfcheck's diagnostics, message included.
  const want = nativeCheck(text).map((d) => ({ line: d.line, column: d.column, code: d.code, message: d.message }));
  assert.ok(want.some((d) => d.line === 10 && d.code === 'unknown-object-kind'), 'the typo is an error');
  await waitForProblems(page, want, 'the problems list');

  // The underline spans the typo.
  const underline = page.locator('#editor .cm-lintRange-error');
  await underline.first().waitFor({ timeout: 5000 });
  assert.deepEqual(await underline.allTextContents(), ['sphere']);

  // Its tooltip says the message and the hint, and offers the fix.
  await underline.first().hover();
  const tooltip = page.locator('.cm-tooltip-lint');
  await tooltip.waitFor({ timeout: 5000 });
  const typo = nativeCheck(text).find((d) => d.line === 10);
  const tip = await tooltip.textContent();
  assert.ok(tip.includes(typo.message), `the tooltip "${tip}" says the message`);
  assert.ok(tip.includes(typo.hint), `the tooltip "${tip}" says the hint`);
  await tooltip.locator('.cm-diagnosticAction').first().click();

  await waitForProblems(page, [], 'the problems list after the fix');
  assert.equal(await page.locator('#editor .cm-lintRange-error').count(), 0, 'no underline left');
  assert.equal(await editorText(page), sfcheckFix(text), 'the text is sfcheck --fix\'s');
});

// Letters and digits only: markdown as text and as the page draws it.
const words = (text) => text.replace(/[^A-Za-z0-9]+/g, ' ').trim();

test('hover and completion are the language server\'s', async () => {
  const { page } = opened;
  const text = await editorText(page);
  const hoverAt = { line: 6, character: 2 };  // LOCATION in the light
  const completeAt = { line: 10, character: 0 };  // a new line in the object
  const [hover, completion] = await sflsAnswers(
    text, [['textDocument/hover', hoverAt], ['textDocument/completion', completeAt]]);

  const place = await editorPlace(page, hoverAt);
  await page.mouse.move(place.x, place.y);
  const tooltip = page.locator('.cm-tooltip-hover');
  await tooltip.waitFor({ timeout: 5000 });
  assert.equal(words(await tooltip.innerText()), words(hover.contents.value), 'the hover');

  await page.mouse.move(0, 0);
  const at = await editorPlace(page, completeAt);
  await page.evaluate((offset) => {
    const view = window.__editorView();
    view.dispatch({ selection: { anchor: offset } });
    view.focus();
  }, at.offset);
  await page.keyboard.press('Control+Space');
  const list = page.locator('.cm-tooltip-autocomplete .cm-completionLabel');
  await list.first().waitFor({ timeout: 5000 });
  const labels = (await list.allTextContents()).sort();
  assert.deepEqual(labels, completion.items.map((i) => i.label).sort(), 'the completion list');
  await page.keyboard.press('Escape');
});

test('the page stayed clean', () => assertClean(assert, opened.watch));
