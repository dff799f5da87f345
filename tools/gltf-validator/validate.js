// Validates one .glb/.gltf with the Khronos glTF validator; prints the report's summary and
// messages, exits 1 when it has errors (warnings and infos are printed, not fatal).
const fs = require('fs');
const validator = require('gltf-validator');
const file = process.argv[2];
if (!file) { console.error('usage: node validate.js FILE.glb'); process.exit(2); }
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), { maxIssues: 100 })
  .then((report) => {
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages) console.log(`  [${m.severity}] ${m.code} ${m.pointer || ''}: ${m.message}`);
    process.exit(i.numErrors > 0 ? 1 : 0);
  })
  .catch((e) => { console.error(`${file}: validator failed: ${e}`); process.exit(1); });
