// Validates one glTF asset (.glb or .gltf) with the Khronos glTF validator and prints its report
// as JSON on stdout (issues.numErrors, numWarnings, numInfos, numHints, messages[], info{}).
// Exit status 0 when the validator ran (whatever it found), 2 when it could not run.
// Usage: node validate.mjs FILE   (after `npm ci` in this folder)
import { readFile } from 'node:fs/promises';
import validator from 'gltf-validator';

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate.mjs FILE.glb');
  process.exit(2);
}
try {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, { uri: file, maxIssues: 1000 });
  console.log(JSON.stringify(report, null, 2));
} catch (error) {
  console.error(`validating ${file}: ${error}`);
  process.exit(2);
}
