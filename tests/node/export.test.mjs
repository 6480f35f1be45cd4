// SPDX-License-Identifier: GPL-3.0-or-later
// `desia export` and the module's exportAssembly binding: files parse back (node's own zlib
// decompresses the .xmpuzzle), the pieces rebuild the .puz labels, meshes enclose the parts'
// voxels, the WebAssembly bytes equal the CLI's, and bad requests exit 2 with a clear message.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { createRequire } from 'node:module';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';
import zlib from 'node:zlib';

import { referenceDir, requireBuilt, root, runCli } from './support.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-export-'));
const k9File = path.join(referenceDir, 'result_puz/Cube_4x4x4_K9.puz');
const puzzles = ['Cube_4x4x4_K9.puz', 'Cube_Hollow_4x4x4_K7', 'cube_5x5x5_K16.puz', 'cartoon_dog.puz', 'bunny_15x14x11_K80.puz']
  .map((name) => path.join(referenceDir, 'result_puz', name));

// The raw embind module (the package facade for exportAssembly is not there yet). Emscripten
// 3.1.6's ES6 output wants CommonJS globals in node and the wasm bytes passed in (toolchain.md #3, #6).
async function loadRawModule() {
  const wasmFile = path.join(root, 'dist/desia_wasm.wasm');
  requireBuilt(wasmFile, 'scripts/build.sh wasm');
  globalThis.require ??= createRequire(import.meta.url);
  globalThis.__dirname ??= path.join(root, 'dist');
  const { default: createDesiaModule } = await import('../../dist/desia_wasm.js');
  return createDesiaModule({ wasmBinary: fs.readFileSync(wasmFile) });
}
const wasm = await loadRawModule();

/** Labels of a .puz file: { size: [nx, ny, nz], labels: [...] } in index order x + nx*(y + ny*z). */
function readPuz(file) {
  const values = fs.readFileSync(file, 'utf8').trim().split(/\s+/).map(Number);
  return { size: values.slice(0, 3), labels: values.slice(3) };
}

function exportWithCli(file, format, extra = []) {
  const output = path.join(tmp, `${path.basename(file)}.${format}${extra.join('')}`);
  const result = runCli(['export', file, '--format', format, ...extra, '--output', output]);
  assert.equal(result.status, 0, result.stderr);
  assert.equal(result.stderr, '');
  return { bytes: fs.readFileSync(output), stdout: result.stdout, output };
}

// ---- mesh reading -------------------------------------------------------------------------------

