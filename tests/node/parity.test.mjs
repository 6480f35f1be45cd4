// SPDX-License-Identifier: GPL-3.0-or-later
// The WebAssembly module and the native CLI give the same report, field for field, on every
// reference file (and the CLI's exit codes follow the verdict).
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { loadDesiaModule } from '../../wasm/index.js';
import { referenceFiles, root, runCli } from './support.mjs';

const core = await loadDesiaModule();
const inputs = [...referenceFiles(), path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json')];

for (const file of inputs) {
  for (const method of ['dbg', 'lp', 'both']) {
    test(`${path.basename(file)} --method ${method}: wasm equals native`, () => {
      const cli = runCli(['check', file, '--method', method, '--json']);
      assert.equal(cli.stderr, '');
      const native = JSON.parse(cli.stdout);
      const wasm = core.check(fs.readFileSync(file, 'utf8'), { method, source: file });
      assert.deepEqual(wasm, native);
      assert.equal(cli.status, native.interlocking ? 0 : 1);
      for (const field of ['parts', 'interlocking', 'deadlocked', 'key', 'keyDirections', 'disassembly']) {
        assert.ok(field in native, `field ${field} missing`);
      }
    });
  }
}

test('every reference result is interlocking with key 1 and disassembles in id order', () => {
  for (const file of referenceFiles().filter((f) => f.includes('result_puz'))) {
    const report = JSON.parse(runCli(['check', file, '--json']).stdout);
    assert.equal(report.interlocking, true, file);
    assert.equal(report.key, 1, file);
    assert.deepEqual(report.disassembly.order, report.partIds, file);
  }
});
