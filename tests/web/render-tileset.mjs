#!/usr/bin/env node
// Renders an exported HLOD package (3D Tiles 1.1) in headless Chromium with a real 3D Tiles
// runtime (three.js + 3d-tiles-renderer, or CesiumJS with --runtime cesium) and checks that it
// loads and shows something.
//
// A static HTTP server on 127.0.0.1 (random free port) serves DIR under /tiles/, viewer.html and
// viewer.js at / and tests/web/node_modules under /node_modules/ (the page's import map points
// there). Debian's /usr/bin/chromium is driven by playwright-core with SwiftShader WebGL; the
// page frames the tileset's bounding sphere and renders until no tile loads have been pending for
// ~1 s (or the timeout). The canvas is saved to OUT.png and the share of pixels that differ from
// the background colour is measured by decoding that PNG here (node:zlib, no extra deps).
//
// Prints one JSON object on stdout:
//   {tilesLoaded, tilesFailed, consoleErrors, consoleMessages, pageErrors,
//    nonBackgroundPixelShare, screenshots, ...}
// Exit 0 when tilesLoaded > 0, tilesFailed == 0, no page errors, no console errors or warnings
// and nonBackgroundPixelShare > 0.01; otherwise exit 1 with a one-line reason on stderr
// (2 on bad usage). A loading timeout fails too (timedOut).
//
// --camera FILE.json views the package from a given camera instead of framing it: {eye,
// target, up, fovDeg[, near, far]} in the package's frame (the frame of its content and of
// `hlod bench`), or a camera path of `hlod bench --path` (its first key); several files
// separated by commas are visited in turn in the same page (tiles loading for each), the
// pictures named OUT-vN.png. --shading takes
// pbr (the runtime's own materials and lights, the default) or geometry / textured, the shading
// of `hlod bench` (bench-shading-three.js), or several separated by commas: the tiles load once
// and one picture per shading is saved as OUT-<shading>.png. --no-antialias turns MSAA off (the
// bench has none), --cull none draws both sides of every surface (a bench that does not cull;
// default gltf: back faces culled unless the material is double-sided, as engines do),
// --background RRGGBB sets the clear colour, --place LON,LAT,H (cesium) puts
// the package on the globe as the README says.
//
// --runtime three,cesium renders with both in one browser (a fresh context each) and prints
// {runs: [report, report]}, the pictures then named OUT-<runtime>[-<shading>].png.
//
// Usage: node render-tileset.mjs DIR OUT.png [--runtime three|cesium[,...]] [--width W] [--height H]
//          [--timeout SECONDS] [--error-target PX] [--camera FILE.json]
//          [--shading pbr|geometry|textured[,...]] [--no-antialias] [--background RRGGBB]
//          [--place LON,LAT,H]

import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const CHROMIUM = '/usr/bin/chromium';
const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--disable-background-networking',
  '--disable-component-update',
  '--no-first-run',
  '--disable-gpu-sandbox',
  '--disable-quic',
  '--disable-sync',
];
const DEFAULT_BACKGROUND = '30343c'; // the pages' default clear colour
const BACKGROUND_TOLERANCE = 12; // per channel, absorbs dithering/colour-space rounding
const MIN_PIXEL_SHARE = 0.01;
// Console warnings a runtime prints about itself, not about the package: reported as notices.
// 3d-tiles-renderer 0.5 says this of every 3D Tiles 1.1 tileset (asset.version "1.1", which
// glTF content without an extension needs).
const KNOWN_NOTICES = [
  /^warning: TilesRenderer: tiles versions at 1\.1 or higher have limited support\./,
];

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.glb': 'model/gltf-binary',
  '.gltf': 'model/gltf+json',
  '.bin': 'application/octet-stream',
  '.b3dm': 'application/octet-stream',
  '.i3dm': 'application/octet-stream',
  '.pnts': 'application/octet-stream',
  '.cmpt': 'application/octet-stream',
  '.subtree': 'application/octet-stream',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg',
  '.webp': 'image/webp',
  '.ktx2': 'image/ktx2',
  '.wasm': 'application/wasm',
};

