// SPDX-License-Identifier: GPL-3.0-or-later
// The core's layers (docs/architecture.md), checked on every #include: a file may include headers
// of its own layer and of the layers below it, never above. model (core/model, core/graph) <
// analysis, search < the kinds (core/voxel, core/plate, core/frame, core/mesh; frames are built on voxels,
// and meshes on a lattice are planned as voxels) <
// io < cli. A layer's private headers ("voxel/x.h") are for its own folder, except the few listed
// below that a layer offers the ones above it. A new public header gets its layer here.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';

import { root } from './support.mjs';

const RANK = { model: 0, analysis: 1, search: 1, voxel: 2, plate: 2, frame: 2, mesh: 2, io: 3, cli: 4 };
const FOLDER_LAYER = { model: 'model', graph: 'model', analysis: 'analysis', search: 'search', voxel: 'voxel',
  plate: 'plate', frame: 'frame', mesh: 'mesh', io: 'io', cli: 'cli' };

// Public headers (core/include/desia) by the layer that implements them.
const HEADER_LAYER = {
  'model.h': 'model', 'error.h': 'model', 'version.h': 'model', 'tolerances.h': 'model',
  'analysis.h': 'analysis', 'search.h': 'search',
  'voxel.h': 'voxel', 'plate.h': 'plate', 'frame.h': 'frame', 'mesh.h': 'mesh',
  'document.h': 'io', 'formats.h': 'io', 'design_io.h': 'io', 'export.h': 'io', 'desia.h': 'io',
};

// Private headers a layer offers the layers above it: vectors for every layer, the part-motion
// helpers, the construction search and the session path for the designers, a plate's plane for cut sheets.
const SHARED_PRIVATE = new Set(['analysis/vec3.h', 'analysis/part_motion.h', 'search/construction_search.h',
  'search/restarts.h', 'search/session_path.h', 'search/level_notation.h', 'plate/plane_frame.h']);

function layerOfInclude(spelled, includingFolder) {
  if (spelled.startsWith('desia/')) return HEADER_LAYER[spelled.slice('desia/'.length)];
  const folder = spelled.split('/')[0];
  if (folder in FOLDER_LAYER && spelled.includes('/')) return FOLDER_LAYER[folder];
  return FOLDER_LAYER[includingFolder];  // a header beside the file
}

function* coreFiles(folder) {
  for (const entry of fs.readdirSync(folder, { withFileTypes: true })) {
    const full = path.join(folder, entry.name);
    if (entry.isDirectory()) yield* coreFiles(full);
    else if (/\.(cpp|h)$/.test(entry.name)) yield full;
  }
}

test('every public header has a layer', () => {
  const headers = fs.readdirSync(path.join(root, 'core/include/desia'));
  assert.deepEqual(headers.filter((h) => !(h in HEADER_LAYER)), []);
});

// The public API is what the CLI, the bindings and the tests need: one header per layer or topic
// and the umbrella desia.h, which includes every other one (issue 25: about a dozen, not 38).
test('the public headers are few, and the umbrella includes them all', () => {
  const headers = fs.readdirSync(path.join(root, 'core/include/desia')).sort();
  assert.ok(headers.length <= 16, `${headers.length} public headers: ${headers.join(', ')}`);
  const umbrella = fs.readFileSync(path.join(root, 'core/include/desia/desia.h'), 'utf8');
  const included = [...umbrella.matchAll(/#include "desia\/([^"]+)"/g)].map((m) => m[1]).sort();
  assert.deepEqual(included, headers.filter((h) => h !== 'desia.h'));
});

test('no file includes a header of a layer above its own, or another folder\'s private header', () => {
  const problems = [];
  for (const file of coreFiles(path.join(root, 'core'))) {
    const relative = path.relative(path.join(root, 'core'), file);
    const top = relative.split(path.sep)[0];
    const layer = top === 'include' ? HEADER_LAYER[path.basename(file)] : FOLDER_LAYER[top];
    if (!layer) continue;
    const lines = fs.readFileSync(file, 'utf8').split('\n');
    lines.forEach((line, index) => {
      const match = /^#include "([^"]+)"/.exec(line);
      if (!match) return;
      const spelled = match[1];
      const target = layerOfInclude(spelled, top);
      const where = `core/${relative}:${index + 1}: ${spelled}`;
      if (!target) return problems.push(`${where} has no layer`);
      const frameOnVoxels = (layer === 'frame' || layer === 'mesh') && target === 'voxel';
      if (RANK[target] > RANK[layer] || (RANK[target] === RANK[layer] && target !== layer && !frameOnVoxels)) {
        problems.push(`${where}: ${layer} must not include ${target}`);
      }
      const folder = spelled.split('/')[0];
      const foreignPrivate = !spelled.startsWith('desia/') && spelled.includes('/') && folder in FOLDER_LAYER &&
        FOLDER_LAYER[folder] !== layer && !SHARED_PRIVATE.has(spelled);
      if (foreignPrivate) problems.push(`${where}: a private header of ${folder}`);
    });
  }
  assert.deepEqual(problems, []);
});