function binaryStlTriangles(bytes) {
  const count = bytes.readUInt32LE(80);
  assert.equal(bytes.length, 84 + 50 * count);
  const triangles = [];
  for (let t = 0; t < count; t++) {
    const at = 84 + 50 * t;
    const f = (k) => bytes.readFloatLE(at + 4 * k);
    triangles.push({ normal: [f(0), f(1), f(2)], vertices: [[f(3), f(4), f(5)], [f(6), f(7), f(8)], [f(9), f(10), f(11)]] });
    assert.equal(bytes.readUInt16LE(at + 48), 0);
  }
  return triangles;
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

// Divergence theorem over outward triangles [[a, b, c], ...].
function volume(triangles) {
  return triangles.reduce((sum, [a, b, c]) => sum + dot(a, cross(b, c)), 0) / 6;
}

// Closed by positions (as a slicer sees an STL): every edge is walked as often each way.
function unbalancedEdges(triangles) {
  const balance = new Map();
  for (const corners of triangles) {
    for (let k = 0; k < 3; k++) {
      const a = corners[k].join(' '), b = corners[(k + 1) % 3].join(' ');
      const key = a < b ? `${a}|${b}` : `${b}|${a}`;
      balance.set(key, (balance.get(key) ?? 0) + (a < b ? 1 : -1));
    }
  }
  return [...balance].filter(([, difference]) => difference !== 0).map(([key]) => key);
}

// OBJ objects by name: { part1: { triangles: [[a, b, c] positions], edges: Map('i j' -> uses) } }.
function readObj(text) {
  const vertices = [];
  const objects = {};
  let current = null;
  for (const line of text.split('\n')) {
    const [kind, ...fields] = line.trim().split(/\s+/);
    if (kind === 'o') {
      current = { triangles: [], directedEdges: new Map() };
      objects[fields[0]] = current;
    } else if (kind === 'v') {
      vertices.push(fields.map(Number));
    } else if (kind === 'f') {
      assert.equal(fields.length, 3, line);
      const indices = fields.map(Number);
      current.triangles.push(indices.map((i) => vertices[i - 1]));
      for (let k = 0; k < 3; k++) {
        const key = `${indices[k]} ${indices[(k + 1) % 3]}`;
        current.directedEdges.set(key, (current.directedEdges.get(key) ?? 0) + 1);
      }
    }
  }
  return objects;
}

// ---- xmpuzzle reading -----------------------------------------------------------------------------

function readXmpuzzle(bytes) {
  const xml = zlib.gunzipSync(bytes).toString('utf8');
  const shapes = [...xml.matchAll(/<voxel x="(\d+)" y="(\d+)" z="(\d+)" name="([^"]*)" type="0">([^<]*)<\/voxel>/g)]
    .map((m) => ({ size: [Number(m[1]), Number(m[2]), Number(m[3])], name: m[4], voxels: m[5] }));
  const offsets = new Map([...xml.matchAll(/^part (\d+): (\d+) (\d+) (\d+)$/gm)]
    .map((m) => [Number(m[1]), [Number(m[2]), Number(m[3]), Number(m[4])]]));
  return { xml, shapes, offsets };
}

// ---- tests ----------------------------------------------------------------------------------------

for (const file of puzzles) {
  test(`${path.basename(file)}: the xmpuzzle gunzips with node's zlib and its pieces rebuild the labels`, () => {
    const { size: [nx, ny, nz], labels } = readPuz(file);
    const parts = Math.max(...labels);
    const { bytes, stdout } = exportWithCli(file, 'xmpuzzle');
    assert.match(stdout, new RegExp(`: all ${parts} parts as xmpuzzle, ${bytes.length} bytes; wrote `));
    const { xml, shapes, offsets } = readXmpuzzle(bytes);
    assert.match(xml, /^<\?xml version="1.0"\?>\n<puzzle version="2">\n <gridType type="0"\/>\n/);
    assert.equal(shapes.length, parts + 1);
    // Shape 0: the assembled puzzle in the full grid.
    assert.deepEqual(shapes[0].size, [nx, ny, nz]);
    assert.equal(shapes[0].voxels, labels.map((label) => (label > 0 ? '#' : '_')).join(''));
    // Shapes 1..N: the parts, cropped, placed back at the offsets listed in the comment.
    const rebuilt = new Array(labels.length).fill(0);
    for (let id = 1; id <= parts; id++) {
      const { size: [px, py, pz], voxels, name } = shapes[id];
      assert.equal(name, `part ${id}`);
      assert.equal(voxels.length, px * py * pz);
      assert.match(voxels, /^[#_]+$/);
      const [ox, oy, oz] = offsets.get(id);
      for (let i = 0; i < voxels.length; i++) {
        if (voxels[i] !== '#') continue;
        const x = i % px, y = Math.floor(i / px) % py, z = Math.floor(i / (px * py));
        const at = x + ox + nx * (y + oy + ny * (z + oz));
        assert.equal(rebuilt[at], 0, 'two pieces claim one voxel');
        rebuilt[at] = id;
      }
    }
    assert.deepEqual(rebuilt, labels);
    const problemShapes = Array.from({ length: parts }, (_, k) => `    <shape id="${k + 1}" count="1"/>\n`).join('');
    assert.ok(xml.includes(`<problem name="desia" state="3" assemblies="1" solutions="1" time="0">\n   <shapes>\n${problemShapes}   </shapes>\n   <result id="0"/>`));
    // desia's assembly as BurrTools' saved solution: the pieces at their crop offsets, and one
    // separation per removal (the last two pieces come apart in the last one).
    const placements = /<assembly>([^<]*)<\/assembly>/.exec(xml)[1].split(' ').map(Number);
    assert.deepEqual(placements, Array.from({ length: parts }, (_, k) => [...offsets.get(k + 1), 0]).flat());
    assert.equal(xml.match(/<separation[ >]/g).length, parts - 1);
  });
}

test('binary STL of all parts: header, count, axis normals matching the winding, closed, volume = voxels', () => {
  const { labels } = readPuz(k9File);
  const { bytes } = exportWithCli(k9File, 'stl', ['--voxel-size', '2']);
  const header = bytes.subarray(0, 80).toString('latin1');
  assert.ok(!header.startsWith('solid'));
  assert.match(header, /^desia voxel export, all 9 parts, voxel size 2 +$/);
  const triangles = binaryStlTriangles(bytes);
  for (const { normal, vertices: [a, b, c] } of triangles) {
    assert.equal(Math.abs(normal[0]) + Math.abs(normal[1]) + Math.abs(normal[2]), 1);
    assert.ok(dot(normal, cross(sub(b, a), sub(c, a))) > 0);
  }
  const corners = triangles.map((t) => t.vertices);
  assert.deepEqual(unbalancedEdges(corners), []);
  assert.equal(volume(corners), labels.filter((label) => label > 0).length * 8);
});

test('one part as binary STL encloses exactly that part; ASCII STL has the same triangles', () => {
  const file = path.join(referenceDir, 'result_puz/cube_5x5x5_K16.puz');
  const { labels } = readPuz(file);
  const binary = binaryStlTriangles(exportWithCli(file, 'stl', ['--part', '11']).bytes).map((t) => t.vertices);
  assert.deepEqual(unbalancedEdges(binary), []);
  assert.equal(volume(binary), labels.filter((label) => label === 11).length);
  const ascii = exportWithCli(file, 'stl-ascii', ['--part', '11']).bytes.toString('utf8');
  assert.match(ascii, /^solid part11\n/);
  assert.match(ascii, /endsolid part11\n$/);
  const asciiCorners = [];
  let corner = [];
  for (const m of ascii.matchAll(/^ +vertex (\S+) (\S+) (\S+)$/gm)) {
    corner.push([Number(m[1]), Number(m[2]), Number(m[3])]);
    if (corner.length === 3) asciiCorners.push(corner), (corner = []);
  }
  assert.deepEqual(asciiCorners, binary);
});

test('OBJ: one object per part, each a closed 2-manifold (by vertex index) with the part volume', () => {
  const file = path.join(referenceDir, 'result_puz/bunny_15x14x11_K80.puz');
  const { labels } = readPuz(file);
  const objects = readObj(exportWithCli(file, 'obj').bytes.toString('utf8'));
  assert.deepEqual(Object.keys(objects), Array.from({ length: 80 }, (_, k) => `part${k + 1}`));
  for (const [name, { triangles, directedEdges }] of Object.entries(objects)) {
    for (const [key, uses] of directedEdges) {
      const [a, b] = key.split(' ');
      assert.equal(uses, 1, `${name}: edge ${key}`);
      assert.equal(directedEdges.get(`${b} ${a}`), 1, `${name}: edge ${key} has no opposite`);
    }
    const id = Number(name.slice(4));
    assert.equal(volume(triangles), labels.filter((label) => label === id).length, name);
  }
});

test('the WebAssembly binding gives the same bytes as the CLI, as a Uint8Array', () => {
  for (const file of [k9File, path.join(referenceDir, 'result_puz/cartoon_dog.puz')]) {
    const text = fs.readFileSync(file, 'utf8');
    const cases = [['stl', []], ['stl-ascii', []], ['obj', []], ['xmpuzzle', []],
      ['obj', ['--voxel-size', '0.1']], ['stl-ascii', ['--part', '3', '--voxel-size', '0.37']], ['stl', ['--part', '2']],
      ['stl', ['--voxel-size', '10', '--clearance', '0.2']], ['stl-zip', ['--voxel-size', '10', '--clearance', '0.2']],
      ['build-plate-stl', ['--voxel-size', '10', '--clearance', '0.15', '--spacing', '3']], ['build-plate-stl', ['--part', '4']]];
    for (const [format, extra] of cases) {
      const flag = (name, fallback) => (extra.includes(name) ? Number(extra[extra.indexOf(name) + 1]) : fallback);
      const [part, voxelSize, clearance, spacing] = [flag('--part', 0), flag('--voxel-size', 1), flag('--clearance', 0), flag('--spacing', NaN)];
      const bytes = wasm.exportAssembly(text, format, part, voxelSize, clearance, spacing, file);
      assert.ok(bytes instanceof Uint8Array, 'a Uint8Array');
      assert.equal(bytes.byteOffset, 0, 'a copy that owns its buffer, not a view of the module heap');
      assert.equal(bytes.buffer.byteLength, bytes.length, 'a copy that owns its buffer, not a view of the module heap');
      assert.ok(Buffer.from(bytes).equals(exportWithCli(file, format, extra).bytes), `${path.basename(file)} ${format} ${extra.join(' ')}`);
    }
  }
});

const badRequests = [
  ['an unknown format', [k9File, '--format', 'step'],
    /^desia: error: unknown export format 'step' \(expected one of: stl, stl-ascii, obj, xmpuzzle, stl-zip, build-plate-stl, svg, dxf, fpuz, csv, puz, voxel-json, pieces-obj, joint-pieces-stl; svg and dxf are plate cut sheets, fpuz to joint-pieces-stl frames\)$/m,
    ['step', 0, 1], /^unknown export format 'step'/],
  ['a part that does not exist', [k9File, '--format', 'stl', '--part', '12'],
    /Cube_4x4x4_K9\.puz: part 12 does not exist: the assembly has parts 1 to 9 \(0 = all parts\)$/m,
    ['stl', 12, 1], /part 12 does not exist/],
  ['one part of an xmpuzzle', [k9File, '--format', 'xmpuzzle', '--part', '2'],
    /a BurrTools \.xmpuzzle holds the whole puzzle, so it cannot hold only part 2/, ['xmpuzzle', 2, 1], /holds the whole puzzle/],
  ['a zero voxel size', [k9File, '--format', 'obj', '--voxel-size', '0'],
    /the voxel size must be a number from 0\.000001 to 1000000, got 0$/m, ['obj', 0, 0], /the voxel size must be a number/],
  ['a clearance of half a voxel', [k9File, '--format', 'stl-zip', '--voxel-size', '10', '--clearance', '5'],
    /Cube_4x4x4_K9\.puz: the clearance must be at least 0 and less than half the voxel size \(5\), got 5$/m,
    ['stl-zip', 0, 10, 5], /^k9\.puz: the clearance must be at least 0 and less than half the voxel size \(5\), got 5$/],
  ['a negative build plate spacing', [k9File, '--format', 'build-plate-stl', '--spacing', '-2'],
    /--spacing -2 is out of range \(0 to 1000\)$/m, ['build-plate-stl', 0, 1, 0, -2], /the spacing must be a number from 0 to 1000000, got -2$/],
  ['a contact-graph document', [path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json'), '--format', 'stl'],
    /figure4_two_parts_move_at_once\.json: export needs a voxel assembly, this is a contacts document$/m, null, null],
];

for (const [name, args, cliMessage, bindingArgs, bindingMessage] of badRequests) {
  test(`${name}: the CLI exits 2 with a clear message, writes nothing; the binding throws the same`, () => {
    const output = path.join(tmp, `bad-${name.replace(/\W+/g, '-')}.out`);
    const result = runCli(['export', ...args, '--output', output]);
    assert.equal(result.status, 2, result.stderr);
    assert.equal(result.stdout, '');
    assert.match(result.stderr, cliMessage);
    assert.ok(!fs.existsSync(output));
    if (bindingArgs) {
      const [format, part, voxelSize] = bindingArgs;
      const [clearance = 0, spacing = NaN] = bindingArgs.slice(3);
      assert.throws(() => wasm.exportAssembly(fs.readFileSync(k9File, 'utf8'), format, part, voxelSize, clearance, spacing, 'k9.puz'), (error) => {
        assert.ok(error instanceof Error);
        assert.equal(error.code, 'bad-input');
        assert.match(error.message, bindingMessage);
        return true;
      });
    }
  });
}

test('non-voxel text through the binding: a bad-input Error naming the source', () => {
  const text = fs.readFileSync(path.join(root, 'examples/contacts/figure4_two_parts_move_at_once.json'), 'utf8');
  assert.throws(() => wasm.exportAssembly(text, 'obj', 0, 1, 0, NaN, 'fig4.json'),
    { code: 'bad-input', message: 'fig4.json: export needs a voxel assembly, this is a contacts document' });
});

test('usage errors: missing flags and bad numbers exit 2 with the export usage line', () => {
  for (const [args, message] of [
    [[k9File, '--output', path.join(tmp, 'x.stl')], /export needs --format stl\|stl-ascii\|obj\|xmpuzzle/],
    [[k9File, '--format', 'stl'], /export needs --output OUT/],
    [['--format', 'stl', '--output', path.join(tmp, 'x.stl')], /export needs a FILE/],
    [[k9File, '--format', 'stl', '--part', 'two', '--output', path.join(tmp, 'x.stl')], /--part needs a part number \(0 = all parts\), got 'two'/],
    [[k9File, '--format', 'stl', '--voxel-size', '1mm', '--output', path.join(tmp, 'x.stl')], /--voxel-size needs a number, got '1mm'/],
    [[k9File, '--format', 'stl', '--scale', '2', '--output', path.join(tmp, 'x.stl')], /unknown option --scale/],
  ]) {
    const result = runCli(['export', ...args]);
    assert.equal(result.status, 2, args.join(' '));
    assert.match(result.stderr, message);
    assert.match(result.stderr, /^usage: desia export FILE --format/m);
  }
  assert.match(runCli(['--help']).stdout, /desia export FILE --format stl\|stl-ascii\|obj\|xmpuzzle/);
});