function parseArgs(argv) {
  const opts = {
    width: 800, height: 600, timeout: 60, errorTarget: 16, runtimes: ['three'], cameras: [],
    shading: ['pbr'], antialias: true, cull: 'gltf', background: DEFAULT_BACKGROUND, place: null, positional: [],
  };
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    const value = () => {
      const v = Number(argv[++i]);
      if (!Number.isFinite(v) || v <= 0) throw new Error(`${a} needs a positive number`);
      return v;
    };
    if (a === '--width') opts.width = Math.round(value());
    else if (a === '--height') opts.height = Math.round(value());
    else if (a === '--timeout') opts.timeout = value();
    else if (a === '--error-target') opts.errorTarget = value();
    else if (a === '--runtime') {
      opts.runtimes = String(argv[++i]).split(',');
      if (!opts.runtimes.every((r) => r === 'three' || r === 'cesium')) throw new Error('--runtime takes three, cesium');
    } else if (a === '--camera') opts.cameras = String(argv[++i]).split(',').map(readCamera);
    else if (a === '--shading') {
      opts.shading = String(argv[++i]).split(',');
      if (!opts.shading.every((s) => ['pbr', 'geometry', 'textured'].includes(s))) {
        throw new Error('--shading takes pbr, geometry, textured');
      }
    } else if (a === '--no-antialias') opts.antialias = false;
    else if (a === '--cull') {
      opts.cull = argv[++i];
      if (opts.cull !== 'gltf' && opts.cull !== 'none') throw new Error('--cull takes gltf or none');
    }
    else if (a === '--background') {
      opts.background = String(argv[++i]).toLowerCase();
      if (!/^[0-9a-f]{6}$/.test(opts.background)) throw new Error('--background takes RRGGBB');
    } else if (a === '--place') {
      opts.place = String(argv[++i]);
      if (!/^-?[\d.]+,-?[\d.]+(,-?[\d.]+)?$/.test(opts.place)) throw new Error('--place takes LON,LAT[,H]');
    } else if (a.startsWith('--')) throw new Error(`unknown option ${a}`);
    else opts.positional.push(a);
  }
  if (opts.positional.length !== 2) throw new Error('expected DIR and OUT.png');
  [opts.dir, opts.out] = opts.positional;
  return opts;
}

/** A camera file: {eye, target, up, fovDeg, near?, far?}, or a bench camera path (first key). */
function readCamera(file) {
  const j = JSON.parse(fs.readFileSync(file, 'utf8'));
  if (Array.isArray(j.keys)) {
    return { eye: j.keys[0].eye, target: j.keys[0].target, up: j.up || [0, 1, 0], fovDeg: j.fov_deg || 60 };
  }
  for (const k of ['eye', 'target', 'up']) {
    if (!Array.isArray(j[k]) || j[k].length !== 3) throw new Error(`${file}: ${k} must be 3 numbers`);
  }
  if (!(j.fovDeg > 0 && j.fovDeg < 180)) throw new Error(`${file}: fovDeg must be in (0, 180)`);
  return j;
}

