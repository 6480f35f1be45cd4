// SPDX-License-Identifier: GPL-3.0-or-later
// Paths and helpers shared by the node tests.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const root = fileURLToPath(new URL('../../', import.meta.url));
export const referenceDir = path.join(root, 'tests/reference/desia/data');
/** The native CLI: build/native's, or the one named by DESIA_CLI (a build directory of one's own). */
export const cliPath = process.env.DESIA_CLI ? path.resolve(process.env.DESIA_CLI) : path.join(root, 'build/native/core/cli/desia');

export function referenceFiles() {
  const files = [];
  for (const folder of ['result_puz', 'input_puz']) {
    for (const name of fs.readdirSync(path.join(referenceDir, folder)).sort()) files.push(path.join(referenceDir, folder, name));
  }
  return files;
}

export function requireBuilt(file, how) {
  if (!fs.existsSync(file)) throw new Error(`${path.relative(root, file)} is missing: run ${how} first`);
}

/** Runs the native CLI; returns { status, stdout, stderr }. */
export function runCli(args) {
  requireBuilt(cliPath, 'scripts/build.sh native');
  const result = spawnSync(cliPath, args, { encoding: 'utf8', maxBuffer: 64 << 20 });
  if (result.error) throw result.error;
  return result;
}
