// SPDX-License-Identifier: GPL-3.0-or-later
// Print-ready exports through the package (issue 11): exportAssembly(result, { format: 'stl-zip' |
// 'build-plate-stl', voxelSize, clearance, spacing }) in the worker and in the synchronous core
// gives the native CLI's bytes; the ZIP is read back here (central directory, local headers,
// node's own CRC-32), one closed STL per part with the inset volume; the build plate's parts rest
// on z = 0 and do not overlap; a clearance of half a voxel or more is a DesiaError naming it.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { after, test } from 'node:test';
import zlib from 'node:zlib';

import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir, runCli } from './support.mjs';

const k9File = path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz');
const bunnyFile = path.join(referenceDir, 'result_puz/bunny_15x14x11_K80.puz');
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-print-'));

const desia = await createDesia();
const core = await loadDesiaModule();
after(async () => {
  await desia.terminate();
  fs.rmSync(tmp, { recursive: true, force: true });
});

function cliExport(file, format, extra) {
  const output = path.join(tmp, `${path.basename(file)}-${format}${extra.join('_')}`);
  const result = runCli(['export', file, '--format', format, ...extra, '--output', output]);
  assert.equal(result.status, 0, result.stderr);
  return new Uint8Array(fs.readFileSync(output));
}

/** The files of a stored ZIP, read from its central directory; each checked against its local header. */
function readZip(bytes) {
  const buffer = Buffer.from(bytes);
  const end = buffer.length - 22;
  assert.equal(buffer.readUInt32LE(end), 0x06054b50, 'end of central directory record');
  const count = buffer.readUInt16LE(end + 10);
  let at = buffer.readUInt32LE(end + 16);
  const files = [];
  for (let k = 0; k < count; k += 1) {
    assert.equal(buffer.readUInt32LE(at), 0x02014b50, 'central directory header');
    const [method, time, date, crc, size] = [buffer.readUInt16LE(at + 10), buffer.readUInt16LE(at + 12),
      buffer.readUInt16LE(at + 14), buffer.readUInt32LE(at + 16), buffer.readUInt32LE(at + 24)];
    const nameLength = buffer.readUInt16LE(at + 28);
    const local = buffer.readUInt32LE(at + 42);
    const name = buffer.toString('latin1', at + 46, at + 46 + nameLength);
    assert.deepEqual([method, time, date], [0, 0, 0x21], `${name}: stored, 1980-01-01 00:00`);
    assert.equal(buffer.readUInt32LE(local), 0x04034b50, `${name}: local header`);
    assert.ok(buffer.subarray(local + 4, local + 30).equals(buffer.subarray(at + 6, at + 32)), `${name}: same fields in both headers`);
    const data = buffer.subarray(local + 30 + nameLength, local + 30 + nameLength + size);
    assert.equal(zlib.crc32(data), crc, `${name}: CRC-32`);
    files.push({ name, data });
    at += 46 + nameLength;
  }
  return files;
}

/** Triangles of a binary STL: [[x, y, z] x 3]. */
function stlTriangles(data) {
  const count = data.readUInt32LE(80);
  assert.equal(data.length, 84 + 50 * count);
  return Array.from({ length: count }, (_, t) => [0, 1, 2].map((v) => [0, 1, 2].map((k) => data.readFloatLE(84 + 50 * t + 12 * (v + 1) + 4 * k))));
}

/** Every edge (between equal points) used by an even number of triangles, as many each way. */
function assertClosed(triangles, what) {
  const uses = new Map();
  const key = (p) => p.join(',');
  for (const t of triangles) {
    for (let k = 0; k < 3; k += 1) {
      const [a, b] = [key(t[k]), key(t[(k + 1) % 3])];
      uses.set(`${a}|${b}`, (uses.get(`${a}|${b}`) ?? 0) + 1);
    }
  }
  for (const [edge, count] of uses) {
    const [a, b] = edge.split('|');
    assert.equal(uses.get(`${b}|${a}`), count, `${what}: edge ${edge} used ${count} times one way`);
  }
}

