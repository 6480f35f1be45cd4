// SPDX-License-Identifier: GPL-3.0-or-later
// Frame structures in the package (issue 9, paper Section 5.3): designFrame in the worker and in
// the synchronous core gives the CLI's result document for the same seed, with progress and an
// AbortSignal; frames come from JSON, OBJ and .fpuz; partSurfaces and exportAssembly take frame
// documents (the core's framePartSurfaces / exportFrame) and export the CLI's bytes.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';

import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { root, runCli } from './support.mjs';

const examples = path.join(root, 'examples/frame');
const cubeFile = path.join(examples, 'frame_cube.json');
const cube = fs.readFileSync(cubeFile, 'utf8');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-frame-api-'));

const desia = await createDesia();
const core = await loadDesiaModule();
after(async () => {
  await desia.terminate();
  fs.rmSync(tmp, { recursive: true, force: true });
});

/** The CLI's result for `input` and `seed`: its text (the file as written) and the file's path. */
function cliDesign(input, seed, extra = []) {
  const output = path.join(tmp, `${path.basename(input)}-${seed}-result.json`);
  const cli = runCli(['design', 'frame', '--input', input, '--output', output, '--seed', String(seed), ...extra]);
  assert.equal(cli.status, 0, cli.stderr);
  return { text: fs.readFileSync(output, 'utf8'), file: output };
}

/** The CLI's export of `file` in `format`, as bytes. */
function cliExport(file, format) {
  const output = path.join(tmp, `export.${format}`);
  const cli = runCli(['export', file, '--format', format, '--output', output]);
  assert.equal(cli.status, 0, cli.stderr);
  return new Uint8Array(fs.readFileSync(output));
}

function badInput(pattern) {
  return (error) => {
    assert.ok(error instanceof DesiaError, String(error));
    assert.equal(error.code, 'bad-input');
    assert.match(error.message, pattern);
    return true;
  };
}

test('FrameApi.DesignsTheCliDocumentInTheWorkerWithProgress', async () => {
  const cli = cliDesign(cubeFile, 3);
  const progress = [];
  const result = await desia.designFrame(cube, { seed: 3, onProgress: (p) => { progress.push(p); } });
  assert.equal(result.status, 'success', result.message);
  assert.match(result.message, /^designed the joints of 12 beams \(key: beam 1(, input beam \d+)?\)/);
  assert.equal(result.puz, null);
  assert.deepEqual(Object.keys(result).sort(), ['document', 'message', 'progress', 'puz', 'status', 'verification']);
  // Byte for byte the CLI's file (JSON.stringify of the parsed file: the same keys in the same order
  // and the same values; nlohmann writes 120.0 where JavaScript writes 120).
  assert.equal(JSON.stringify(result.document), JSON.stringify(JSON.parse(cli.text)));
  assert.equal(result.document.kind, 'frame');
  assert.equal(result.document.beams.length, 12);
  assert.equal(result.document.jointVoxels.length, 8);
  assert.equal(result.verification.verdict, 'interlocking');
  assert.equal(result.verification.key, 1);
  assert.deepEqual(result.verification.disassembly.order, [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]);
  assert.equal(result.progress.targetParts, 12);
  assert.ok(progress.length >= 1);
  assert.equal(progress.at(-1).targetParts, 12);
  // The synchronous core gives the same, and the same seed twice the same again.
  const local = core.designFrame(JSON.parse(cube), { seed: 3 });
  assert.equal(JSON.stringify(local.document), JSON.stringify(result.document));
  assert.deepEqual(local.verification, result.verification);
  // Another seed: still the CLI's bytes for that seed.
  const other = await desia.designFrame(cube, { seed: 11, candidates: 3 });
  assert.equal(JSON.stringify(other.document), JSON.stringify(JSON.parse(cliDesign(cubeFile, 11, ['--candidates', '3']).text)));
});

