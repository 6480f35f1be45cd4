// SPDX-License-Identifier: GPL-3.0-or-later
// designVoxel's `liveSurfaces` (issue 28, item 8; the playground draws live design with it): a
// snapshot delivered through the package's worker also carries the part surfaces of the shape
// with its labels, the same triangles partSurfaces gives for that assembly, in one worker and in a
// portfolio of two; the option changes nothing else (same puzzle bytes), and a wrong value is a
// DesiaError.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { after, test } from 'node:test';

import { DesiaError, createDesia, loadDesiaModule } from '../../wasm/index.js';
import { referenceDir } from './support.mjs';

const core = await loadDesiaModule();
const bunnyShape = fs.readFileSync(path.join(referenceDir, 'input_puz/bunny_origin.puz'), 'utf8');
const shapeDocument = core.parseDocument(bunnyShape, { source: 'bunny_origin.puz' });
const desia = await createDesia();
after(() => desia.terminate());

/** The snapshot's surfaces are partSurfaces of the shape with the snapshot's labels. */
function assertSurfacesOfSnapshot(snapshot) {
  assert.ok(Array.isArray(snapshot.surfaces), `snapshot at depth ${snapshot.depth} has surfaces`);
  const document = { ...shapeDocument, voxel: { ...shapeDocument.voxel, labels: Array.from(snapshot.labels) } };
  const expected = core.partSurfaces(document, { source: 'node' });
  assert.deepEqual(snapshot.surfaces.map((surface) => surface.partId), expected.map((surface) => surface.partId));
  assert.equal(Math.max(...snapshot.surfaces.map((surface) => surface.partId)), snapshot.depth + 1, 'parts 1..depth and the remainder');
  snapshot.surfaces.forEach((surface, k) => {
    assert.ok(surface.positions instanceof Float32Array && surface.normals instanceof Float32Array);
    assert.deepEqual(surface.positions, expected[k].positions, `part ${surface.partId}`);
    assert.deepEqual(surface.normals, expected[k].normals, `part ${surface.partId}`);
  });
}

test('liveSurfaces: every snapshot through the worker carries its part surfaces; the puzzle is unchanged', async () => {
  const options = { parts: 60, seed: 1, source: 'bunny_origin.puz' };
  const snapshots = [];
  const live = await desia.designVoxel(bunnyShape, { ...options, liveSurfaces: true, onProgress: (progress) => {
    if (progress.snapshot) snapshots.push(progress.snapshot);
  } });
  assert.equal(live.status, 'success');
  assert.ok(snapshots.length >= 2, `${snapshots.length} snapshots`);
  for (const snapshot of snapshots) assertSurfacesOfSnapshot(snapshot);
  const plain = await desia.designVoxel(bunnyShape, options);
  assert.equal(live.puz, plain.puz, 'the same puzzle with and without live surfaces');
});

test('liveSurfaces in a portfolio of two workers: the deepest search\'s snapshots carry surfaces', async () => {
  let withSurfaces = 0;
  const result = await desia.designVoxel(bunnyShape, { parts: 60, seed: 1, jobs: 2, liveSurfaces: true, source: 'bunny_origin.puz',
    onProgress: (progress) => {
      if (!progress.snapshot) return;
      assertSurfacesOfSnapshot(progress.snapshot);
      withSurfaces += 1;
    } });
  assert.equal(result.status, 'success');
  assert.ok(withSurfaces >= 1);
});

test('liveSurfaces must be true or false', async () => {
  await assert.rejects(desia.designVoxel(bunnyShape, { parts: 60, liveSurfaces: 'yes' }), (error) => error instanceof DesiaError
    && error.code === 'bad-input' && /liveSurfaces must be true or false/.test(error.message));
});