function volume(triangles) {
  let sum = 0;
  for (const [a, b, c] of triangles) {
    sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return sum / 6;
}

function voxelCounts(file) {
  const labels = fs.readFileSync(file, 'utf8').trim().split(/\s+/).slice(3).map(Number);
  const counts = new Map();
  for (const label of labels) if (label > 0) counts.set(label, (counts.get(label) ?? 0) + 1);
  return counts;
}

test("stl-zip: the CLI's bytes in the worker and the core, one closed STL per part lying on z = 0, inset volume", async () => {
  const options = { format: 'stl-zip', voxelSize: 10, clearance: 0.2, source: 'bunny.puz' };
  const text = fs.readFileSync(bunnyFile, 'utf8');
  const zip = await desia.exportAssembly(text, options);
  assert.ok(zip instanceof Uint8Array);
  assert.deepEqual(zip, core.exportAssembly(text, options), 'worker and synchronous core agree');
  assert.deepEqual(zip, cliExport(bunnyFile, 'stl-zip', ['--voxel-size', '10', '--clearance', '0.2']), 'WebAssembly = native');
  const files = readZip(zip);
  const counts = voxelCounts(bunnyFile);
  assert.deepEqual(files.map((file) => file.name), Array.from({ length: 80 }, (_, k) => `part-${String(k + 1).padStart(2, '0')}.stl`));
  for (const [k, { name, data }] of files.entries()) {
    const triangles = stlTriangles(data);
    assertClosed(triangles, name);
    assert.equal(Math.min(...triangles.flat().map((p) => p[2])), 0, `${name} rests on z = 0`);
    // Inset: smaller than its voxels, but by less than a 0.2 mm skin over all of its faces.
    const full = counts.get(k + 1) * 1000;
    assert.ok(volume(triangles) < full && volume(triangles) > full - 0.2 * 6 * 100 * counts.get(k + 1), `${name}: volume`);
  }
});

test('build-plate-stl: every part on z = 0, no overlapping boxes, the same bytes natively', async () => {
  const options = { format: 'build-plate-stl', voxelSize: 10, clearance: 0.2, spacing: 5 };
  const text = fs.readFileSync(k9File, 'utf8');
  const plate = await desia.exportAssembly(text, options);
  assert.deepEqual(plate, cliExport(k9File, 'build-plate-stl', ['--voxel-size', '10', '--clearance', '0.2', '--spacing', '5']));
  const triangles = stlTriangles(Buffer.from(plate));
  assert.equal(Math.min(...triangles.flat().map((p) => p[2])), 0);
  // The parts' triangles, one part after the other, with the counts of the part-by-part ZIP.
  const zip = readZip(await desia.exportAssembly(text, { format: 'stl-zip', voxelSize: 10, clearance: 0.2 }));
  let next = 0;
  const boxes = zip.map(({ data }) => {
    const part = triangles.slice(next, next += stlTriangles(data).length);
    const points = part.flat();
    assert.ok(Math.abs(volume(part) - volume(stlTriangles(data))) < 1e-2, 'the same part, moved');
    return [0, 1, 2].map((k) => [Math.min(...points.map((p) => p[k])), Math.max(...points.map((p) => p[k]))]);
  });
  assert.equal(next, triangles.length);
  for (const [a, boxA] of boxes.entries()) {
    assert.equal(boxA[2][0], 0, `part ${a + 1} rests on the plate`);
    for (const [b, boxB] of boxes.entries()) {
      if (b <= a) continue;
      const gap = Math.max(boxB[0][0] - boxA[0][1], boxA[0][0] - boxB[0][1], boxB[1][0] - boxA[1][1], boxA[1][0] - boxB[1][1]);
      assert.ok(gap >= 5 - 1e-3, `parts ${a + 1} and ${b + 1} are ${gap} mm apart`);
    }
  }
  // The default spacing is one voxel.
  assert.deepEqual(await desia.exportAssembly(text, { format: 'build-plate-stl', voxelSize: 10 }),
    await desia.exportAssembly(text, { format: 'build-plate-stl', voxelSize: 10, spacing: 10 }));
});

test('bad clearances and spacings are DesiaErrors naming the value', async () => {
  const rejectsWith = (options, message) => assert.rejects(desia.exportAssembly(fs.readFileSync(k9File, 'utf8'), { source: 'k9.puz', ...options }), (error) => {
    assert.ok(error instanceof DesiaError, String(error));
    assert.equal(error.code, 'bad-input');
    assert.match(error.message, message);
    return true;
  });
  await rejectsWith({ format: 'stl-zip', voxelSize: 10, clearance: 5 },
    /^k9\.puz: the clearance must be at least 0 and less than half the voxel size \(5\), got 5$/);
  await rejectsWith({ format: 'stl', clearance: -0.1 }, /less than half the voxel size \(0\.5\), got -0\.1$/);
  await rejectsWith({ format: 'xmpuzzle', clearance: 0.1 }, /the clearance applies to stl, stl-ascii, obj, stl-zip and build-plate-stl$/);
  await rejectsWith({ format: 'stl-zip', clearance: '0.2' }, /^exportAssembly: clearance must be a number, got a string/);
  await rejectsWith({ format: 'build-plate-stl', spacing: -1 }, /the spacing must be a number from 0 to 1000000, got -1$/);
  await rejectsWith({ format: 'stl-zip', spacing: 3 }, /spacing apply to 'svg' and 'dxf' cut files only/);
});
