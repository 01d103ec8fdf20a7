// The editor as a user meets it: a scene typed key by key with a typo gets
// its diagnostic in the problems list (line, column, message) and
// underlined in the text; the fix in the diagnostic's tooltip, one click,
// takes it away, and the text is then what `sfcheck --fix` makes of it.
// Usage: node run.mjs editor.test.mjs BUILD_DIR
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, before, test } from 'node:test';
import { assertClean, launchBrowser, openPage, startServer } from './harness.mjs';
import { sfcheck, sfcheckFix } from './native.mjs';
import { editorText, waitForProblems } from './page.mjs';

// An instruction file whose object kind is in lower case (line 10): an
// error with a fix-it ("SPHERE").
const typed = [
  'OUTPUT_FILE out.ppm', 'START CAMERA', 'LOCATION 0 1 8', 'LOOK_AT 0 0 0', 'END CAMERA',
  'START LIGHT', 'LOCATION 5 5 5', 'COLOUR 1 1 1', 'END LIGHT', 'START OBJECT sphere',
  'END OBJECT',
];

let server;
let browser;
let opened;
before(async () => {
  server = await startServer();
  browser = await launchBrowser();
  opened = await openPage(browser, server.url);
});
after(async () => {
  await browser?.close();
  await server?.close();
});

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

test('the page stayed clean', () => assertClean(assert, opened.watch));
