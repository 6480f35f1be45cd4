// SPDX-License-Identifier: GPL-3.0-or-later
//
// The published playground's first visit (issue 28, item 10), in headless Chromium with an empty
// profile: builds the site (scripts/build-site.mjs: minified JavaScript, .br/.gz beside every
// file), serves it as a host that sends precompressed files would (scripts/serve.mjs --root), and
// counts what the server sends: the bytes (bodies as sent, compressed where the browser accepts
// it, plus headers) and responses until the page shows its first verdict, then until the service
// worker reports the playground kept for offline use, and which files were sent twice. With
// --throttle it also times the first verdict on a 10 Mbit/s link with 60 ms of latency (Chromium's
// network emulation). Also prints the core's sizes: raw, gzip -9 and brotli -q 11.
//
//   node tests/benchmarks/first_visit_bench.mjs [--throttle] [--site DIR] [--json FILE]
//
// tests/browser/first-visit.test.mjs runs measureFirstVisit() and checks the budget.

import { mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import zlib from 'node:zlib';
import { chromium } from 'playwright-core';

import { buildSite } from '../../scripts/build-site.mjs';
import { startServer } from '../../scripts/serve.mjs';
import { CHROMIUM_ARGS, CHROMIUM_PATH, REPO_ROOT } from '../browser/support.mjs';

/** The link of the estimate: 10 Mbit/s down, 60 ms round trip. */
export const SLOW_LINK = { latency: 60, downloadThroughput: 10e6 / 8, uploadThroughput: 10e6 / 8 };
const SETTLE_MS = 120_000;

/** Raw, gzip -9 and brotli -q 11 sizes of a file. */
export async function compressedSizes(file) {
  const bytes = await readFile(file);
  return {
    raw: bytes.length,
    gzip: zlib.gzipSync(bytes, { level: 9 }).length,
    brotli: zlib.brotliCompressSync(bytes, {
      params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 11, [zlib.constants.BROTLI_PARAM_SIZE_HINT]: bytes.length },
    }).length,
  };
}

function sum(responses) {
  return responses.reduce((total, response) => total + response.bytes + response.headerBytes, 0);
}

/**
 * One first visit of the site in `siteDir` (built into a temporary folder when omitted). Returns
 * { verdictMs, beforeVerdict: { bytes, responses }, afterOffline: { bytes, responses },
 *   sentTwice: [paths sent in full more than once], encodings: { path: encoding }, offline }, and
 * with `revisit` also `revisit: { bytes, responses, full: [paths sent in full] }` for a reload
 * once the offline copy was kept (until it is kept again).
 */
export async function measureFirstVisit({ siteDir, throttle = false, revisit = false } = {}) {
  const tmp = await mkdtemp(path.join(os.tmpdir(), 'desia-first-visit-'));
  const log = [];
  let server;
  let context;
  try {
    if (!siteDir) {
      siteDir = path.join(tmp, 'site');
      await buildSite(siteDir);
    }
    server = await startServer({ port: 0, root: siteDir, onResponse: (entry) => log.push({ ...entry, at: Date.now() }) });
    context = await chromium.launchPersistentContext(path.join(tmp, 'profile'), {
      executablePath: CHROMIUM_PATH,
      headless: true,
      args: CHROMIUM_ARGS,
      viewport: { width: 1400, height: 900 },
    });
    const page = context.pages()[0] ?? await context.newPage();
    if (throttle) {
      const devtools = await context.newCDPSession(page);
      await devtools.send('Network.enable');
      await devtools.send('Network.emulateNetworkConditions', { offline: false, ...SLOW_LINK });
    }
    const started = Date.now();
    await page.goto(server.url);
    await page.waitForFunction(() => document.body.dataset.status === 'ready' && document.querySelector('#verdict')?.textContent,
      null, { timeout: SETTLE_MS });
    const verdictAt = Date.now();
    const beforeVerdict = log.filter((entry) => entry.at <= verdictAt);
    await page.waitForFunction(() => ['ready', 'unavailable'].includes(document.body.dataset.offline), null, { timeout: SETTLE_MS });
    const offline = await page.evaluate(() => ({
      state: document.body.dataset.offline,
      title: document.querySelector('#offline-status').title,
    }));
    const afterOffline = [...log];
    let second = null;
    if (revisit) {
      await page.reload();
      await page.waitForFunction(() => document.body.dataset.status === 'ready' && ['ready', 'unavailable'].includes(document.body.dataset.offline),
        null, { timeout: SETTLE_MS });
      const again = log.slice(afterOffline.length);
      second = {
        bytes: sum(again),
        responses: again.length,
        full: again.filter((entry) => entry.status === 200).map((entry) => entry.path),
        offline: await page.evaluate(() => document.body.dataset.offline),
      };
    }
    const full = new Map();
    for (const entry of afterOffline.filter((response) => response.status === 200 && response.method === 'GET')) {
      full.set(entry.path, (full.get(entry.path) ?? 0) + 1);
    }
    return {
      verdictMs: verdictAt - started,
      beforeVerdict: { bytes: sum(beforeVerdict), responses: beforeVerdict.length },
      afterOffline: { bytes: sum(afterOffline), responses: afterOffline.length },
      sentTwice: [...full].filter(([, count]) => count > 1).map(([file]) => file),
      encodings: Object.fromEntries(afterOffline.filter((entry) => entry.status === 200).map((entry) => [entry.path, entry.encoding])),
      log: afterOffline.map(({ path: file, status, bytes, encoding, at }) => ({ path: file, status, bytes, encoding, ms: at - started })),
      offline,
      revisit: second,
    };
  } finally {
    await context?.close();
    await server?.close();
    await rm(tmp, { recursive: true, force: true });
  }
}

