#!/usr/bin/env node
// Validates an exported package as the official 3D Tiles validator (CesiumGS
// 3d-tiles-validator 0.6) does, with the checks that apply to our tilesets, and fails on any
// error, any warning and any "may be unused" info.
//
// The official validator is not installable here (the npm registry this project uses does not
// serve `3d-tiles-validator`), so this script repeats what it does for a tileset of boxes and
// glTF contents:
// - tileset.json: asset.version "1.0" or "1.1" (else ASSET_VERSION_UNKNOWN, warning); a
//   top-level geometricError >= 0; refine in the root tile (TILE_REFINE_MISSING_IN_ROOT, error)
//   and "ADD" or "REPLACE" everywhere; every tile with exactly one bounding volume (box of 12,
//   region of 6, sphere of 4 finite numbers), a geometricError >= 0 and not larger than its
//   parent's (TILE_GEOMETRIC_ERRORS_INCONSISTENT, warning), a transform of 16 finite numbers
//   with an invertible upper 3x3, children as a non-empty array, content uris that resolve to
//   files inside the package; extensionsUsed / extensionsRequired consistent.
// - every content (once per file) through the Khronos glTF validator exactly as the official
//   validator's GltfValidator passes it: validateBytes with the content's uri, maxIssues 1000
//   and external resources (textures) read relative to the content; a content with glTF
//   errors is an error (CONTENT_VALIDATION_ERROR), with warnings a warning
//   (CONTENT_VALIDATION_WARNING), with infos only an info (CONTENT_VALIDATION_INFO), each with
//   the glTF messages as causes.
//
// Prints the issues (causes counted by code) and one summary line; with --json, a JSON report
// on stdout instead: {tiles, contents, files, errors, warnings, infos, unusedObjects,
// infoCodes: {code: count}, issues: [...]}.
// Exit code 0 when there are no errors, no warnings and no UNUSED_OBJECT infos (the infos that
// remain, such as UNSUPPORTED_EXTENSION for EXT_meshopt_compression, are listed); 1 otherwise;
// 2 on bad usage.
//
// Usage: node validate-tileset.mjs DIR [--json]

import fs from 'node:fs';
import path from 'node:path';
import validator from 'gltf-validator';

const SEVERITY = ['error', 'warning', 'info', 'hint'];

function finiteNumbers(a, n) {
  return Array.isArray(a) && a.length === n && a.every((v) => typeof v === 'number' && Number.isFinite(v));
}

function det3(m) {
  // Column-major 4x4: the upper 3x3 is m[0..2], m[4..6], m[8..10].
  return (
    m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) + m[8] * (m[1] * m[6] - m[5] * m[2])
  );
}

class Report {
  constructor() {
    this.issues = [];
    this.tiles = 0;
    this.contents = 0;
    this.files = 0;
  }
  add(severity, type, where, message, causes = []) {
    this.issues.push({ severity, type, path: where, message, causes });
  }
  count(severity) {
    return this.issues.filter((i) => i.severity === severity).length;
  }
}

function checkBoundingVolume(bv, where, report) {
  if (!bv || typeof bv !== 'object') {
    report.add('error', 'PROPERTY_MISSING', where, 'boundingVolume is missing');
    return;
  }
  const kinds = ['box', 'region', 'sphere'].filter((k) => k in bv);
  if (kinds.length !== 1) {
    report.add('error', 'ONE_OF_ERROR', where, `boundingVolume has ${kinds.length} of box, region, sphere`);
    return;
  }
  const sizes = { box: 12, region: 6, sphere: 4 };
  const k = kinds[0];
  if (!finiteNumbers(bv[k], sizes[k])) {
    report.add('error', 'BOUNDING_VOLUME_INVALID', `${where}/${k}`, `${k} must be ${sizes[k]} finite numbers`);
  } else if (k === 'sphere' && bv.sphere[3] < 0) {
    report.add('error', 'BOUNDING_VOLUME_INVALID', `${where}/sphere`, 'negative radius');
  }
}

