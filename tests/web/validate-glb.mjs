#!/usr/bin/env node
// Runs the Khronos glTF validator (npm `gltf-validator`, the library `gltf-transform validate`
// wraps) on every .glb under DIR, recursively.
//
// Prints one line per file: "<relative path>: <E> errors, <W> warnings, <I> infos", followed by
// the messages of its errors (warnings are allowed and only counted). Exit codes: 0 when every
// file is valid, 1 when any file has errors, cannot be read, or DIR holds no .glb at all,
// 2 on bad usage.
//
// Usage: node validate-glb.mjs DIR

import fs from 'node:fs';
import path from 'node:path';
import validator from 'gltf-validator';

const SEVERITY = ['error', 'warning', 'info', 'hint'];

function findGlbs(dir) {
  const out = [];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...findGlbs(full));
    else if (entry.isFile() && entry.name.toLowerCase().endsWith('.glb')) out.push(full);
  }
  return out.sort();
}

async function validateFile(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  return validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    // A GLB may still reference external buffers/images next to it.
    externalResourceFunction: (uri) =>
      fs.promises
        .readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)))
        .then((data) => new Uint8Array(data)),
  });
}

async function main() {
  const dir = process.argv[2];
  if (!dir || process.argv.length > 3) {
    console.error('usage: node validate-glb.mjs DIR');
    return 2;
  }
  if (!fs.existsSync(dir) || !fs.statSync(dir).isDirectory()) {
    console.error(`validate-glb: not a directory: ${dir}`);
    return 2;
  }
  const files = findGlbs(dir);
  if (files.length === 0) {
    console.error(`validate-glb: no .glb files under ${dir}`);
    return 1;
  }

  let failed = 0;
  let totalErrors = 0;
  let totalWarnings = 0;
  for (const file of files) {
    const rel = path.relative(dir, file);
    let report;
    try {
      report = await validateFile(file);
    } catch (err) {
      // The validator rejects only when it cannot even detect the format.
      console.log(`${rel}: unreadable (${err})`);
      ++failed;
      continue;
    }
    const { numErrors, numWarnings, numInfos, messages } = report.issues;
    totalErrors += numErrors;
    totalWarnings += numWarnings;
    console.log(`${rel}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos`);
    if (numErrors > 0) {
      ++failed;
      for (const m of messages.filter((m) => m.severity === 0)) {
        console.log(`  ${SEVERITY[m.severity]} ${m.code}: ${m.message}${m.pointer ? ` (${m.pointer})` : ''}`);
      }
    }
  }
  console.log(
    `validate-glb: ${files.length} files, ${failed} invalid, ${totalErrors} errors, ${totalWarnings} warnings ` +
      `(gltf-validator ${validator.version()})`,
  );
  return failed > 0 ? 1 : 0;
}

process.exitCode = await main();
