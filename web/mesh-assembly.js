// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh assemblies in the playground (issue 29, docs/meshes.md): several OBJ/STL/3MF files dropped
// or picked at once, a 3MF, or one file of several parts (OBJ objects or groups, ASCII STL solids)
// are one assembly of closed meshes, checked by the core as `desia check FILES` checks them (the
// package's check of a mesh document) and drawn from the core's part surfaces: the same view,
// report, blocking graphs, playback and exploded view as every other kind. A single file of one part is
// not an assembly: it stays a mesh to voxelize (web/mesh-input.js). The page's Test choice applies.
//
// For tests: body[data-mesh-assembly] names the files on screen as a mesh assembly ('' when none).

import { meshViewDocument } from './mesh-document.js';

export { isMeshAssemblyName } from './mesh-document.js';

/** The same cap as a mesh to voxelize: a binary STL of the core's 5,000,000 triangles. */
const MAX_MESH_BYTES = 256 * 1024 * 1024;

/** 'a.obj' for one file, 'a.obj + 2 more' for several: the name on screen and in the menu. */
function assemblyName(files) {
  return files.length === 1 ? files[0].name : `${files[0].name} + ${files.length - 1} more`;
}

/** The mesh document of picked or dropped Files: { files: [{ name, bytes }] } (millimetres). */
async function meshDocumentOf(files) {
  const total = files.reduce((sum, file) => sum + file.size, 0);
  if (total > MAX_MESH_BYTES) {
    throw new Error(`${assemblyName(files)}: the files are ${(total / 1048576).toFixed(1)} MiB; the playground accepts meshes up to ${MAX_MESH_BYTES / 1048576} MiB`);
  }
  const contents = await Promise.all(files.map((file) => file.arrayBuffer()));
  return { files: files.map((file, k) => ({ name: file.name, bytes: new Uint8Array(contents[k]) })) };
}

/**
 * `core` is the page's CoreWorker; `loadAssembly(name, load, { origin, asInput })` shows what
 * `load()` yields (here a prepared { text, document, surfaces, report, elapsedMs }; errors land
 * in the page's error box); `method()` is the Test chosen on the page.
 */
export function createMeshAssemblyInput({ core, loadAssembly, method }) {
  /** The assembly on screen: { name, meshes } (meshes: a promise of its mesh document), or null. */
  let shown = null;

  function show(name, meshes) {
    shown = { name, meshes };
    document.body.dataset.meshAssembly = name;
    return loadAssembly(name, async () => {
      const { value: { report, surfaces }, elapsedMs } = await core.run('mesh-assembly', '', { meshes: await meshes, method: method() });
      // No text: a mesh assembly is shown from its files, and is not the Design panel's input.
      return { text: '', document: meshViewDocument(name, report), surfaces, report, elapsedMs };
    }, { origin: '', asInput: false }); // the core's messages name their file among several: shown as they are
  }

  return {
    /** Several files, or one 3MF: always an assembly (the core names what it cannot read). */
    open(files) {
      const meshes = meshDocumentOf(files);
      meshes.catch(() => {});  // shown by loadAssembly
      return show(assemblyName(files), meshes);
    },
    /**
     * One OBJ or STL: an assembly when the core finds several parts in it, then shown (true);
     * else false (a single solid, or a file the core cannot read as parts: the voxelizer says why).
     */
    async openIfSeveralParts(file) {
      let parts = 0;
      let meshes;
      try {
        meshes = await meshDocumentOf([file]);
        ({ value: parts } = await core.run('mesh-parts', '', { meshes }));
      } catch {
        return false;
      }
      if (parts < 2) return false;
      await show(file.name, Promise.resolve(meshes));
      return true;
    },
    /** True when `name` is the mesh assembly on screen (the Test choice then checks its files again). */
    shows(name) {
      return shown !== null && shown.name === name;
    },
    recheck() {
      return shown ? show(shown.name, shown.meshes) : Promise.resolve();
    },
    /** Another assembly is on screen now. */
    forget() {
      shown = null;
      document.body.dataset.meshAssembly = '';
    },
  };
}