function checkTile(tile, where, parentError, dir, report, contentUris) {
  report.tiles++;
  checkBoundingVolume(tile.boundingVolume, `${where}/boundingVolume`, report);
  const ge = tile.geometricError;
  if (typeof ge !== 'number' || !Number.isFinite(ge) || ge < 0) {
    report.add('error', 'VALUE_NOT_IN_RANGE', `${where}/geometricError`, `geometricError must be a number >= 0, is ${ge}`);
  } else if (parentError !== undefined && ge > parentError) {
    report.add('warning', 'TILE_GEOMETRIC_ERRORS_INCONSISTENT', where,
      `geometricError ${ge} is larger than the parent's ${parentError}`);
  }
  if ('refine' in tile && tile.refine !== 'ADD' && tile.refine !== 'REPLACE') {
    report.add('error', 'VALUE_NOT_IN_LIST', `${where}/refine`, `refine must be ADD or REPLACE, is ${tile.refine}`);
  }
  if ('transform' in tile) {
    if (!finiteNumbers(tile.transform, 16)) {
      report.add('error', 'ARRAY_LENGTH_UNEXPECTED', `${where}/transform`, 'transform must be 16 finite numbers');
    } else if (Math.abs(det3(tile.transform)) < 1e-12) {
      report.add('error', 'TRANSFORM_INVALID', `${where}/transform`, 'transform is not invertible');
    }
  }
  if ('content' in tile) {
    report.contents++;
    const uri = tile.content && tile.content.uri;
    if (typeof uri !== 'string' || uri.length === 0) {
      report.add('error', 'PROPERTY_MISSING', `${where}/content/uri`, 'content has no uri');
    } else {
      const file = path.resolve(dir, decodeURIComponent(uri));
      if (!file.startsWith(path.resolve(dir) + path.sep)) {
        report.add('error', 'IO_ERROR', `${where}/content/uri`, `content ${uri} is outside the package`);
      } else if (!fs.existsSync(file)) {
        report.add('error', 'IO_ERROR', `${where}/content/uri`, `content ${uri} does not exist`);
      } else {
        contentUris.add(uri);
      }
    }
    if (tile.content && tile.content.boundingVolume) {
      checkBoundingVolume(tile.content.boundingVolume, `${where}/content/boundingVolume`, report);
    }
  }
  if ('children' in tile) {
    if (!Array.isArray(tile.children) || tile.children.length === 0) {
      report.add('error', 'ARRAY_LENGTH_MISMATCH', `${where}/children`, 'children must be a non-empty array');
    } else {
      tile.children.forEach((child, i) =>
        checkTile(child, `${where}/children/${i}`, typeof ge === 'number' ? ge : undefined, dir, report, contentUris));
    }
  }
}

async function validateContent(dir, uri, report) {
  const file = path.resolve(dir, decodeURIComponent(uri));
  const root = path.resolve(dir) + path.sep;
  const bytes = new Uint8Array(fs.readFileSync(file));
  let result;
  try {
    result = await validator.validateBytes(bytes, {
      uri,
      maxIssues: 1000,
      externalResourceFunction: (ref) => {
        const resource = path.resolve(path.dirname(file), decodeURIComponent(ref));
        if (!resource.startsWith(root)) return Promise.reject(new Error(`${ref} is outside the package`));
        return fs.promises.readFile(resource).then((data) => new Uint8Array(data));
      },
    });
  } catch (err) {
    report.add('error', 'CONTENT_VALIDATION_ERROR', uri, `Content ${uri} caused internal validation error: ${err}`);
    return;
  }
  const { numErrors, numWarnings, numInfos, messages } = result.issues;
  const causes = messages.map((m) => ({ severity: SEVERITY[m.severity], code: m.code, message: m.message, pointer: m.pointer }));
  if (numErrors > 0) report.add('error', 'CONTENT_VALIDATION_ERROR', uri, `Content ${uri} caused validation errors`, causes);
  else if (numWarnings > 0) report.add('warning', 'CONTENT_VALIDATION_WARNING', uri, `Content ${uri} caused validation warnings`, causes);
  else if (numInfos > 0) report.add('info', 'CONTENT_VALIDATION_INFO', uri, `Content ${uri} caused validation infos`, causes);
}

