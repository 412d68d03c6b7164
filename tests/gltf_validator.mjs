// ctest gltf.validator (gltf_validator.sh): the Khronos glTF-Validator (npm gltf-validator, pinned in package.json)
// validates each .gltf given; any error fails. Prints one line per file (errors, warnings, infos, hints) and the
// messages of every issue that is not a hint.
// Usage: node gltf_validator.mjs NODE_MODULES FILE.gltf…
import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import path from "node:path";

const [modules, ...files] = process.argv.slice(2);
const require = createRequire(path.join(path.resolve(modules), "noop.js"));
const validator = require("gltf-validator");
if (files.length === 0) {
  console.error("gltf_validator.mjs: no .gltf files given");
  process.exit(2);
}
let failed = 0;
for (const file of files) {
  const report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
    uri: path.basename(file),
    maxIssues: 0,
    // The assets are self-contained (data: URIs): any external resource is a failure.
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri} in ${file}`)),
  });
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages)
    if (m.severity < 3) console.log(`  [${["error", "warning", "info"][m.severity]}] ${m.code} ${m.pointer ?? ""}: ${m.message}`);
  if (i.numErrors > 0 || i.truncated) failed++;
  // A layered asset (a folder layered-*): the validator must know its extensions (no warning, e.g.
  // UNSUPPORTED_EXTENSION) and see KHR_materials_clearcoat and/or KHR_materials_iridescence used.
  if (path.basename(path.dirname(path.dirname(file))).startsWith("layered")) {
    const used = report.info?.extensionsUsed ?? [];
    const known = used.filter((e) => e === "KHR_materials_clearcoat" || e === "KHR_materials_iridescence");
    if (i.numWarnings > 0 || known.length === 0 || known.length !== used.length) {
      console.log(`  layered asset: expected known layer extensions and no warning, got ${JSON.stringify(used)}`);
      failed++;
    }
  }
  if (report.info?.materialCount !== 1 || report.info?.drawCallCount !== 1) {
    console.log(`  expected one material and one draw call, got ${JSON.stringify(report.info)}`);
    failed++;
  }
}
console.log(`${files.length - failed} of ${files.length} assets valid (validator ${validator.version()})`);
process.exit(failed === 0 ? 0 : 1);
