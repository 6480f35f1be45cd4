#!/usr/bin/env node
// SPDX-License-Identifier: GPL-3.0-or-later
//
// npm's `prepack` step (run by `npm pack` and `npm publish`): the package is useless without its
// WebAssembly module, and npm would silently pack a checkout that was never built. So:
//   - every dist/ file listed in package.json "files" is there (the .wasm a WebAssembly binary):
//     nothing to do, nothing printed;
//   - some are missing and this checkout can build them (scripts/build.sh and Emscripten's
//     emcmake on PATH): builds them with `bash scripts/build.sh wasm`, then checks again;
//   - otherwise: stops with a message saying how to build them, and npm packs nothing.
// Everything goes to stderr: `npm pack --json` keeps a clean stdout.

import { spawnSync } from 'node:child_process';
import { accessSync, constants, existsSync, openSync, readFileSync, readSync, closeSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const BUILD_COMMAND = 'bash scripts/build.sh wasm';
const HOW_TO_BUILD = `Build it first, from the repository root:\n\n    ${BUILD_COMMAND}\n\n`
  + '(bash scripts/setup.sh installs Emscripten 3.1.6 and what else the build needs; '
  + 'bash scripts/start.sh does both and serves the playground.)';

/** The dist/ files the package ships, from package.json "files". */
function moduleFiles() {
  const manifest = JSON.parse(readFileSync(path.join(ROOT, 'package.json'), 'utf8'));
  const files = (manifest.files ?? []).filter((file) => file.startsWith('dist/'));
  if (!files.some((file) => file.endsWith('.wasm'))) {
    throw new Error('package.json "files" lists no dist/*.wasm: the package would ship without its WebAssembly module');
  }
  return files;
}

/** Why `file` is not a usable build output, or null when it is. */
function problemWith(file) {
  const full = path.join(ROOT, file);
  if (!existsSync(full)) return 'missing';
  const size = statSync(full).size;
  if (size === 0) return 'empty';
  if (file.endsWith('.wasm')) {
    const magic = Buffer.alloc(4);
    const fd = openSync(full, 'r');
    try {
      readSync(fd, magic, 0, 4, 0);
    } finally {
      closeSync(fd);
    }
    if (!magic.equals(Buffer.from([0x00, 0x61, 0x73, 0x6d]))) return 'not a WebAssembly binary';
  }
  return null;
}

function problems(files) {
  return files.map((file) => [file, problemWith(file)]).filter(([, problem]) => problem !== null);
}

function onPath(command) {
  return (process.env.PATH ?? '').split(path.delimiter).some((dir) => {
    if (!dir) return false;
    try {
      accessSync(path.join(dir, command), constants.X_OK);
      return true;
    } catch {
      return false;
    }
  });
}

function fail(message) {
  console.error(`\ndesia prepack: ${message}\n`);
  process.exit(1);
}

function main() {
  let files;
  try {
    files = moduleFiles();
  } catch (error) {
    fail(error.message);
  }
  let found = problems(files);
  if (found.length === 0) return;
  const list = found.map(([file, problem]) => `${file} (${problem})`).join(', ');
  const canBuild = existsSync(path.join(ROOT, 'scripts/build.sh')) && onPath('emcmake');
  if (!canBuild) {
    fail(`the package needs its WebAssembly module, and this checkout lacks it: ${list}.\n${HOW_TO_BUILD}`);
  }
  console.error(`desia prepack: ${list}; building the WebAssembly module (${BUILD_COMMAND})…`);
  // The build's stdout goes to stderr too, so that `npm pack --json` prints only its JSON.
  const build = spawnSync('bash', ['scripts/build.sh', 'wasm'], { cwd: ROOT, stdio: ['ignore', 2, 2] });
  if (build.error || build.status !== 0) {
    fail(`${BUILD_COMMAND} failed (${build.error?.message ?? `exit ${build.status}`}): nothing was packed.\n`
      + 'Run bash scripts/setup.sh, then the build again, and read its messages.');
  }
  found = problems(files);
  if (found.length > 0) {
    fail(`${BUILD_COMMAND} finished but left ${found.map(([file, problem]) => `${file} (${problem})`).join(', ')}: nothing was packed.`);
  }
  console.error('desia prepack: built.');
}

main();