function parseArguments(argv) {
  const options = { throttle: false, siteDir: undefined, json: undefined };
  for (let i = 0; i < argv.length; i += 1) {
    if (argv[i] === '--throttle') options.throttle = true;
    else if (argv[i] === '--site') options.siteDir = path.resolve(argv[++i]);
    else if (argv[i] === '--json') options.json = path.resolve(argv[++i]);
    else throw new Error(`unknown argument ${argv[i]} (usage: node tests/benchmarks/first_visit_bench.mjs [--throttle] [--site DIR] [--json FILE])`);
  }
  return options;
}

const kb = (bytes) => `${(bytes / 1000).toFixed(0)} KB`;
const mb = (bytes) => `${(bytes / 1e6).toFixed(2)} MB`;

async function main() {
  const options = parseArguments(process.argv.slice(2));
  const wasm = await compressedSizes(path.join(REPO_ROOT, 'dist/desia_wasm.wasm'));
  const loader = await compressedSizes(path.join(REPO_ROOT, 'dist/desia_wasm.js'));
  const lightWasm = await compressedSizes(path.join(REPO_ROOT, 'dist/desia_light.wasm'));
  const lightLoader = await compressedSizes(path.join(REPO_ROOT, 'dist/desia_light.js'));
  const plain = await measureFirstVisit({ siteDir: options.siteDir, revisit: true });
  const slow = options.throttle ? await measureFirstVisit({ siteDir: options.siteDir, throttle: true }) : null;
  console.log('| figure | value |');
  console.log('| --- | ---: |');
  console.log(`| core dist/desia_wasm.wasm: raw / gzip -9 / brotli -q 11 | ${kb(wasm.raw)} / ${kb(wasm.gzip)} / **${kb(wasm.brotli)}** |`);
  console.log(`| core loader dist/desia_wasm.js: raw / gzip / brotli | ${kb(loader.raw)} / ${kb(loader.gzip)} / ${kb(loader.brotli)} |`);
  console.log(`| light core dist/desia_light.wasm: raw / gzip -9 / brotli -q 11 | ${kb(lightWasm.raw)} / ${kb(lightWasm.gzip)} / **${kb(lightWasm.brotli)}** |`);
  console.log(`| light core loader dist/desia_light.js: raw / gzip / brotli | ${kb(lightLoader.raw)} / ${kb(lightLoader.gzip)} / ${kb(lightLoader.brotli)} |`);
  console.log(`| first visit, until the first verdict | **${mb(plain.beforeVerdict.bytes)}** in ${plain.beforeVerdict.responses} responses |`);
  console.log(`| first visit, until kept for offline (every example too) | ${mb(plain.afterOffline.bytes)} in ${plain.afterOffline.responses} responses |`);
  console.log(`| files sent twice | ${plain.sentTwice.length === 0 ? 'none' : plain.sentTwice.join(', ')} |`);
  console.log(`| second visit (reload), until kept again | ${kb(plain.revisit.bytes)} in ${plain.revisit.responses} responses, ${plain.revisit.full.length} sent in full |`);
  if (slow) console.log(`| first verdict at 10 Mbit/s, 60 ms (Chromium's emulation) | ${(slow.verdictMs / 1000).toFixed(1)} s |`);
  console.log(`| first verdict, local server | ${(plain.verdictMs / 1000).toFixed(1)} s |`);
  if (plain.offline.state !== 'ready') console.log(`offline: ${plain.offline.state} (${plain.offline.title})`);
  if (options.json) await writeFile(options.json, `${JSON.stringify({ wasm, loader, lightWasm, lightLoader, plain, slow }, null, 2)}\n`);
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  main().catch((error) => {
    console.error(error.stack ?? error);
    process.exit(1);
  });
}
