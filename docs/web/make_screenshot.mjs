// The picture of docs/WEB.md: the page (make web's folder) in headless
// Chromium, the default scene rendered to its last pass, the glTF view
// beside it and a hover open in the editor.
//
//   node make_screenshot.mjs WEB_DIR OUT_DIR   (cmake --build BUILD --target docs-web-images)
//
// Needs /usr/bin/chromium and tests/web's playwright-core (install-deps).
import { spawn } from 'node:child_process';
import { mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '../..');
const [webDir, outDir] = process.argv.slice(2);
if (!webDir || !outDir) {
  console.error('usage: make_screenshot.mjs WEB_DIR OUT_DIR');
  process.exit(2);
}
const require = createRequire(path.join(root, 'tests/web/package.json'));
const { chromium } = require('playwright-core');

const port = 8100 + Math.floor(Math.random() * 800);
const server = spawn('python3', [path.join(root, 'scripts/web-serve.py'), webDir, '--port', `${port}`],
                     { stdio: 'ignore' });
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1400, height: 860 } });
  for (let tries = 0; ; ++tries) {
    try {
      await page.goto(`http://127.0.0.1:${port}/`);
      break;
    } catch (error) {
      if (tries > 50) throw error;  // the server is not up yet
      await new Promise((resolve) => setTimeout(resolve, 100));
    }
  }
  await page.waitForFunction(
      () => performance.getEntriesByName('scenefile-final-image').length > 0, null,
      { timeout: 60000 });
  const word = page.locator('#editor .cm-line', { hasText: 'SHININESS' }).first();
  await word.hover({ position: { x: 40, y: 8 } });
  await page.waitForSelector('.cm-tooltip-hover', { timeout: 10000 });
  mkdirSync(outDir, { recursive: true });
  await page.screenshot({ path: path.join(outDir, 'page.png') });
} finally {
  await browser.close();
  server.kill();
}
