#!/usr/bin/env node
// Runs the Khronos glTF validator (the pinned npm package beside this file)
// on every .gltf/.glb named on the command line. Prints one line per file
// (its errors, warnings, infos and hints), then each of those issues
// (severity 0 error, 1 warning, 2 info, 3 hint); exit 1 when any file has
// an error, 0 otherwise, 2 when it cannot run.
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file) {
  const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file),
    maxIssues: 0,  // no limit
    // umbra embeds its buffer (data URI or GLB chunk): any external file is a failure.
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}`)),
  });
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ` +
              `${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages)
    console.log(`  severity ${m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`);
  return i.numErrors;
}

(async () => {
  const files = process.argv.slice(2);
  if (files.length === 0) {
    console.error('usage: validate.js FILE.gltf|FILE.glb ...');
    process.exit(2);
  }
  let errors = 0;
  for (const file of files) errors += await validate(file);
  process.exit(errors > 0 ? 1 : 0);
})().catch((e) => {
  console.error(`validate.js: ${e.message}`);
  process.exit(2);
});
