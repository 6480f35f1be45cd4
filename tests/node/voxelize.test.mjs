// SPDX-License-Identifier: GPL-3.0-or-later
// Mesh voxelization: the WebAssembly module against the native CLI on the same meshes (same
// document, same labels), every accepted input type, and bad meshes rejecting with the CLI's
// message.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';

import { createDesia, DesiaError, loadDesiaModule } from '../../wasm/index.js';
import { root, runCli } from './support.mjs';

const core = await loadDesiaModule();
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-voxelize-'));
const octahedronFile = path.join(root, 'tests/data/meshes/octahedron.obj');

function writeTemp(name, content) {
  const file = path.join(tmp, name);
  fs.writeFileSync(file, content);
  return file;
}

// A torus around the y axis (major radius 1, minor 0.4), slightly tilted so no row lines up.
function torus(segments = 28, sides = 14) {
  const vertices = [];
  const triangles = [];
  for (let i = 0; i < segments; i++) {
    const u = (2 * Math.PI * i) / segments;
    for (let j = 0; j < sides; j++) {
      const v = (2 * Math.PI * j) / sides;
      const r = 1 + 0.4 * Math.cos(v);
      const [x, y, z] = [r * Math.cos(u), 0.4 * Math.sin(v), r * Math.sin(u)];
      vertices.push([x + 0.05 * y, y - 0.05 * x, z]);
    }
  }
  const at = (i, j) => (i % segments) * sides + (j % sides);
  for (let i = 0; i < segments; i++) {
    for (let j = 0; j < sides; j++) {
      triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
    }
  }
  return { vertices, triangles };
}

function objText({ vertices, triangles }) {
  return `${vertices.map((v) => `v ${v.join(' ')}`).join('\n')}\n${triangles.map((t) => `f ${t.map((k) => k + 1).join(' ')}`).join('\n')}\n`;
}

function binaryStl({ vertices, triangles }) {
  const buffer = Buffer.alloc(84 + 50 * triangles.length);
  buffer.write('solid binary header', 0, 'ascii');
  buffer.writeUInt32LE(triangles.length, 80);
  triangles.forEach((t, n) => {
    t.forEach((k, corner) => vertices[k].forEach((c, axis) => buffer.writeFloatLE(c, 84 + 50 * n + 12 + 12 * corner + 4 * axis)));
  });
  return buffer;
}

function cliVoxelize(input, resolution, output) {
  return runCli(['voxelize', '--input', input, '--resolution', String(resolution), '--output', output]);
}

test('torus: the module returns the document the CLI writes, and the .puz has the same labels', () => {
  const file = writeTemp('torus.obj', objText(torus()));
  const jsonFile = path.join(tmp, 'torus.json');
  const cli = cliVoxelize(file, 24, jsonFile);
  assert.equal(cli.stderr, '');
  assert.equal(cli.status, 0);
  const native = JSON.parse(fs.readFileSync(jsonFile, 'utf8'));
  const wasm = core.voxelize(fs.readFileSync(file), { resolution: 24, source: file });
  assert.deepEqual(wasm, native);
  assert.equal(wasm.name, 'torus');
  assert.equal(wasm.kind, 'voxel');
  const [nx, ny, nz] = wasm.voxel.size;
  assert.equal(nx, 24);
  assert.equal(wasm.parts.length, 1);
  assert.equal(wasm.parts[0].voxelCount, wasm.voxel.labels.filter((v) => v === 1).length);
  assert.match(cli.stdout, new RegExp(`-> grid ${nx} x ${ny} x ${nz}, ${wasm.parts[0].voxelCount} voxels \\(one part\\); wrote `));
  // The hole: the column through the middle of the x-z plane is empty.
  for (let y = 0; y < ny; y++) assert.equal(wasm.voxel.labels[nx / 2 + nx * (y + ny * Math.floor(nz / 2))], 0);

  const puzFile = path.join(tmp, 'torus.puz');
  assert.equal(cliVoxelize(file, 24, puzFile).status, 0);
  const fromPuz = core.parseDocument(fs.readFileSync(puzFile, 'utf8'), { source: puzFile });
  assert.deepEqual(fromPuz.voxel, wasm.voxel);
});

