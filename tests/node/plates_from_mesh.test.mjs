// SPDX-License-Identifier: GPL-3.0-or-later
// `desia plates-from-mesh`: a closed low-poly mesh to a plate design of mitred plates. The
// sculptures of examples/plate/ come out as committed (make_sculptures.py wrote them with this
// command), an STL works as the OBJ does, the design is input design plate accepts, and bad
// meshes and thicknesses exit 2 naming what is wrong.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { test } from 'node:test';

import { root, runCli } from './support.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'desia-plates-from-mesh-'));
const examples = path.join(root, 'examples/plate');

for (const [name, thickness, faces, edges] of [['cube', '12', 6, 12], ['icosahedron', '6', 20, 30], ['dodecahedron', '6', 12, 30], ['lizard', '6', 38, 90]]) {
  test(`${name}: one mitred plate per face, one contact per edge, as committed`, () => {
    const output = path.join(tmp, `${name}.json`);
    const result = runCli(['plates-from-mesh', '--input', path.join(examples, `${name}.obj`), '--thickness', thickness, '--output', output]);
    assert.equal(result.status, 0, result.stderr);
    assert.match(result.stdout, new RegExp(`-> ${faces} faces, ${edges} edges\\n${faces} mitred plates of ${thickness} mm, ${edges} contacts \\(one per edge\\)\\n`));
    const written = JSON.parse(fs.readFileSync(output, 'utf8'));
    assert.equal(written.kind, 'plate');
    assert.equal(written.plates.length, faces);
    assert.deepEqual(written.plates.map((plate) => plate.id), Array.from({ length: faces }, (_, k) => k + 1));
    assert.deepEqual(written, JSON.parse(fs.readFileSync(path.join(examples, `${name}.json`), 'utf8')));
  });
}

test('the design is input for design plate (a plan, or exit 1 when none is found; never bad input)', () => {
  const design = runCli(['design', 'plate', '--input', path.join(examples, 'dodecahedron.json'), '--output', path.join(tmp, 'plan.json'), '--quiet']);
  assert.ok(design.status === 0 || design.status === 1, `${design.status}: ${design.stderr}`);
});

test('an STL gives the same plates as the OBJ', () => {
  // The cube's triangles as ASCII STL (every triangle with its own vertex copies).
  const obj = fs.readFileSync(path.join(examples, 'cube.obj'), 'utf8').split('\n');
  const vertices = obj.filter((line) => line.startsWith('v ')).map((line) => line.slice(2));
  let stl = 'solid cube\n';
  for (const line of obj.filter((l) => l.startsWith('f '))) {
    const corners = line.slice(2).split(' ').map(Number);
    for (let k = 1; k + 1 < corners.length; k++) {
      stl += ' facet normal 0 0 0\n  outer loop\n';
      for (const c of [corners[0], corners[k], corners[k + 1]]) stl += `   vertex ${vertices[c - 1]}\n`;
      stl += '  endloop\n endfacet\n';
    }
  }
  stl += 'endsolid cube\n';
  fs.writeFileSync(path.join(tmp, 'cube.stl'), stl);
  const result = runCli(['plates-from-mesh', '--input', path.join(tmp, 'cube.stl'), '--thickness', '12', '--output', path.join(tmp, 'cube-stl.json')]);
  assert.equal(result.status, 0, result.stderr);
  const fromStl = JSON.parse(fs.readFileSync(path.join(tmp, 'cube-stl.json'), 'utf8'));
  const fromObj = JSON.parse(fs.readFileSync(path.join(examples, 'cube.json'), 'utf8'));
  // STL numbers the vertices by first appearance, so a plate's loops may start at another corner.
  const canonical = (plates) => plates.map((plate) => {
    const [outer, inner] = plate.faces;
    let start = 0;
    for (let k = 1; k < outer.length; k++) if (outer[k].join() < outer[start].join()) start = k;
    const turn = (loop) => [...loop.slice(start), ...loop.slice(0, start)];
    return { id: plate.id, faces: [turn(outer), turn(inner)] };
  });
  assert.deepEqual(canonical(fromStl.plates), canonical(fromObj.plates));
});

const cubeObj = () => fs.readFileSync(path.join(examples, 'cube.obj'), 'utf8');
const refusals = [
  ['zero thickness', cubeObj, ['--thickness', '0'], /cube\.obj: the thickness must be a positive number of millimetres, found 0/],
  ['thickness too large', cubeObj, ['--thickness', '150'], /the thickness 150 mm is too large for face 1 \(around \(-100, 0, 0\)\): .*; this face allows at most about 99\.97 mm: give a smaller thickness/],
  ['not a number', cubeObj, ['--thickness', '5mm'], /--thickness expects a number, got '5mm'/],
  ['open mesh', () => cubeObj().replace(/^f .*\n/m, ''), ['--thickness', '5'], /the mesh is not closed: edge between vertices \d+ and \d+ belongs to 1 triangle/],
  ['inconsistent orientation', () => cubeObj().replace(/^f (\d+) (\d+) (\d+) (\d+)$/m, 'f $4 $3 $2 $1'), ['--thickness', '5'], /the mesh is not consistently oriented: triangles \d+ and \d+ both run from vertex/],
  ['non-planar face', () => cubeObj().replace(/^v 100\.000000 100\.000000 100\.000000$/m, 'v 100 100 101'), ['--thickness', '5'], /face \d+ \(around .*\) is not planar: its vertices lie up to 0\.25 mm off one plane/],
];

for (const [name, content, options, message] of refusals) {
  test(`refused (${name}): exit 2 naming it`, () => {
    const input = path.join(tmp, 'cube.obj');
    fs.writeFileSync(input, content());
    const result = runCli(['plates-from-mesh', '--input', input, ...options, '--output', path.join(tmp, 'refused.json')]);
    assert.equal(result.status, 2, result.stdout);
    assert.match(result.stderr, message);
    assert.equal(fs.existsSync(path.join(tmp, 'refused.json')), false);
  });
}

test('usage: --thickness and --output are required', () => {
  const missing = runCli(['plates-from-mesh', '--input', path.join(examples, 'cube.obj'), '--output', path.join(tmp, 'x.json')]);
  assert.equal(missing.status, 2);
  assert.match(missing.stderr, /plates-from-mesh needs --thickness T/);
  const noJson = runCli(['plates-from-mesh', '--input', path.join(examples, 'cube.obj'), '--thickness', '5', '--output', path.join(tmp, 'x.obj')]);
  assert.equal(noJson.status, 2);
  assert.match(noJson.stderr, /needs --output PLATES\.json/);
});