test('FrameApi.EveryExampleDesignsToAnInterlockingResult', async () => {
  for (const [file, beams] of [['frame_chair.json', 11], ['flower.json', 23], ['scaffold_92.json', 92]]) {
    const text = fs.readFileSync(path.join(examples, file), 'utf8');
    const result = await desia.designFrame(text, { seed: 1, source: file });
    assert.equal(result.status, 'success', `${file}: ${result.message}`);
    assert.equal(result.document.beams.length, beams, file);
    assert.equal(result.verification.verdict, 'interlocking', file);
    assert.equal(result.verification.key, 1, file);
  }
});

test('FrameApi.CutPointAndBadInputNameTheBeamLikeTheCli', async () => {
  const cutPoint = path.join(examples, 'cut_point.json');
  const refused = await desia.designFrame(fs.readFileSync(cutPoint, 'utf8'), { source: cutPoint });
  assert.equal(refused.status, 'cut-point');
  assert.equal(refused.document, null);
  assert.equal(refused.verification, null);
  const cli = runCli(['design', 'frame', '--input', cutPoint, '--output', path.join(tmp, 'never.json')]);
  assert.equal(cli.status, 1);
  assert.equal(`desia: ${cutPoint}: ${refused.message}\n`, cli.stderr);
  assert.match(refused.message, /^beam 9 is a cut point of the parts-graph/);

  // A malformed frame: the same message as the CLI's.
  const broken = path.join(tmp, 'broken.json');
  fs.writeFileSync(broken, '{"kind": "frame", "joints": [[0,0,0],[100,0,0]], "beams": [[1,1]]}');
  const cliBroken = runCli(['design', 'frame', '--input', broken, '--output', path.join(tmp, 'never.json')]);
  assert.equal(cliBroken.status, 2);
  await assert.rejects(desia.designFrame(fs.readFileSync(broken, 'utf8'), { source: broken }),
    (error) => error instanceof DesiaError && error.code === 'bad-input' && `desia: error: ${error.message}\n` === cliBroken.stderr);
  await assert.rejects(desia.designFrame(cube, { jointSize: -1 }), badInput(/design option 'jointSize' must be a number above 0/));
  await assert.rejects(desia.designFrame(cube, { timeLimit: 'soon' }), badInput(/design option 'timeLimit' must be a number/));
  await assert.rejects(desia.designFrame(cube, { mode: 'fast' }), badInput(/unknown design option 'mode' for designFrame/));
  await assert.rejects(desia.designFrame(42), badInput(/designFrame: input must be a string/));
  assert.throws(() => core.parseFrame('v 0 0 0\nv 1 0 0\nl 1 1\n', { source: 'bad.obj' }), badInput(/^bad\.obj/));
  // The worker is still fine.
  assert.equal((await desia.designFrame(cube)).status, 'success');
});

test('FrameApi.ReadsObjAndFpuzAndHonoursJointSize', async () => {
  const document = JSON.parse(cube);
  // The cube's 12 edges as OBJ lines (every vertex a joint).
  const obj = [
    ...document.joints.map((joint) => `v ${joint.position.join(' ')}`),
    ...document.beams.map((beam) => `l ${beam.joints.join(' ')}`),
  ].join('\n');
  const fromObj = await desia.parseFrame(obj, { source: 'cube.obj' });
  assert.equal(fromObj.kind, 'frame');
  assert.equal(fromObj.joints.length, 8);
  assert.equal(fromObj.beams.length, 12);
  const designed = await desia.designFrame(obj, { source: 'cube.obj', seed: 2 });
  assert.equal(designed.status, 'success', designed.message);
  assert.equal(designed.verification.key, 1);

  const sized = await desia.designFrame(cube, { jointSize: 90 });
  assert.equal(sized.status, 'success', sized.message);
  assert.equal(sized.document.jointSize, 90);
  assert.equal((await desia.parseFrame(cube, { jointSize: 90 })).jointSize, 90);

  // .fpuz: written by the core, read again, designed again.
  const fpuz = new TextDecoder().decode(await desia.exportAssembly(designed.document, { format: 'fpuz' }));
  const reread = await desia.parseFrame(fpuz, { source: 'cube.fpuz' });
  assert.equal(reread.beams.length, 12);
  assert.deepEqual(reread.jointVoxels, designed.document.jointVoxels);
  const again = await desia.designFrame(fpuz, { source: 'cube.fpuz' });
  assert.equal(again.status, 'success', again.message);
  await assert.rejects(desia.parseFrame(cube, { jointSize: 'big' }), badInput(/parseFrame: jointSize must be a number/));
});

