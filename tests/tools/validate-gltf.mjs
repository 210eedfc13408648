// Runs the Khronos glTF-Validator (npm gltf-validator, pinned in package.json) on each file named
// on the command line. Prints one line per file: its error, warning, info and hint counts, and
// each error; exits 1 if any file has an error (or cannot be read), 0 otherwise.
// Install once: npm ci --prefix tests/tools   (scripts/install-deps does it when npm is present)

import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

let failed = false;
for (const file of process.argv.slice(2)) {
  try {
    const bytes = new Uint8Array(await readFile(file));
    const report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 0,
      // Side files (buffers, images) resolve next to the glTF, as a viewer would.
      externalResourceFunction: (uri) =>
        readFile(path.join(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
    });
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages.filter((m) => m.severity === 0).slice(0, 20)) console.log(`  error ${m.code} at ${m.pointer ?? ''}: ${m.message}`);
    if (i.numErrors > 0) failed = true;
  } catch (e) {
    console.log(`${file}: cannot validate: ${e.message ?? e}`);
    failed = true;
  }
}
process.exit(failed ? 1 : 0);