/** Serves fixed files and two directory trees; never anything outside them. */
function startServer(tilesDir) {
  const roots = {
    '/tiles/': path.resolve(tilesDir),
    '/node_modules/': path.join(HERE, 'node_modules'),
  };
  const files = {
    '/': path.join(HERE, 'viewer.html'),
    '/viewer.html': path.join(HERE, 'viewer.html'),
    '/viewer.js': path.join(HERE, 'viewer.js'),
    '/bench-shading-three.js': path.join(HERE, 'bench-shading-three.js'),
    '/cesium.html': path.join(HERE, 'cesium.html'),
    '/cesium-viewer.js': path.join(HERE, 'cesium-viewer.js'),
  };
  const httpErrors = [];
  const server = http.createServer((req, res) => {
    const send = (status, body, type = 'text/plain; charset=utf-8') => {
      if (status >= 400 && req.url !== '/favicon.ico') httpErrors.push(`${status} ${req.url}`);
      res.writeHead(status, { 'Content-Type': type, 'Cache-Control': 'no-store' });
      res.end(body);
    };
    if (req.method !== 'GET' && req.method !== 'HEAD') return send(405, 'method not allowed');
    let urlPath;
    try {
      urlPath = decodeURIComponent(new URL(req.url, 'http://127.0.0.1').pathname);
    } catch {
      return send(400, 'bad url');
    }
    let file = files[urlPath];
    if (!file) {
      const prefix = Object.keys(roots).find((p) => urlPath.startsWith(p));
      if (!prefix) return send(404, 'not found');
      const root = roots[prefix];
      file = path.resolve(root, '.' + urlPath.slice(prefix.length - 1));
      if (file !== root && !file.startsWith(root + path.sep)) return send(403, 'forbidden');
    }
    fs.readFile(file, (err, data) => {
      if (err) return send(404, 'not found');
      const type = MIME[path.extname(file).toLowerCase()] || 'application/octet-stream';
      send(200, req.method === 'HEAD' ? undefined : data, type);
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => resolve({ server, httpErrors, port: server.address().port }));
  });
}

/** Minimal PNG decoder: 8-bit greyscale/RGB/RGBA (+alpha), non-interlaced, as Chromium writes. */
function decodePng(buf) {
  const sig = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  if (buf.length < 8 || !buf.subarray(0, 8).equals(sig)) throw new Error('not a PNG');
  let pos = 8;
  let width, height, bitDepth, colorType, interlace;
  const idat = [];
  while (pos + 8 <= buf.length) {
    const len = buf.readUInt32BE(pos);
    const type = buf.toString('latin1', pos + 4, pos + 8);
    const data = buf.subarray(pos + 8, pos + 8 + len);
    pos += 12 + len;
    if (type === 'IHDR') {
      width = data.readUInt32BE(0);
      height = data.readUInt32BE(4);
      bitDepth = data[8];
      colorType = data[9];
      interlace = data[12];
    } else if (type === 'IDAT') idat.push(data);
    else if (type === 'IEND') break;
  }
  const channels = { 0: 1, 2: 3, 4: 2, 6: 4 }[colorType];
  if (bitDepth !== 8 || !channels || interlace !== 0) {
    throw new Error(`unsupported PNG (bit depth ${bitDepth}, colour type ${colorType}, interlace ${interlace})`);
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const pixels = Buffer.alloc(stride * height);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const src = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const row = y * stride;
    for (let x = 0; x < stride; ++x) {
      const a = x >= channels ? pixels[row + x - channels] : 0;
      const b = y > 0 ? pixels[row - stride + x] : 0;
      const c = x >= channels && y > 0 ? pixels[row - stride + x - channels] : 0;
      let p;
      switch (filter) {
        case 0: p = 0; break;
        case 1: p = a; break;
        case 2: p = b; break;
        case 3: p = (a + b) >> 1; break;
        case 4: {
          const pa = Math.abs(b - c), pb = Math.abs(a - c), pc = Math.abs(a + b - 2 * c);
          p = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
          break;
        }
        default: throw new Error(`bad PNG filter ${filter}`);
      }
      pixels[row + x] = (src[x] + p) & 0xff;
    }
  }
  return { width, height, channels, pixels };
}

function nonBackgroundShare(png, background) {
  const BACKGROUND = [0, 2, 4].map((k) => parseInt(background.slice(k, k + 2), 16));
  const { width, height, channels, pixels } = png;
  let count = 0;
  for (let i = 0; i < width * height; ++i) {
    const o = i * channels;
    const rgb = channels >= 3 ? [pixels[o], pixels[o + 1], pixels[o + 2]] : [pixels[o], pixels[o], pixels[o]];
    if (rgb.some((v, k) => Math.abs(v - BACKGROUND[k]) > BACKGROUND_TOLERANCE)) ++count;
  }
  return width * height > 0 ? count / (width * height) : 0;
}

const withTimeout = (promise, ms, what) =>
  Promise.race([
    promise,
    new Promise((_, reject) => setTimeout(() => reject(new Error(`${what} timed out after ${ms} ms`)), ms).unref()),
  ]);

// The picture file of `runtime`, camera `view` and `shading`: OUT, or with -RUNTIME, -vVIEW and
// -SHADING before .png as far as there are several.
function outName(opts, runtime, view, shading) {
  let suffix = opts.runtimes.length > 1 ? `-${runtime}` : '';
  if (opts.cameras.length > 1) suffix += `-v${view}`;
  if (opts.shading.length > 1) suffix += `-${shading}`;
  return suffix ? opts.out.replace(/(\.png)?$/i, `${suffix}.png`) : opts.out;
}

async function run(opts, state) {
  if (!fs.existsSync(path.join(opts.dir, 'tileset.json'))) throw new Error(`no tileset.json in ${opts.dir}`);
  if (!fs.existsSync(path.join(HERE, 'node_modules', '3d-tiles-renderer')) ||
      !fs.existsSync(path.join(HERE, 'node_modules', 'cesium'))) {
    throw new Error('tests/web/node_modules missing: run npm ci in tests/web');
  }
  const { server, httpErrors, port } = await startServer(opts.dir);
  state.server = server;

  state.browser = await chromium.launch({
    executablePath: CHROMIUM,
    headless: true,
    args: CHROMIUM_ARGS,
    timeout: 30000,
  }); // playwright gives the browser a fresh temporary profile and deletes it on close
  const reports = [];
  for (const runtime of opts.runtimes) {
    const before = httpErrors.length;
    const report = await renderWith(opts, runtime, state.browser, port);
    report.httpErrors = httpErrors.slice(before);
    reports.push(report);
  }
  return reports.length === 1 ? reports[0] : { runs: reports };
}

// One runtime in its own browser context (a page of its own, nothing shared).
async function renderWith(opts, runtime, browser, port) {
  const context = await browser.newContext({
    viewport: { width: opts.width, height: opts.height },
    deviceScaleFactor: 1,
  });
  const page = await context.newPage();
  const consoleErrors = []; // errors and warnings
  const consoleMessages = []; // anything else the page logs
  const pageErrors = [];
  page.on('console', (msg) => {
    const type = msg.type();
    const text = `${type}: ${msg.text()}`;
    if ((type === 'error' || type === 'warning') && !KNOWN_NOTICES.some((r) => r.test(text))) {
      consoleErrors.push(text);
    } else {
      consoleMessages.push(text);
    }
  });
  page.on('pageerror', (err) => pageErrors.push(String(err && err.stack ? err.message : err)));

  const query = new URLSearchParams({
    w: opts.width,
    h: opts.height,
    errorTarget: opts.errorTarget,
    timeoutMs: Math.round(opts.timeout * 1000),
    bg: opts.background,
    shading: opts.shading[0],
    antialias: opts.antialias ? '1' : '0',
    cull: opts.cull === 'none' ? 'none' : 'gltf',
  });
  if (opts.cameras.length) query.set('camera', JSON.stringify(opts.cameras[0]));
  if (opts.place) query.set('place', opts.place);
  const pageName = runtime === 'cesium' ? 'cesium.html' : 'viewer.html';
  await page.goto(`http://127.0.0.1:${port}/${pageName}?${query}`, { timeout: 15000 });
  let result;
  try {
    await page.waitForFunction(() => window.__hlodResult && window.__hlodResult.done, null, {
      timeout: opts.timeout * 1000 + 15000,
      polling: 100,
    });
    result = await page.evaluate(() => window.__hlodResult);
  } catch (err) {
    // The page never finished (module failed to load, or it hung): report what is known.
    result = await page.evaluate(() => window.__hlodResult || null).catch(() => null);
    if (!result) {
      throw new Error(`page did not start: ${[...pageErrors, ...consoleErrors][0] || err.message}`);
    }
    result.timedOut = true;
  }

  fs.mkdirSync(path.dirname(path.resolve(opts.out)), { recursive: true });
  const screenshots = [];
  const views = [];
  let share = 0;
  let current = opts.shading[0];
  for (let v = 0; v < Math.max(opts.cameras.length, 1); ++v) {
    if (v > 0) {
      await page.evaluate((cam) => window.__hlodView(cam), opts.cameras[v]);
      result = await page.evaluate(() => window.__hlodResult);
    }
    views.push({ timedOut: result.timedOut, elapsedMs: result.elapsedMs, stats: result.stats });
    for (const shading of opts.shading) {
      const out = outName(opts, runtime, v, shading);
      if (!result.timedOut && shading !== current) {
        await page.evaluate((s) => window.__hlodShade(s), shading);
        current = shading;
      }
      const png = await page.locator('canvas').first().screenshot({ path: out, timeout: 15000 });
      share = Math.max(share, nonBackgroundShare(decodePng(png), opts.background));
      screenshots.push(out);
    }
  }

  const report = {
    tilesLoaded: result.tilesLoaded,
    tilesFailed: result.tilesFailed,
    consoleErrors,
    consoleMessages,
    pageErrors,
    nonBackgroundPixelShare: Number(share.toFixed(4)),
    failures: result.failures,
    httpErrors: [],
    timedOut: result.timedOut,
    framed: result.framed,
    viewFromPackage: Boolean(result.viewFromPackage),
    sphere: result.sphere,
    stats: result.stats,
    elapsedMs: result.elapsedMs,
    screenshot: screenshots[0],
    screenshots,
    views,
    runtime,
  };
  await context.close();
  return report;
}

function verdict(report) {
  if (report.tilesFailed > 0) return `${report.tilesFailed} tile(s) failed to load: ${report.failures[0] || ''}`;
  if (report.pageErrors.length) return `page error: ${report.pageErrors[0]}`;
  if (report.consoleErrors.length) return `console error: ${report.consoleErrors[0]}`;
  if (!report.framed) return 'the root tileset never loaded (no bounding sphere to frame)';
  if (report.timedOut) return 'loading did not settle before the timeout';
  if (report.tilesLoaded === 0) return 'no tile content loaded';
  if (!(report.nonBackgroundPixelShare > MIN_PIXEL_SHARE)) {
    return `only ${(report.nonBackgroundPixelShare * 100).toFixed(2)}% of the pixels differ from the background`;
  }
  return null;
}

async function main() {
  let opts;
  try {
    opts = parseArgs(process.argv.slice(2));
  } catch (err) {
    console.error(`render-tileset: ${err.message}`);
    console.error('usage: node render-tileset.mjs DIR OUT.png [--runtime three|cesium] [--width W] [--height H] ' +
      '[--timeout S] [--error-target PX] [--camera FILE.json] [--shading pbr|geometry|textured[,...]] ' +
      '[--no-antialias] [--background RRGGBB] [--place LON,LAT,H]');
    return 2;
  }

  const state = { browser: null, server: null };
  const cleanup = async () => {
    const b = state.browser;
    state.browser = null;
    if (b) await withTimeout(b.close(), 10000, 'closing the browser').catch(() => {});
    if (state.server) {
      state.server.closeAllConnections();
      state.server.close();
      state.server = null;
    }
  };
  // Last resort if anything hangs: playwright kills the browsers it launched on process exit.
  const limit = (opts.timeout + 60) * opts.runtimes.length * Math.max(opts.cameras.length, 1);
  const watchdog = setTimeout(() => {
    console.error(`render-tileset: watchdog: gave up after ${limit} s`);
    process.exit(1);
  }, limit * 1000);

  let code = 1;
  try {
    const report = await run(opts, state);
    console.log(JSON.stringify(report));
    const reports = report.runs || [report];
    let reason = null;
    for (const r of reports) {
      if (r.timedOut) console.error(`render-tileset: warning: ${r.runtime}: loading did not settle within ${opts.timeout} s`);
      const why = verdict(r);
      if (why && !reason) reason = reports.length > 1 ? `${r.runtime}: ${why}` : why;
    }
    if (reason) console.error(`render-tileset: FAIL: ${reason.replace(/\s*\n\s*/g, ' ')}`);
    code = reason ? 1 : 0;
  } catch (err) {
    console.error(`render-tileset: FAIL: ${String(err && err.message ? err.message : err).split('\n')[0]}`);
    code = 1;
  } finally {
    await cleanup();
    clearTimeout(watchdog);
  }
  return code;
}

process.exitCode = await main();