test('octahedron file: 80 voxels at resolution 8 from every input type, OBJ and STL alike', async () => {
  const desia = await createDesia();
  const bytes = fs.readFileSync(octahedronFile);
  const reference = await desia.voxelize(bytes, { resolution: 8, source: 'octahedron.obj' });
  assert.deepEqual(reference.voxel.size, [8, 8, 8]);
  assert.equal(reference.parts[0].voxelCount, 80);
  const copy = new Uint8Array(bytes);
  for (const input of [copy, copy.buffer, new DataView(copy.buffer), bytes.toString('utf8')]) {
    assert.deepEqual(await desia.voxelize(input, { resolution: 8, source: 'octahedron.obj' }), reference);
  }
  const mesh = {
    vertices: [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
    triangles: [[0, 2, 4], [0, 5, 2], [0, 4, 3], [0, 3, 5], [1, 4, 2], [1, 2, 5], [1, 3, 4], [1, 5, 3]],
  };
  const stl = binaryStl(mesh);
  // A binary STL whose header starts with "solid", with no file name to go by.
  assert.deepEqual((await desia.voxelize(stl, { resolution: 8 })).voxel, reference.voxel);
  const stlFile = writeTemp('octahedron.stl', stl);
  const jsonFile = path.join(tmp, 'octahedron-stl.json');
  assert.equal(cliVoxelize(stlFile, 8, jsonFile).status, 0);
  assert.deepEqual(JSON.parse(fs.readFileSync(jsonFile, 'utf8')).voxel, reference.voxel);
  // The default resolution is 32 in both.
  const defaultFile = path.join(tmp, 'octahedron-32.json');
  assert.equal(runCli(['voxelize', '--input', octahedronFile, `--output=${defaultFile}`]).status, 0);
  const defaults = JSON.parse(fs.readFileSync(defaultFile, 'utf8'));
  assert.deepEqual(defaults.voxel.size, [32, 32, 32]);
  assert.deepEqual(core.voxelize(bytes, { source: octahedronFile }), defaults);
});

test('bad meshes reject with a DesiaError carrying the message the CLI prints', () => {
  const lines = fs.readFileSync(octahedronFile, 'utf8').split('\n');
  const cases = [
    { name: 'open.obj', text: lines.filter((line) => line !== 'f 2 6 4').join('\n'), code: 'bad-input', resolution: 8,
      message: /: the mesh is not closed: edge between vertices 2 and 4 belongs to 1 triangle \(a closed solid needs 2\)$/ },
    { name: 'index.obj', text: `${lines.join('\n')}f 1 2 900\n`, code: 'bad-input', resolution: 8,
      message: /index\.obj:18: face index 900 out of range \(mesh has 6 vertices\)$/ },
    { name: 'nan.obj', text: 'v 0 0 x\n', code: 'bad-input', resolution: 8, message: /nan\.obj:1: vertex coordinate 'x' is not a number$/ },
    { name: 'big.obj', text: lines.join('\n'), code: 'too-large', resolution: 2000, message: /resolution 2000 is out of range/ },
    { name: 'low.obj', text: lines.join('\n'), code: 'bad-input', resolution: 2, message: /no voxel centre lies inside the mesh at resolution 2/ },
  ];
  for (const { name, text, code, resolution, message } of cases) {
    const file = writeTemp(name, text);
    const cli = cliVoxelize(file, resolution, path.join(tmp, 'never.puz'));
    assert.equal(cli.status, 2, name);
    assert.equal(cli.stdout, '', name);
    assert.match(cli.stderr, /^desia: error: .*\n$/, name);
    const cliMessage = cli.stderr.slice('desia: error: '.length, -1);
    assert.match(cliMessage, message, name);
    assert.throws(() => core.voxelize(fs.readFileSync(file), { resolution, source: file }), (error) => {
      assert.ok(error instanceof DesiaError, name);
      assert.equal(error.code, code, name);
      assert.equal(error.message, cliMessage, name);
      return true;
    });
  }
  assert.equal(fs.existsSync(path.join(tmp, 'never.puz')), false);
  assert.throws(() => core.voxelize(42), (error) => error instanceof DesiaError && error.code === 'bad-input' && /must be a Uint8Array/.test(error.message));
  assert.throws(() => core.voxelize('v 0 0 0', { resolution: 2.5 }), /resolution must be an integer/);
  // The module stays usable after errors.
  assert.equal(core.voxelize(fs.readFileSync(octahedronFile), { resolution: 8 }).parts[0].voxelCount, 80);
});

test('desia voxelize usage errors exit 2 with the voxelize usage line', () => {
  for (const [args, message] of [
    [['--input', octahedronFile], /needs --output/],
    [['--output', 'x.puz'], /needs --input/],
    [['--input', octahedronFile, '--output', 'x.txt'], /must name a \.puz or \.json file/],
    [['--input', octahedronFile, '--output', 'x.puz', '--resolution', 'ten'], /needs a positive integer, got 'ten'/],
    [['--input', octahedronFile, '--output', 'x.puz', '--bogus'], /unknown option --bogus/],
    [['--input'], /--input needs a value/],
  ]) {
    const result = runCli(['voxelize', ...args]);
    assert.equal(result.status, 2, args.join(' '));
    assert.match(result.stderr, message);
    assert.match(result.stderr, /usage: desia voxelize --input MESH/);
  }
  const missing = runCli(['voxelize', '--input', path.join(tmp, 'missing.obj'), '--output', path.join(tmp, 'm.puz')]);
  assert.equal(missing.status, 2);
  assert.match(missing.stderr, /missing\.obj: cannot open the file/);
  assert.match(runCli(['--help']).stdout, /desia voxelize --input MESH\.obj\|\.stl/);
});