async function validate(dir) {
  const report = new Report();
  const tilesetFile = path.join(dir, 'tileset.json');
  let tileset;
  try {
    tileset = JSON.parse(fs.readFileSync(tilesetFile, 'utf8'));
  } catch (err) {
    report.add('error', 'IO_ERROR', tilesetFile, `cannot read tileset.json: ${err.message}`);
    return report;
  }
  const version = tileset.asset && tileset.asset.version;
  if (typeof version !== 'string') report.add('error', 'PROPERTY_MISSING', '/asset/version', 'asset.version is missing');
  else if (version !== '1.0' && version !== '1.1') report.add('warning', 'ASSET_VERSION_UNKNOWN', '/asset/version', `unknown version ${version}`);
  if (typeof tileset.geometricError !== 'number' || !(tileset.geometricError >= 0)) {
    report.add('error', 'VALUE_NOT_IN_RANGE', '/geometricError', 'geometricError must be a number >= 0');
  }
  const used = tileset.extensionsUsed || [];
  for (const e of tileset.extensionsRequired || []) {
    if (!used.includes(e)) report.add('error', 'EXTENSION_REQUIRED_BUT_NOT_USED', '/extensionsRequired', `${e} is required but not used`);
  }
  if (!tileset.root || typeof tileset.root !== 'object') {
    report.add('error', 'PROPERTY_MISSING', '/root', 'root is missing');
    return report;
  }
  if (!('refine' in tileset.root)) report.add('error', 'TILE_REFINE_MISSING_IN_ROOT', '/root', 'the root tile has no refine');
  const uris = new Set();
  checkTile(tileset.root, '/root', tileset.geometricError, dir, report, uris);
  report.files = uris.size;
  for (const uri of [...uris].sort()) await validateContent(dir, uri, report);
  return report;
}

function causeCounts(issues, severity) {
  const counts = {};
  for (const issue of issues) {
    for (const c of issue.causes) if (c.severity === severity) counts[c.code] = (counts[c.code] || 0) + 1;
  }
  return counts;
}

async function main() {
  const args = process.argv.slice(2);
  const json = args.includes('--json');
  const positional = args.filter((a) => a !== '--json');
  if (positional.length !== 1 || args.some((a) => a.startsWith('--') && a !== '--json')) {
    console.error('usage: node validate-tileset.mjs DIR [--json]');
    return 2;
  }
  const dir = positional[0];
  if (!fs.existsSync(dir) || !fs.statSync(dir).isDirectory()) {
    console.error(`validate-tileset: not a directory: ${dir}`);
    return 2;
  }
  const report = await validate(dir);
  const infoCodes = causeCounts(report.issues, 'info');
  const summary = {
    tiles: report.tiles,
    contents: report.contents,
    files: report.files,
    errors: report.count('error'),
    warnings: report.count('warning'),
    infos: report.count('info'),
    unusedObjects: infoCodes.UNUSED_OBJECT || 0,
    errorCodes: causeCounts(report.issues, 'error'),
    warningCodes: causeCounts(report.issues, 'warning'),
    infoCodes,
    gltfValidator: validator.version(),
  };
  const ok = summary.errors === 0 && summary.warnings === 0 && summary.unusedObjects === 0;
  if (json) {
    console.log(JSON.stringify({ ...summary, issues: report.issues.filter((i) => i.severity !== 'info') }));
  } else {
    for (const issue of report.issues.filter((i) => i.severity !== 'info')) {
      console.log(`${issue.severity} ${issue.type} ${issue.path}: ${issue.message}`);
      for (const c of issue.causes.filter((c) => c.severity !== 'info').slice(0, 20)) {
        console.log(`  ${c.severity} ${c.code}: ${c.message}${c.pointer ? ` (${c.pointer})` : ''}`);
      }
    }
    console.log(
      `validate-tileset: ${summary.tiles} tiles, ${summary.files} content files: ${summary.errors} errors, ` +
        `${summary.warnings} warnings, ${summary.infos} infos (glTF infos: ${JSON.stringify(infoCodes)}), ` +
        `gltf-validator ${summary.gltfValidator}`,
    );
  }
  if (!ok) console.error(`validate-tileset: FAIL: ${summary.errors} errors, ${summary.warnings} warnings, ${summary.unusedObjects} unused objects`);
  return ok ? 0 : 1;
}

process.exitCode = await main();
