// SPDX-License-Identifier: GPL-3.0-or-later
// The package API in node: loading without setup, the worker-backed promise API against the
// native CLI (checks, seeded designs, progress, errors, step-by-step sessions, exports), and the
// TypeScript declarations matching what the module really exports and returns. Aborting,
// crashes, terminate() and idle exit: tests/node/package-worker.test.mjs.
import assert from 'node:assert/strict';
import { gunzipSync } from 'node:zlib';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';

import * as desiaPackage from '../../wasm/index.js';
import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir, referenceFiles, root, runCli } from './support.mjs';

const k9 = fs.readFileSync(path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz'), 'utf8');
const cubeShape = fs.readFileSync(path.join(referenceDir, 'input_puz/Cube_4x4x4_origin.puz'), 'utf8');
const declarations = fs.readFileSync(path.join(root, 'wasm/index.d.ts'), 'utf8');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-api-'));

// One worker-backed instance for the tests that do not stop workers, and one synchronous core
// (each load in this thread adds Emscripten's process listeners).
const desia = await createDesia();
const core = await loadDesiaModule();
after(async () => {
  await desia.terminate();
  fs.rmSync(tmp, { recursive: true, force: true });
});

/** The method names an interface of index.d.ts declares (`name(` at the start of a member line). */
function declaredMethods(interfaceName) {
  const match = new RegExp(`^export interface ${interfaceName}\\b[^{]*\\{([\\s\\S]*?)^\\}`, 'm').exec(declarations);
  assert.ok(match, `interface ${interfaceName} not found in index.d.ts`);
  return [...match[1].matchAll(/^ {2}(\w+)\(/gm)].map((m) => m[1]).sort();
}

/** The field names an interface of index.d.ts declares (`name:` or `name?:` at the start of a member line). */
function declaredFields(interfaceName) {
  const match = new RegExp(`^export interface ${interfaceName}\\b[^{]*\\{([\\s\\S]*?)^\\}`, 'm').exec(declarations);
  assert.ok(match, `interface ${interfaceName} not found in index.d.ts`);
  return [...match[1].matchAll(/^ {2}(\w+)\??:/gm)].map((m) => m[1]).sort();
}

/** Splits a binary STL into its triangle count and the extent of its vertices per axis. */
function binaryStlSummary(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const triangles = view.getUint32(80, true);
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let t = 0; t < triangles; t++) {
    for (let v = 0; v < 3; v++) {
      for (let axis = 0; axis < 3; axis++) {
        const value = view.getFloat32(84 + 50 * t + 12 + 12 * v + 4 * axis, true);
        min[axis] = Math.min(min[axis], value);
        max[axis] = Math.max(max[axis], value);
      }
    }
  }
  return { triangles, byteLength: bytes.byteLength, extent: max.map((m, axis) => m - min[axis]) };
}

test('declared exports in index.d.ts are exactly the runtime exports', () => {
  const declared = [...declarations.matchAll(/^export (?:declare )?(?:function|class|const) (\w+)/gm)].map((m) => m[1]).sort();
  assert.deepEqual(Object.keys(desiaPackage).sort(), declared);
});

test('the declared interfaces list exactly the methods of the objects the package returns', async () => {
  assert.deepEqual(Object.keys(desia).sort(), declaredMethods('Desia'));
  assert.deepEqual(Object.keys(core).sort(), declaredMethods('DesiaCore'));
  const session = await desia.designSession(cubeShape, { parts: 5 });
  assert.deepEqual(Object.keys(session).sort(), declaredMethods('AsyncDesignSession'));
  await session.dispose();
  const syncSession = core.designSession(cubeShape, { parts: 5 });
  assert.deepEqual(Object.keys(syncSession).sort(), declaredMethods('DesignSession'));
  syncSession.dispose();
  const [surface] = await desia.partSurfaces(k9);
  assert.deepEqual(Object.keys(surface).sort(), declaredFields('PartSurface'));
});

test('createDesia needs no setup and checks a reference puzzle', async () => {
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
  for (const text of ['2 1 1\n1 2\n', '3 1 1\n1 2 3\n', '1 2 1\n1\n2\n', '1 1 2\n1\n\n2\n']) {
    const report = await desia.check(text, { method: 'both' });
    assert.equal(report.interlocking, false, text);
    assert.notEqual(report.disassembly, null, text);
  }
});

test("Fig. 4's assembly: only the linear program sees the motion", async () => {
  const text = fs.readFileSync(path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json'), 'utf8');
  const report = await desia.check(text, { method: 'both' });
  assert.equal(report.methods.dbg.verdict, 'deadlocked');
  assert.equal(report.methods.lp.verdict, 'not-interlocking');
  assert.deepEqual(report.witness.parts, [2, 3]);
  assert.equal(report.witness.direction, null);
  assert.deepEqual(report.witness.velocities, [[1, 0, 0], [0, 1, 0]]);
});

test('toPuz writes .puz text byte for byte as the original writer, from .puz or JSON', async () => {
  assert.equal(core.toPuz(k9), k9);
  const document = core.parseDocument(k9);
  assert.equal(core.toPuz(document), k9);
  assert.equal(core.toPuz(JSON.stringify(document)), k9);
  const figure4 = fs.readFileSync(path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json'), 'utf8');
  assert.throws(() => core.toPuz(figure4, { source: 'fig4.json' }), /fig4\.json: only voxel assemblies have a \.puz form/);
});

test('the worker-backed check equals `desia check --json` on every reference file, with every method', async () => {
  const inputs = [...referenceFiles(), path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json')];
  for (const file of inputs) {
    for (const method of ['dbg', 'lp', 'both']) {
      const cli = runCli(['check', file, '--method', method, '--json']);
      assert.equal(cli.stderr, '', file);
      const report = await desia.check(fs.readFileSync(file, 'utf8'), { method, source: file });
      assert.deepEqual(report, JSON.parse(cli.stdout), `${file} --method ${method}`);
    }
  }
});

for (const worker of [true, false]) {
  test(`designVoxel (${worker ? 'in a worker' : 'in-process'}) gives the CLI's puzzle for the same seed, with progress`, async () => {
    const api = worker ? desia : await createDesia({ worker: false });
    const shapeFile = path.join(referenceDir, 'input_puz/Cube_5x5x5_origin.puz');
    const output = path.join(tmp, `cube5-${worker}.puz`);
    const cli = runCli(['design', 'voxel', '--input', shapeFile, '--parts', '12', '--seed', '4', '--jobs', '1', '--output', output]);
    assert.equal(cli.status, 0, cli.stderr);
    const seen = [];
    const result = await api.designVoxel(fs.readFileSync(shapeFile, 'utf8'), {
      parts: 12, seed: 4, source: 'Cube_5x5x5_origin.puz', onProgress: (progress) => seen.push(progress),
    });
    assert.equal(result.status, 'success', result.message);
    assert.equal(result.puz, fs.readFileSync(output, 'utf8'));
    // The same object as the synchronous core's, labels as a plain array included.
      assert.deepEqual(result, core.designVoxel(fs.readFileSync(shapeFile, 'utf8'), { parts: 12, seed: 4, source: 'Cube_5x5x5_origin.puz' }));
    assert.ok(Array.isArray(result.document.voxel.labels));
    assert.equal(result.verification.interlocking, true);
    assert.equal(result.verification.key, 1);
    // Progress arrived, and the last one is the final state of the search (plus its time).
    assert.ok(seen.length >= 1);
    // (A live `snapshot` of the deepest node rides on progress only: live_design.test.mjs.)
    const { elapsedSeconds, snapshot, ...last } = seen.at(-1);
    assert.ok(elapsedSeconds >= 0);
    assert.deepEqual(last, result.progress);
    assert.equal(seen.at(-1).bestDepth, 12);
    for (let i = 1; i < seen.length; i++) assert.ok(seen[i].nodesVisited > seen[i - 1].nodesVisited, 'progress moves forward');
    if (!worker) await api.terminate();
  });
}

test('bad design input and options reject with a DesiaError with the core message and code', async () => {
  const cases = [
    [cubeShape, { parts: 2 }, 'bad-input', /parts = 2: an interlocking puzzle needs at least 3 parts/],
    [cubeShape, { parts: 5, rank: 'prettiest' }, 'bad-input', /unknown ranking 'prettiest'/],
    [cubeShape, {}, 'bad-input', /design option 'parts' is required/],
    ['3 1 1\n1 0 1\n', { parts: 3, source: 'split.puz' }, 'bad-input', /^split\.puz: .*not face-connected/],
    [cubeShape, { parts: 5, onProgress: 'loudly' }, 'bad-input', /designVoxel: onProgress must be a function/],
    [cubeShape, { parts: 5, signal: 'stop' }, 'bad-input', /designVoxel: signal must be an AbortSignal/],
    [cubeShape, { parts: 5, shape: () => 1 }, 'bad-input', /designVoxel: the arguments cannot be sent to the worker/],
  ];
  for (const [shape, options, code, message] of cases) {
    await assert.rejects(desia.designVoxel(shape, options), (error) => {
      assert.ok(error instanceof DesiaError, String(error));
      assert.equal(error.code, code);
      assert.equal(error.fatal, false);
      assert.match(error.message, message);
      return true;
    });
  }
  // The same message as the CLI prints for the same file.
  const ragged = path.join(tmp, 'ragged.puz');
  fs.writeFileSync(ragged, '4 4 4\n1 1 1 1\n1 1\n');
  const cli = runCli(['design', 'voxel', '--input', ragged, '--parts', '5', '--output', path.join(tmp, 'never.puz')]);
  assert.equal(cli.status, 2);
  await assert.rejects(desia.designVoxel('4 4 4\n1 1 1 1\n1 1\n', { parts: 5, source: ragged }),
    (error) => error.code === 'bad-input' && `desia: error: ${error.message}\n` === cli.stderr);
  await assert.rejects(desia.voxelize(42), (error) => error instanceof DesiaError && /voxelize: mesh must be a Uint8Array/.test(error.message));
  // The worker is still fine.
  assert.equal((await desia.check(k9)).key, 1);
});

test('designFrame names unknown options and bad frames in the worker and the sync core (more: frame_api.test.mjs)', async () => {
  const expected = (pattern) => (error) => {
    assert.ok(error instanceof DesiaError, String(error));
    assert.equal(error.code, 'bad-input');
    assert.match(error.message, pattern);
    return true;
  };
  await assert.rejects(desia.designFrame('{}', { parts: 4 }), expected(/^unknown design option 'parts' for designFrame/));
  assert.throws(() => core.designFrame('{}', { parts: 4 }), expected(/^unknown design option 'parts' for designFrame/));
  assert.throws(() => core.designFrame('{}'), expected(/^<input>: kind: expected "frame"/));
});

test('designPlate plans the CLI\'s joints in the worker, with progress; bad options and cut points are named', async () => {
  const examples = path.join(root, 'examples/plate');
  const table = fs.readFileSync(path.join(examples, 'table.json'), 'utf8');
  const cli = runCli(['design', 'plate', '--input', path.join(examples, 'table.json'), '--output', path.join(os.tmpdir(), `desia-plan-${process.pid}.json`), '--seed', '3']);
  assert.equal(cli.status, 0, cli.stderr);
  const expected = JSON.parse(fs.readFileSync(path.join(os.tmpdir(), `desia-plan-${process.pid}.json`), 'utf8'));
  let progressCalls = 0;
  const result = await desia.designPlate(table, { seed: 3, onProgress: () => { progressCalls += 1; } });
  assert.equal(result.status, 'success');
  assert.equal(result.verification.verdict, 'interlocking');
  assert.equal(result.verification.key, 1);
  assert.deepEqual(result.document, expected, 'same seed, same plan as the CLI');
  assert.equal(result.puz, null);
  assert.ok(progressCalls >= 1);
  const chair = await desia.designPlate(fs.readFileSync(path.join(examples, 'chair_cut_point.json'), 'utf8'));
  assert.equal(chair.status, 'cut-point');
  assert.match(chair.message, /^plate 5 is a cut point of the parts-graph/);
  assert.equal(chair.repair.message, 'added plate 9, a bar joining plates 1 and 6 past cut point 5');
  assert.equal(chair.repair.document.plates.length, 9);
  // The repaired chair designs with made joints (its rails' dovetail housings run on to the legs' edges).
  const fixed = await desia.designPlate(chair.repair.document, { joints: 'milled' });
  assert.equal(fixed.status, 'success', fixed.message);
  assert.equal(fixed.document.jointGeometry, 'milled');
  await assert.rejects(desia.designPlate(table, { parts: 4 }), (error) => error.code === 'bad-input'
    && /unknown design option 'parts' for designPlate/.test(error.message));
  await assert.rejects(desia.designPlate(k9), (error) => error.code === 'bad-input' && /designPlate needs a plate design/.test(error.message));
  assert.equal(result.document.jointGeometry, 'cut');
  const loose = await desia.designPlate(table, { seed: 3, clearance: 0.2, tenonCount: 1 });
  assert.equal(loose.status, 'success');
  assert.equal(loose.document.clearance, 0.2);
  assert.equal(loose.document.fabricationPlates.length, 6);
  const planned = await desia.designPlate(table, { joints: 'planned' });
  assert.equal(planned.document.jointGeometry, 'planned');
  await assert.rejects(desia.designPlate(table, { joints: 'glued' }), (error) => error.code === 'bad-input' && /joints must be 'auto' \(cut if possible, else milled, else planned\), 'cut'/.test(error.message));
  await assert.rejects(desia.designPlate(table, { clearance: -1 }), (error) => error.code === 'bad-input' && /clearance/.test(error.message));
  // Cut sheets in the worker are the CLI's, byte for byte.
  const resultFile = path.join(os.tmpdir(), `desia-plate-${process.pid}.json`);
  fs.writeFileSync(resultFile, JSON.stringify(loose.document));
  const svgFile = path.join(os.tmpdir(), `desia-plate-${process.pid}.svg`);
  assert.equal(runCli(['export', resultFile, '--format', 'svg', '--kerf', '0.1', '--output', svgFile]).status, 0);
  const sheets = await desia.cutSheets(loose.document, { kerf: 0.1 });
  assert.equal(sheets.length, 1);
  assert.equal(sheets[0], fs.readFileSync(svgFile, 'utf8'));
  const bytes = await desia.exportAssembly(loose.document, { format: 'dxf' });
  assert.match(new TextDecoder().decode(bytes), /CUT_OUTER/);
  await assert.rejects(desia.cutSheets(loose.document, { sheet: '600x400' }), (error) => error.code === 'bad-input'
    && /plate 1 \(1050 x 650 mm\) does not fit/.test(error.message));
  await assert.rejects(desia.exportAssembly(loose.document, { format: 'svg', sheetIndex: 3 }), (error) => error.code === 'bad-input'
    && /sheetIndex 3 is out of range/.test(error.message));
});

test('designPlate with joints \'milled\' gives the CLI\'s CABINET (Fig. 13): a mitre joint at the ridge, the sides\' tenons in the roof, verified on exact faces', async () => {
  const input = path.join(root, 'examples/plate/cabinet.json');
  const cabinet = fs.readFileSync(input, 'utf8');
  const cliFile = path.join(tmp, 'cabinet-milled.json');
  const cli = runCli(['design', 'plate', '--input', input, '--joints', 'milled', '--seed', '2', '--output', cliFile]);
  assert.equal(cli.status, 0, cli.stderr);
  const result = await desia.designPlate(cabinet, { joints: 'milled', seed: 2 });
  assert.equal(result.status, 'success', result.message);
  assert.equal(result.verification.verdict, 'interlocking');
  assert.equal(result.verification.shapeRemoval.clear, true);
  assert.equal(JSON.stringify(result.document), JSON.stringify(JSON.parse(fs.readFileSync(cliFile, 'utf8'))));
  const types = new Set(result.document.joints.map((joint) => joint.type));
  assert.ok((types.has('mitre-tenon') || types.has('mitre-slide')) && types.has('mortise-tenon'), [...types].join(', '));
});

test('designPlate with joints \'milled\' gives the CLI\'s BOOKSHELF: sliding dovetails, replayed on the shapes, STL not cut sheets', async () => {
  const input = path.join(root, 'examples/plate/bookshelf.json');
  const bookshelf = fs.readFileSync(input, 'utf8');
  const cliFile = path.join(tmp, 'bookshelf-milled.json');
  const cli = runCli(['design', 'plate', '--input', input, '--joints', 'milled', '--output', cliFile]);
  assert.equal(cli.status, 0, cli.stderr);
  const cliText = fs.readFileSync(cliFile, 'utf8');
  const result = await desia.designPlate(bookshelf, { joints: 'milled' });
  assert.equal(result.status, 'success', result.message);
  assert.equal(result.verification.verdict, 'interlocking');
  assert.equal(result.verification.key, 1);
  // Byte for byte the CLI's file (JSON.stringify of the parsed file: the same keys in the same
  // order and the same values; nlohmann writes -0.0 and 120.0 where JavaScript writes 0 and 120).
  assert.equal(JSON.stringify(result.document), JSON.stringify(JSON.parse(cliText)));
  assert.equal(JSON.stringify(core.designPlate(bookshelf, { joints: 'milled' }).document), JSON.stringify(result.document), 'the synchronous core too');
  const { document } = result;
  assert.equal(document.jointGeometry, 'milled');
  assert.equal(document.plates.length, 12);
  const types = document.joints.map((joint) => joint.type);
  assert.ok(types.includes('dovetail'), JSON.stringify(types));
  assert.ok(types.every((type) => type === 'dovetail' || type === 'mortise-tenon'), JSON.stringify(types));
  assert.ok(document.plates.some((plate) => Array.isArray(plate.attached) && plate.attached.length > 0), 'the dovetails\' solids are attached to their plates');
  // The check replays the removal plan on the milled plates.
  const report = await desia.check(JSON.stringify(document));
  assert.equal(report.verdict, 'interlocking');
  assert.equal(report.shapeRemoval.clear, true, report.shapeRemoval.failure);
  assert.equal(report.shapeRemoval.failure, '');
  // Cut sheets cannot hold a dovetail: the core's message, in the worker and the sync core.
  const milledMessage = /plate \d+ carries \d+ solid\(s\) of milled joints \(its "attached": tongues, tenons, housing walls\), which cut sheets cannot hold: export stl or obj for the CNC, or design with joints 'cut'/;
  await assert.rejects(desia.cutSheets(document), (error) => error instanceof DesiaError && error.code === 'bad-input' && milledMessage.test(error.message));
  await assert.rejects(desia.exportAssembly(document, { format: 'dxf' }), (error) => error.code === 'bad-input' && milledMessage.test(error.message));
  assert.throws(() => core.cutSheets(cliText), (error) => error.code === 'bad-input' && milledMessage.test(error.message));
  // STL and OBJ hold the dovetails: the CLI's bytes; the surfaces the viewer draws are the STL's triangles.
  for (const format of ['stl', 'obj']) {
    const output = path.join(tmp, `bookshelf-milled.${format}`);
    const exported = runCli(['export', cliFile, '--format', format, '--output', output]);
    assert.equal(exported.status, 0, exported.stderr);
    assert.deepEqual(await desia.exportAssembly(document, { format }), new Uint8Array(fs.readFileSync(output)), format);
  }
  const stl = binaryStlSummary(await desia.exportAssembly(document, { format: 'stl' }));
  const surfaces = await desia.partSurfaces(document);
  assert.deepEqual(surfaces.map((surface) => surface.partId), [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]);
  assert.equal(surfaces.reduce((sum, surface) => sum + surface.positions.length / 9, 0), stl.triangles);
  // A step-by-step session takes joints 'milled' too; its children's joints are of the declared types.
  const session = core.designSession(bookshelf, { joints: 'milled' });
  try {
    assert.ok(session.childCount() > 0);
    for (const joint of session.preview(0).joints) assert.ok(['mortise-tenon', 'halved', 'dovetail', 'empty'].includes(joint.type), joint.type);
  } finally {
    session.dispose();
  }
});

test('a design session in the worker steps like the synchronous one', async () => {
  const options = { parts: 6, seed: 2 };
  const local = core.designSession(cubeShape, options);
  const remote = await desia.designSession(cubeShape, options);
  try {
    assert.deepEqual(await remote.state(), local.state());
    assert.equal(await remote.back(), false);
    assert.equal(await remote.next(), local.next());
    const children = await remote.childCount();
    assert.equal(children, local.childCount());
    assert.ok(children > 2);
    const preview = await remote.preview(2);
    assert.deepEqual(preview, local.preview(2));
    assert.ok(Array.isArray(preview.voxel.labels));
    assert.equal(await remote.choose(2), undefined);
    local.choose(2);
    assert.deepEqual((await remote.state()).document, preview);
    assert.deepEqual(await remote.check(), local.check());
    assert.equal(await remote.back(), true);
    local.back();
    while (!(await remote.state()).complete && (await remote.next())) local.next();
    assert.deepEqual(await remote.state(), local.state());
    await assert.rejects(remote.choose(999), (error) => error instanceof DesiaError && /child 999 does not exist/.test(error.message));
  } finally {
    local.dispose();
    await remote.dispose();
  }
  await assert.rejects(remote.state(), (error) => error.code === 'bad-input' && /the session was disposed/.test(error.message));
  await remote.dispose(); // twice is fine
  await assert.rejects(desia.designSession(cubeShape, { parts: 1 }), /needs at least 3 parts/);
});

test('voxelize in the worker moves a copy: the caller keeps its buffer', async () => {
  const bytes = fs.readFileSync(path.join(root, 'tests/data/meshes/octahedron.obj'));
  const expected = core.voxelize(bytes, { resolution: 8, source: 'octahedron.obj' });
  const text = bytes.toString('utf8');
  // A node Buffer (whose slice() is a view), a plain Uint8Array, an ArrayBuffer and a view into it.
  const array = new Uint8Array(bytes);
  for (const input of [bytes, array, array.buffer, new DataView(array.buffer, 0, array.byteLength)]) {
    const document = await desia.voxelize(input, { resolution: 8, source: 'octahedron.obj' });
    assert.deepEqual(document, expected);
    assert.ok(Array.isArray(document.voxel.labels));
  }
  assert.equal(bytes.toString('utf8'), text);
  assert.equal(new TextDecoder().decode(array), text);
  assert.equal(array.buffer.byteLength, bytes.byteLength);
});

// exportAssembly needs the exporter binding in dist/ (scripts/build.sh wasm).
test('exportAssembly writes STL, OBJ and BurrTools files of a voxel puzzle', async () => {
  const stl = await desia.exportAssembly(k9, { format: 'stl', source: 'k9.puz' });
  assert.ok(stl instanceof Uint8Array);
  assert.deepEqual(stl, core.exportAssembly(k9, { source: 'k9.puz' }), 'the default format is binary STL, the same in the worker');
  const all = binaryStlSummary(stl);
  assert.equal(all.byteLength, 84 + 50 * all.triangles);
  assert.deepEqual(all.extent, [4, 4, 4]);
  // One part, and a voxel size that scales the model.
  const key = binaryStlSummary(await desia.exportAssembly(core.parseDocument(k9), { format: 'stl', part: 1 }));
  assert.ok(key.triangles > 0 && key.triangles < all.triangles);
  assert.deepEqual(binaryStlSummary(await desia.exportAssembly(k9, { voxelSize: 2.5 })).extent, [10, 10, 10]);
  const ascii = new TextDecoder().decode(await desia.exportAssembly(k9, { format: 'stl-ascii' }));
  assert.match(ascii, /^solid/);
  assert.match(ascii, /endsolid[^\n]*\n?$/);
  assert.equal(ascii.match(/\bfacet normal\b/g).length, all.triangles);
  const obj = new TextDecoder().decode(await desia.exportAssembly(k9, { format: 'obj' }));
  assert.match(obj, /^v -?[\d.]+ -?[\d.]+ -?[\d.]+$/m);
  assert.match(obj, /^f \d+/m);
  const xmpuzzle = await desia.exportAssembly(k9, { format: 'xmpuzzle' });
  // BurrTools always writes gzip; ours must unzip (CRC and length checked by zlib) to the XML.
  const xml = gunzipSync(xmpuzzle).toString('utf8');
  assert.match(xml, /^<\?xml version="1\.0"\?>\n<puzzle version="2">/);
  assert.equal(xml.match(/<voxel /g).length, 10, 'the result shape and the 9 pieces');
  assert.deepEqual(xmpuzzle, core.exportAssembly(k9, { format: 'xmpuzzle' }), 'worker and sync core agree');
  // Bad arguments and inputs.
  const rejectsWith = (promise, code, message) => assert.rejects(promise, (error) => {
    assert.ok(error instanceof DesiaError, String(error));
    assert.equal(error.code, code);
    assert.match(error.message, message);
    return true;
  });
  // Byte for byte what `desia export` writes, for every format.
  const k9File = path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz');
  for (const [format, part, voxelSize] of [['stl', 0, 1], ['stl', 3, 2], ['stl-ascii', 0, 1], ['obj', 2, 0.5], ['xmpuzzle', 0, 1]]) {
    const output = path.join(tmp, `k9-${part}.${format}`);
    const cli = runCli(['export', k9File, '--format', format, '--part', String(part), '--voxel-size', String(voxelSize), '--output', output]);
    assert.equal(cli.status, 0, cli.stderr);
    const bytes = await desia.exportAssembly(k9, { format, part, voxelSize, source: k9File });
    assert.deepEqual(bytes, new Uint8Array(fs.readFileSync(output)), `${format} part ${part}`);
  }
  await rejectsWith(desia.exportAssembly(k9, { part: 'key' }), 'bad-input', /^exportAssembly: part must be an integer \(32-bit\), got a string \("key"\)$/);
  await rejectsWith(desia.exportAssembly(k9, { voxelSize: '2' }), 'bad-input', /^exportAssembly: voxelSize must be a number, got a string/);
  // Ranges are the core's to name.
  await rejectsWith(desia.exportAssembly(k9, { voxelSize: -1 }), 'bad-input', /the voxel size must be a number from 0\.000001 to 1000000, got -1$/);
  await rejectsWith(desia.exportAssembly(k9, { part: -1 }), 'bad-input', /part -1 does not exist: the assembly has parts 1 to 9/);
  await rejectsWith(desia.exportAssembly(k9, { format: 7 }), 'bad-input', /exportAssembly: format must be a string/);
  await rejectsWith(desia.exportAssembly(42), 'bad-input', /exportAssembly: assembly must be a string/);
  await rejectsWith(desia.exportAssembly(k9, { format: 'dxf', source: 'k9.puz' }), 'bad-input', /^k9\.puz: cut files are made of plate structures/);
  await rejectsWith(desia.exportAssembly(k9, { format: 'pdf' }), 'bad-input', /pdf/);
  await rejectsWith(desia.exportAssembly(k9, { kerf: 0.1 }), 'bad-input', /kerf apply to 'svg' and 'dxf' cut files only/);
  await rejectsWith(desia.exportAssembly('4 4 4\n1 1 1 1\n1 1\n', { source: 'ragged.puz' }), 'bad-input',
    /^ragged\.puz:3: row 2 of layer 1 has 2 values, expected Nx = 4$/);
});

test('partSurfaces gives every part the triangles of its STL export, the same in the worker', async () => {
  const rejectsWith = (promise, code, message) => assert.rejects(promise, (error) => {
    assert.ok(error instanceof DesiaError);
    assert.equal(error.code, code);
    assert.match(error.message, message);
    return true;
  });
  const surfaces = await desia.partSurfaces(k9, { source: 'k9.puz' });
  const fromCore = core.partSurfaces(core.parseDocument(k9));
  assert.deepEqual(surfaces.map((s) => s.partId), [1, 2, 3, 4, 5, 6, 7, 8, 9]);
  assert.deepEqual(surfaces, fromCore, 'worker and sync core agree (text in, document object in)');
  for (const { partId, positions, normals } of surfaces) {
    assert.ok(positions instanceof Float32Array && normals instanceof Float32Array);
    assert.equal(positions.length, normals.length);
    const { triangles } = binaryStlSummary(core.exportAssembly(k9, { format: 'stl', part: partId }));
    assert.equal(positions.length / 9, triangles, `part ${partId}: as many triangles as its binary STL`);
    for (let v = 0; v < normals.length; v += 3) {
      const n = [normals[v], normals[v + 1], normals[v + 2]];
      assert.equal(n.filter((c) => c !== 0).length, 1, `part ${partId}: an axis normal`);
      assert.ok(n.every((c) => c === 0 || Math.abs(c) === 1), `part ${partId}: a unit normal`);
    }
  }
  await rejectsWith(desia.partSurfaces(k9, { format: 'stl' }), 'bad-input', /^partSurfaces: unknown option 'format' \(expected source or signal\)$/);
  assert.throws(() => core.partSurfaces(k9, 'k9.puz'),
    (error) => error instanceof DesiaError && /^partSurfaces: options must be an object, got a string/.test(error.message));
  await rejectsWith(desia.partSurfaces(42), 'bad-input', /^partSurfaces: assembly must be a string, got a number/);
  const contacts = JSON.stringify({ format: 'desia-assembly', kind: 'contacts', parts: [{ id: 1 }, { id: 2 }],
    contacts: [{ a: 1, b: 2, normal: [1, 0, 0] }] });
  await rejectsWith(desia.partSurfaces(contacts, { source: 'c.json' }), 'bad-input', /^c\.json: export needs a voxel assembly, this is a contacts document$/);
});

test('a plate design session steps to the verified plan designPlate finds, in the worker too', async () => {
  const table = fs.readFileSync(path.join(root, 'examples/plate/table.json'), 'utf8');
  const expected = core.designPlate(table, { seed: 1 });
  for (const session of [core.designSession(table, { seed: 1 }), await desia.designSession(table, { seed: 1 })]) {
    try {
      const first = await session.state();
      assert.deepEqual([first.partsPlaced, first.targetParts, first.complete], [1, 6, false]);
      assert.equal(first.document.kind, 'plate');
      assert.ok(await session.childCount() > 0);
      const preview = await session.preview(0);
      assert.equal(preview.plate, 1, 'the top is the best key');
      assert.deepEqual(preview.direction, [0, 1, 0]);
      assert.ok(preview.joints.every((joint) => joint.type === 'mortise-tenon'));
      while (!(await session.state()).complete) assert.equal(await session.next(), true);
      const done = await session.state();
      assert.equal(done.steps.length, 5);
      assert.deepEqual(done.document, expected.document, 'the same verified result as designPlate');
      const report = await session.check();
      assert.equal(report.verdict, 'interlocking');
      assert.equal(report.key, 1);
      assert.equal(await session.back(), true);
      assert.equal((await session.state()).complete, false);
    } finally {
      await session.dispose();
    }
  }
  const chair = fs.readFileSync(path.join(root, 'examples/plate/chair_cut_point.json'), 'utf8');
  assert.throws(() => core.designSession(chair, {}), (error) => error.code === 'bad-input' && /^plate 5 is a cut point/.test(error.message));
});

test('a frame design session steps FRAME CUBE to a verified design, in the worker too', async () => {
  const cube = fs.readFileSync(path.join(root, 'examples/frame/frame_cube.json'), 'utf8');
  const expected = core.designFrame(cube, { seed: 1 });
  for (const session of [core.designSession(cube, { seed: 1, source: 'frame_cube.json' }),
    await desia.designSession(cube, { seed: 1, source: 'frame_cube.json' })]) {
    try {
      const first = await session.state();
      assert.deepEqual([first.partsPlaced, first.targetParts, first.complete, first.steps], [1, 12, false, []]);
      assert.equal(first.document.kind, 'frame');
      assert.ok(await session.childCount() > 0);
      const preview = await session.preview(0);
      assert.equal(typeof preview.beam, 'number');
      assert.deepEqual(preview.direction, [0, 1, 0], 'the key leaves upwards');
      assert.equal(preview.joints.length, 2);
      assert.ok(preview.joints.every((joint) => typeof joint.joint === 'number' && Array.isArray(joint.voxels)));
      while (!(await session.state()).complete) assert.equal(await session.next(), true);
      const done = await session.state();
      assert.equal(done.steps.length, 11);
      assert.equal(done.steps[0].beam, preview.beam);
      assert.equal(done.document.kind, 'frame');
      assert.ok(Array.isArray(done.document.jointVoxels), 'the result document, with its joint voxels');
      assert.deepEqual(done.document, expected.document, 'the same verified result as designFrame');
      const report = await session.check();
      assert.equal(report.verdict, 'interlocking');
      assert.equal(report.key, 1);
      assert.equal(await session.back(), true);
      assert.equal((await session.state()).complete, false);
      assert.equal(await session.next(), true);
      assert.equal((await session.state()).complete, true);
    } finally {
      await session.dispose();
    }
  }
  const cut = fs.readFileSync(path.join(root, 'examples/frame/cut_point.json'), 'utf8');
  assert.throws(() => core.designSession(cut, {}), (error) => error.code === 'bad-input' && /^beam 9 is a cut point/.test(error.message));
});
