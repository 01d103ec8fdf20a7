// Runs one of the page's test scripts: node run.mjs SCRIPT.test.mjs BUILD_DIR
// Skips it (exit status 77, ctest's SKIP_RETURN_CODE) where the browser or
// the npm packages are not installed (scripts/install-deps.sh installs
// them); fails where the page was not built (make test builds it first).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const [script, buildDir] = process.argv.slice(2);
const missing = ['/usr/bin/chromium', path.join(here, 'node_modules/playwright-core'),
                 path.join(here, 'node_modules/pngjs')].filter((p) => !fs.existsSync(p));
if (missing.length > 0) {
  console.log(`skipped: ${missing.join(', ')} missing (scripts/install-deps.sh installs them)`);
  process.exit(77);
}
const index = path.join(path.resolve(buildDir), 'web/index.html');
if (!fs.existsSync(index)) {
  console.error(`${index} is missing: build the page first (make web)`);
  process.exit(1);
}
process.argv = [process.argv[0], path.join(here, script), buildDir];
await import(pathToFileURL(path.join(here, script)).href);
