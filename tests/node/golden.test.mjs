// SPDX-License-Identifier: GPL-3.0-or-later
// The golden corpus (tests/golden/, issue 25): every case of scripts/golden.mjs run again, natively
// (the CLI's exit code, masked stdout and stderr, every file it wrote and `desia check --json` of
// each) and through the WebAssembly package (the same designs, seeds and limits; the result
// document, its verification and check against the native files), one test per case. A failure
// names the case and the first differing line. If a change to results is intended, regenerate
// with `node scripts/golden.mjs generate` and say so in the commit message (tests/golden/README.md).
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { describe, test } from 'node:test';

import {
  caseDir, cases, goldenDir, KNOWN_WASM_ORDER_DIFFERENCES, loadWasmCore, nativeDifferences, runNative, wasmComparison,
} from '../../scripts/golden.mjs';
import { cliPath, requireBuilt } from './support.mjs';

const regenerate = 'if the change is intended, regenerate with node scripts/golden.mjs generate and say so in the commit message';

function assertNoDifferences(id, where, differences) {
  if (differences.length) assert.fail(`${id} (${where}) differs from tests/golden:\n  ${differences.join('\n  ')}\n(${regenerate})`);
}

test('the corpus holds exactly the cases of scripts/golden.mjs', () => {
  const manifest = JSON.parse(fs.readFileSync(path.join(goldenDir, 'manifest.json'), 'utf8'));
  assert.deepEqual(manifest.cases.map((c) => c.id), cases.map((c) => c.id), `tests/golden/manifest.json is stale (${regenerate})`);
  const missing = cases.filter((c) => !fs.existsSync(path.join(caseDir(c), 'record.json'))).map((c) => c.id);
  assert.deepEqual(missing, [], `no record for these cases (${regenerate})`);
  for (const id of KNOWN_WASM_ORDER_DIFFERENCES) assert.ok(cases.some((c) => c.id === id), `KNOWN_WASM_ORDER_DIFFERENCES names ${id}, which is no case`);
});

describe('golden corpus, native CLI', { concurrency: 2 }, () => {
  for (const testCase of cases) {
    test(testCase.id, async () => {
      requireBuilt(cliPath, 'scripts/build.sh native');
      const fresh = await runNative(testCase, { cli: cliPath });
      assertNoDifferences(testCase.id, `native: desia ${testCase.args.join(' ')}`, nativeDifferences(testCase, fresh));
    });
  }
});

describe('golden corpus, WebAssembly package', () => {
  // Loaded by the first test (not in a hook, so that a missing module fails every test, named).
  let loading;
  for (const testCase of cases.filter((c) => c.wasm)) {
    test(testCase.id, async (t) => {
      loading ??= loadWasmCore();
      const { differences, notes } = wasmComparison(testCase, await loading);
      for (const note of notes) t.diagnostic(note);
      assertNoDifferences(testCase.id, `WebAssembly, from ${testCase.input}`, differences);
    });
  }
});
