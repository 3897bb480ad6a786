// Runs the Khronos glTF-Validator (npm gltf-validator) on each file and prints one JSON line per file:
// {"file", "errors", "warnings", "infos", "hints", "messages": ["CODE pointer: message", ...errors first]}.
// Usage: node validate_gltf.cjs VALIDATOR_DIR FILE...   (VALIDATOR_DIR holds node_modules/gltf-validator)
// Exit status: 0 when every file has no errors, 1 when some file has errors, 2 when the validator is missing.
'use strict';
const fs = require('fs');
const path = require('path');
const [dir, ...files] = process.argv.slice(2);
let validator;
try {
  validator = require(path.resolve(dir, 'node_modules', 'gltf-validator'));
} catch (e) {
  console.error(`validate_gltf: no gltf-validator under ${dir} (scripts/setup.sh installs it): ${e.message}`);
  process.exit(2);
}
(async () => {
  let failed = false;
  for (const file of files) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
      uri: path.basename(file),
      maxIssues: 100,
      externalResourceFunction: (uri) => new Promise((resolve, reject) =>
        fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)),
                    (err, data) => err ? reject(err.toString()) : resolve(new Uint8Array(data)))),
    });
    const issues = report.issues;
    const messages = issues.messages.slice().sort((a, b) => a.severity - b.severity)
                           .map((m) => `${m.code} ${m.pointer || ''}: ${m.message}`);
    failed = failed || issues.numErrors > 0;
    console.log(JSON.stringify({file, errors: issues.numErrors, warnings: issues.numWarnings,
                                infos: issues.numInfos, hints: issues.numHints, messages}));
  }
  process.exit(failed ? 1 : 0);
})().catch((e) => { console.error(`validate_gltf: ${e}`); process.exit(1); });
