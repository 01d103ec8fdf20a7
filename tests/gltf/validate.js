// Runs the Khronos glTF Validator on each file named on the command line and
// fails when any reports an error or a warning, each of which it prints.
// Usage: node validate.js FILE.gltf|FILE.glb...
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 0,
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        const resolved = path.resolve(path.dirname(file), decodeURIComponent(uri));
        fs.readFile(resolved, (err, data) => (err ? reject(err.toString()) : resolve(data)));
      }),
  });
  for (const m of report.issues.messages.filter((m) => m.severity <= 1)) {
    const kind = ['error', 'warning', 'info', 'hint'][m.severity];
    console.log(`${file}: ${kind}: ${m.code}: ${m.message} (${m.pointer || ''})`);
  }
  return report.issues;
}

(async () => {
  let errors = 0;
  let warnings = 0;
  let infos = 0;
  for (const file of process.argv.slice(2)) {
    const issues = await validate(file);
    errors += issues.numErrors;
    warnings += issues.numWarnings;
    infos += issues.numInfos;
  }
  const files = process.argv.length - 2;
  console.log(
    `gltf-validator: ${files} files, ${errors} errors, ${warnings} warnings, ${infos} infos`);
  process.exit(errors + warnings === 0 && files > 0 ? 0 : 1);
})().catch((e) => {
  console.error(e);
  process.exit(2);
});
