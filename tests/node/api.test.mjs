// SPDX-License-Identifier: GPL-3.0-or-later
// The package API in node: loading without setup, results, errors, and the TypeScript
// declarations matching what the module really exports.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import * as desiaPackage from '../../wasm/index.js';
import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir, root } from './support.mjs';

const k9 = fs.readFileSync(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), 'utf8');

test('declared exports in index.d.ts are exactly the runtime exports', () => {
  const declarations = fs.readFileSync(path.join(root, 'wasm/index.d.ts'), 'utf8');
  const declared = [...declarations.matchAll(/^export (?:declare )?(?:function|class|const) (\w+)/gm)].map((m) => m[1]).sort();
  assert.deepEqual(Object.keys(desiaPackage).sort(), declared);
});

test('createDesia needs no setup and checks a reference puzzle', async () => {
  const desia = await createDesia();
  assert.match(desia.version(), /^\d+\.\d+\.\d+$/);
  const report = await desia.check(k9);
  assert.equal(report.verdict, 'interlocking');
  assert.equal(report.interlocking, true);
  assert.equal(report.deadlocked, false);
  assert.equal(report.key, 1);
  assert.deepEqual(report.keyDirections, ['-z']);
  assert.equal(report.parts, 9);
  assert.deepEqual(report.disassembly.order, [1, 2, 3, 4, 5, 6, 7, 8, 9]);
  assert.deepEqual(report.disassembly.paths[2], [{ dir: '+z', steps: 1 }, { dir: '-x', steps: 2 }]);
  assert.deepEqual(report.baseDirections.map((d) => d.label), ['+x', '+y', '+z']);
});

test('parseDocument returns the JSON assembly document', async () => {
  const core = await loadDesiaModule();
  const document = core.parseDocument(k9);
  assert.equal(document.format, 'desia-assembly');
  assert.equal(document.kind, 'voxel');
  assert.deepEqual(document.voxel.size, [4, 4, 4]);
  assert.equal(document.voxel.labels.length, 64);
  assert.deepEqual(document.parts.map((p) => p.voxelCount), [7, 7, 7, 7, 7, 7, 7, 8, 7]);
  // The document is itself valid input and gives the same verdict.
  assert.equal(core.check(JSON.stringify(document)).key, 1);
});

test('bad input rejects with a DesiaError carrying the core message', async () => {
  const desia = await createDesia();
  await assert.rejects(desia.check('4 4 4\n1 1 1 1\n1 1\n', { source: 'ragged.puz' }), (error) => {
    assert.ok(error instanceof DesiaError);
    assert.ok(error instanceof Error);
    assert.equal(error.code, 'bad-input');
    assert.equal(error.message, 'ragged.puz:3: row 2 of layer 1 has 2 values, expected Nx = 4');
    return true;
  });
  await assert.rejects(desia.check('{"kind": "voxel"', { source: 'cut.json' }), /cut\.json:1:\d+: malformed JSON/);
  await assert.rejects(desia.check('1024 1024 1024\n'), (error) => error.code === 'too-large');
  await assert.rejects(desia.check(k9, { method: 'magic' }), /unknown method 'magic'/);
  await assert.rejects(desia.check(42), (error) => error instanceof DesiaError && /must be a string/.test(error.message));
  // The module stays usable after errors.
  assert.equal((await desia.check(k9)).key, 1);
});

test('two parts in a row are a verdict, not a crash', async () => {
  const desia = await createDesia();
  for (const text of ['2 1 1\n1 2\n', '3 1 1\n1 2 3\n', '1 2 1\n1\n2\n', '1 1 2\n1\n\n2\n']) {
    const report = await desia.check(text, { method: 'both' });
    assert.equal(report.interlocking, false, text);
    assert.notEqual(report.disassembly, null, text);
  }
});

test("Fig. 4's assembly: only the linear program sees the motion", async () => {
  const desia = await createDesia();
  const text = fs.readFileSync(path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json'), 'utf8');
  const report = await desia.check(text, { method: 'both' });
  assert.equal(report.methods.dbg.verdict, 'deadlocked');
  assert.equal(report.methods.lp.verdict, 'not-interlocking');
  assert.deepEqual(report.witness.parts, [2, 3]);
  assert.equal(report.witness.direction, null);
  assert.deepEqual(report.witness.velocities, [[1, 0, 0], [0, 1, 0]]);
});

test('toPuz writes .puz text byte for byte as the original writer, from .puz or JSON', async () => {
  const core = await loadDesiaModule();
  assert.equal(core.toPuz(k9), k9);
  const document = core.parseDocument(k9);
  assert.equal(core.toPuz(document), k9);
  assert.equal(core.toPuz(JSON.stringify(document)), k9);
  const figure4 = fs.readFileSync(path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json'), 'utf8');
  assert.throws(() => core.toPuz(figure4, { source: 'fig4.json' }), /fig4\.json: only voxel assemblies have a \.puz form/);
});