test('FrameApi.PartSurfacesAndExportsComeFromTheCore', async () => {
  const cli = cliDesign(cubeFile, 1);
  const result = JSON.parse(cli.text);
  // A designed frame: one surface per beam with its joint voxels, in id order, in mm.
  const surfaces = await desia.partSurfaces(result);
  assert.deepEqual(surfaces.map((s) => s.partId), [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]);
  for (const { positions, normals } of surfaces) {
    assert.ok(positions instanceof Float32Array && positions.length > 0 && positions.length % 9 === 0);
    assert.equal(normals.length, positions.length);
  }
  const xs = surfaces.flatMap((s) => Array.from(s.positions.filter((_, i) => i % 3 === 0)));
  assert.equal(Math.min(...xs), -60);
  assert.equal(Math.max(...xs), 660);
  // A frame without joints: its beams and the bare joint cubes (part 0).
  const bare = core.partSurfaces(cube);
  assert.deepEqual(bare.map((s) => s.partId), [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0]);
  // Exports: the CLI's bytes.
  for (const format of ['stl', 'obj', 'fpuz', 'csv', 'stl-ascii', 'pieces-obj', 'joint-pieces-stl']) {
    const bytes = await desia.exportAssembly(cli.text, { format });
    assert.deepEqual(bytes, cliExport(cli.file, format), format);
  }
  const part = await desia.exportAssembly(result, { format: 'stl', part: 1 });
  assert.ok(part.byteLength > 84);
  await assert.rejects(desia.exportAssembly(cube, { format: 'csv' }), badInput(/no designed joints yet/));
  // An axis-aligned frame on one grid exports as a voxel puzzle (BurrTools), the CLI's bytes.
  assert.deepEqual(await desia.exportAssembly(cli.text, { format: 'xmpuzzle' }), cliExport(cli.file, 'xmpuzzle'));
  await assert.rejects(desia.exportAssembly(result, { format: 'svg' }), badInput(/cut files are made of plate structures/));
  await assert.rejects(desia.exportAssembly(result, { format: 'stl', part: 13 }), badInput(/part 13 is not a beam of this frame/));
  await assert.rejects(desia.exportAssembly(cube, { format: 'pieces-obj' }), badInput(/no designed joints yet/));
  // The check reads a frame document like the CLI does, and sweeps each beam out in the plan.
  const checked = await desia.check(cli.text);
  assert.equal(checked.key, 1);
  assert.deepEqual(checked.shapeRemoval, { checked: 'each beam, its body and joint voxels, swept along its axis in the planned order', clear: true, failure: '' });
});

test('FrameApi.AbortStopsALongFrameDesign', async () => {
  // 882 beams: seconds of work (the 300-beam scaffold now designs in well under a second).
  const scaffold = fs.readFileSync(path.join(examples, 'scaffold_882.json'), 'utf8');
  const controller = new AbortController();
  let started;
  const progressed = new Promise((resolve) => { started = resolve; });
  const running = desia.designFrame(scaffold, { signal: controller.signal, onProgress: () => started() });
  await progressed;
  controller.abort();
  await assert.rejects(running, (error) => error instanceof DOMException && error.name === 'AbortError');
  // A fresh worker takes the next call.
  assert.equal((await desia.designFrame(cube)).status, 'success');
});
