// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shared pieces of the browser tests: prerequisites, the static server, Chromium, and the page's
// observable state (the data-* attributes and ids documented at the top of web/main.js and
// web/design-panel.js). Not a test file itself (no `.test.` in its name).

import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { mkdir, mkdtemp, rm } from 'node:fs/promises';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const CHROMIUM_PATH = '/usr/bin/chromium';
export const REPO_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
export const ARTIFACTS_DIR = path.join(REPO_ROOT, 'test-artifacts');
export const SETTLE_TIMEOUT_MS = 30_000;

// Flags from shared/toolchain.md (no background traffic on a closed network), plus SwiftShader:
// with --disable-gpu, current Chromium only offers software WebGL when explicitly allowed.
export const CHROMIUM_ARGS = [
  '--headless',
  '--no-sandbox',
  '--disable-gpu',
  '--disable-quic',
  '--no-first-run',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--enable-unsafe-swiftshader',
  '--use-angle=swiftshader',
];

/** Fails early, with the fix in the message, when something the tests need is missing. */
export function checkPrerequisites(exampleFiles = []) {
  const required = [
    [CHROMIUM_PATH, 'Chromium is missing: install Debian\'s chromium package (bash scripts/setup.sh)'],
    [path.join(REPO_ROOT, 'node_modules/three/build/three.module.js'), 'three is missing: run npm ci'],
    [path.join(REPO_ROOT, 'wasm/index.js'), 'wasm/index.js is missing'],
    [path.join(REPO_ROOT, 'dist/desia_wasm.wasm'), 'the WebAssembly build is missing: run bash scripts/build.sh wasm'],
    ...exampleFiles.map((file) => [path.join(REPO_ROOT, 'examples/voxel', file), `examples/voxel/${file} is missing`]),
  ];
  for (const [file, message] of required) {
    if (!existsSync(file)) throw new Error(`${message} (${file} not found)`);
  }
}

/** Starts scripts/serve.mjs on a free port; resolves with { url, stop }. */
export function startServer() {
  const child = spawn(process.execPath, [path.join(REPO_ROOT, 'scripts/serve.mjs'), '--port', '0'], {
    cwd: REPO_ROOT,
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let stderr = '';
  child.stderr.on('data', (chunk) => { stderr += chunk; });
  const stop = () => new Promise((resolve) => {
    if (child.exitCode !== null || child.signalCode !== null) return resolve();
    child.once('exit', () => resolve());
    child.kill('SIGTERM');
  });
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => {
      stop();
      reject(new Error(`scripts/serve.mjs printed no URL within 10 s; stderr: ${stderr}`));
    }, 10_000);
    let stdout = '';
    child.stdout.on('data', (chunk) => {
      stdout += chunk;
      const match = /^(http:\/\/127\.0\.0\.1:\d+\/web\/)\s*$/m.exec(stdout);
      if (match) {
        clearTimeout(timer);
        resolve({ url: match[1], stop });
      }
    });
    child.once('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`scripts/serve.mjs exited with code ${code}; stderr: ${stderr}`));
    });
  });
}

/**
 * The server, a persistent Chromium context in a temporary profile and its first page, plus
 * `close()`. `options` go to launchPersistentContext (e.g. acceptDownloads).
 */
export async function openBrowser(options = {}) {
  await mkdir(ARTIFACTS_DIR, { recursive: true });
  const server = await startServer();
  const userDataDir = await mkdtemp(path.join(os.tmpdir(), 'desia-chromium-'));
  let context;
  try {
    context = await chromium.launchPersistentContext(userDataDir, {
      executablePath: CHROMIUM_PATH,
      headless: true,
      args: CHROMIUM_ARGS,
      viewport: { width: 1280, height: 800 },
      ...options,
    });
  } catch (error) {
    await server.stop();
    await rm(userDataDir, { recursive: true, force: true });
    throw error;
  }
  const page = context.pages()[0] ?? await context.newPage();
  const close = async () => {
    await context.close();
    await server.stop();
    await rm(userDataDir, { recursive: true, force: true });
  };
  return { server, context, page, close };
}

export async function screenshot(page, name) {
  await page.screenshot({ path: path.join(ARTIFACTS_DIR, `${name}.png`) });
}

export async function pageState(page) {
  return page.evaluate(() => ({
    status: document.body.dataset.status,
    source: document.body.dataset.source,
    webgl: document.body.dataset.webgl,
    verdict: document.querySelector('#verdict')?.textContent ?? '',
    verdictCode: document.querySelector('#verdict')?.dataset.verdict ?? '',
    key: document.querySelector('#verdict')?.dataset.key ?? '',
    parts: document.querySelector('#parts-count')?.textContent ?? '',
    keyDirections: document.querySelector('#key-directions')?.textContent ?? '',
    meshes: document.querySelector('#viewport')?.dataset.parts ?? '',
    error: document.querySelector('#error')?.hidden ? '' : document.querySelector('#error')?.textContent ?? '',
  }));
}

/** Waits until the page has finished with `source` (ready or error) and returns its state. */
export async function waitForSettled(page, source, timeout = SETTLE_TIMEOUT_MS) {
  try {
    await page.waitForFunction(
      (expected) => document.body.dataset.source === expected
        && (document.body.dataset.status === 'ready' || document.body.dataset.status === 'error'),
      source,
      { timeout },
    );
  } catch (error) {
    const state = await pageState(page).catch(() => ({}));
    await screenshot(page, `timeout-${source}`).catch(() => {});
    throw new Error(`page did not settle on ${source} within ${timeout} ms: ${JSON.stringify(state)}`);
  }
  return pageState(page);
}

/** Like waitForSettled, but a page error is a test failure that quotes the page's message. */
export async function waitForReady(page, source, timeout) {
  const state = await waitForSettled(page, source, timeout);
  if (state.status !== 'ready') {
    await screenshot(page, `error-${source}`);
    assert.fail(`the page shows an error for ${source}: ${state.error}`);
  }
  return state;
}

export function assertInterlockingWithKey(state, key) {
  assert.equal(state.verdictCode, 'interlocking', `verdict: ${state.verdict}`);
  // The key is named as the part list names it: a part, a plate or a beam (issue 28, item 7).
  assert.match(state.verdict, new RegExp(`^Interlocking\\b.*\\b(part|plate|beam) ${key}$`));
  assert.equal(state.key, String(key));
}

/**
 * Opens the Design settings (N, seed, time limit, …): a phone folds them under the verdict
 * (issue 28, item 1), and a test that fills them opens them as a user taps "Settings".
 */
export async function showDesignSettings(page) {
  await page.evaluate(() => { document.querySelector('#design-settings').open = true; });
}
