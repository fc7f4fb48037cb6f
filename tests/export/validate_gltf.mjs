// Validate glTF files with the Khronos glTF-Validator (npm gltf-validator, installed in web/):
// node validate_gltf.mjs FILE… prints one JSON line per file with the report's issue counts and
// messages (docs/design.md#exports).
import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";
import path from "node:path";
import { fileURLToPath } from "node:url";

const web = path.join(path.dirname(fileURLToPath(import.meta.url)), "..", "..", "web");
const validator = createRequire(path.join(web, "package.json"))("gltf-validator");

for (const file of process.argv.slice(2)) {
  const report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
    uri: path.basename(file),
    maxIssues: 100,
    externalResourceFunction: (uri) => readFile(path.join(path.dirname(file), uri)),
  });
  const { numErrors, numWarnings, numInfos, numHints, messages } = report.issues;
  console.log(JSON.stringify({ file, numErrors, numWarnings, numInfos, numHints,
    messages: messages.map((m) => `${m.severity} ${m.code} ${m.pointer ?? ""}: ${m.message}`),
    version: report.validatorVersion }));
}
