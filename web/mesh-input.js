// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh input: an OBJ or STL mesh (the user's file, dropped or picked, or a bundled example) is
// voxelized by the core in the worker into a one-part voxel shape, which becomes the assembly on
// screen and so the Design panel's input. The resolution (voxels along the longest side of the
// mesh's bounding box) has a slider; moving it voxelizes the same mesh again, debounced, and a
// voxelization that is still running after a moment is cancelled (its worker terminated: a busy
// WebAssembly worker cannot read a message) rather than waited for.
//
// For tests: #mesh-panel[data-state] = voxelizing | ready | error (hidden when no mesh is the
// input), #mesh-stats[data-voxels, data-grid ("16x5x16"), data-resolution, data-code (the
// core's error code)].

import { byId } from './dom.js';
import { readUrlState, writeUrlState } from './url-state.js';

/** Bundled closed meshes (examples/meshes/), listed with the examples. */
export const MESH_EXAMPLES = [
  { file: 'torus.obj', label: 'Torus (mesh to voxelize)' },
];
const MESH_EXAMPLES_URL = new URL('../examples/meshes/', import.meta.url);

/** The CLI's default (`desia voxelize`), so a mesh gives the same shape here and there. */
export const DEFAULT_RESOLUTION = 32;
/** Meshes are limited by the core to 5,000,000 triangles: a binary STL of that is about 250 MB. */
const MAX_MESH_BYTES = 256 * 1024 * 1024;
/** A slider being dragged voxelizes once it rests this long. */
const DEBOUNCE_MS = 250;
/** A voxelization (with its check) running longer than this is cancelled, not waited for. */
const SLOW_MS = 300;

export function isMeshName(name) {
  return /\.(obj|stl)$/i.test(name ?? '');
}

/** 'torus.obj' -> 'torus'. */
function stem(name) {
  return name.replace(/\.[^.]*$/, '') || 'mesh';
}

/** Reads the bytes once, on first use; later voxelizations reuse them. */
function lazyBytes(read) {
  let promise = null;
  return () => {
    promise ??= read().then((buffer) => new Uint8Array(buffer));
    return promise;
  };
}

/**
 * Wires the mesh panel. `core` is the page's CoreWorker; `loadAssembly(name, readText,
 * { origin })` shows an assembly whose text `readText()` yields (errors land in the page's error
 * box; messages that already start with `origin`, the mesh's name, are shown as they are).
 */
export function createMeshInput({ core, loadAssembly }) {
  const ui = {
    panel: byId('mesh-panel'),
    name: byId('mesh-name'),
    slider: byId('mesh-resolution'),
    number: byId('mesh-resolution-number'),
    stats: byId('mesh-stats'),
  };
  /** The mesh being voxelized: { name, example, bytes() }, or null. */
  let mesh = null;
  /** The newest voxelization: { mesh, resolution, started }; null once it has finished. */
  let pending = null;
  let timer = 0;
  /** Set by user input that has not been voxelized yet (a 'change' then voxelizes at once). */
  let dirty = false;

  function setResolution(value) {
    ui.number.value = String(value);
    ui.slider.value = String(value); // A value beyond the slider's range pins it to an end.
  }

  function setState(state, text, data = {}) {
    ui.panel.dataset.state = state;
    ui.stats.textContent = text;
    for (const key of ['voxels', 'grid', 'resolution', 'code']) ui.stats.dataset[key] = data[key] ?? '';
  }

  /**
   * Voxelizes the current mesh at the resolution on screen and shows the result. The number
   * goes to the core unchecked: its messages say what is out of range.
   */
  function voxelize() {
    clearTimeout(timer);
    dirty = false;
    if (!mesh) return Promise.resolve();
    const source = mesh;
    const resolution = Number(ui.number.value.trim() === '' ? Number.NaN : ui.number.value);
    if (source.example) writeUrlState({ resolution: ui.number.value });
    // The page would wait for a long voxelization before starting this one: stop it instead.
    if (pending && performance.now() - pending.started > SLOW_MS) core.cancel();
    const request = { mesh: source, resolution, started: performance.now() };
    pending = request;
    const isNewest = () => pending === request;
    setState('voxelizing', `Voxelizing at resolution ${ui.number.value}…`, { resolution: String(resolution) });
    const shapeName = `${stem(source.name)}_r${ui.number.value}.json`;
    const done = loadAssembly(shapeName, async () => {
      try {
        const bytes = await source.bytes();
        const { value, elapsedMs } = await core.run('voxelize', '', { resolution, source: source.name }, { bytes });
        if (isNewest()) {
          const grid = value.size.join('x');
          setState('ready', `${value.voxels} voxels · grid ${value.size.join(' × ')} · ${Math.round(elapsedMs)} ms`, {
            voxels: String(value.voxels), grid, resolution: String(resolution),
          });
        }
        return value.text;
      } catch (error) {
        if (isNewest() && !error.cancelled) setState('error', 'No shape: the reason is in the red box at the top of the report (right column; under the view on a phone).', { resolution: String(resolution), code: error.code ?? 'error' });
        throw error;
      }
    }, { origin: source.name });
    return done.finally(() => {
      if (isNewest()) pending = null;
    });
  }

  function schedule() {
    dirty = true;
    clearTimeout(timer);
    timer = setTimeout(voxelize, DEBOUNCE_MS);
  }

  function show(source) {
    mesh = source;
    ui.panel.hidden = false;
    ui.name.textContent = source.name;
    return voxelize();
  }

  function wire() {
    ui.slider.addEventListener('input', () => {
      ui.number.value = ui.slider.value;
      schedule();
    });
    ui.number.addEventListener('input', () => {
      if (ui.number.value.trim() !== '') ui.slider.value = ui.number.value;
      schedule();
    });
    for (const input of [ui.slider, ui.number]) {
      input.addEventListener('change', () => {
        if (dirty) voxelize();
      });
    }
  }

  setResolution(DEFAULT_RESOLUTION);
  wire();

  return {
    examples: MESH_EXAMPLES,
    isExample(file) {
      return MESH_EXAMPLES.some((example) => example.file === file);
    },
    /** A user's mesh file: its resolution is not part of the URL (the file is not either). */
    openFile(file) {
      writeUrlState({ resolution: null });
      return show({
        name: file.name,
        example: false,
        bytes: lazyBytes(async () => {
          if (file.size > MAX_MESH_BYTES) {
            throw new Error(`the file is ${(file.size / 1048576).toFixed(1)} MiB; the playground accepts meshes up to ${MAX_MESH_BYTES / 1048576} MiB`);
          }
          return file.arrayBuffer();
        }),
      });
    },
    /** A bundled mesh; a resolution in the URL (a shared link) is taken as it is. */
    openExample(file) {
      const fromUrl = readUrlState().resolution;
      if (fromUrl !== undefined && fromUrl.trim() !== '') setResolution(fromUrl.trim());
      return show({
        name: file,
        example: true,
        bytes: lazyBytes(async () => {
          const url = new URL(file, MESH_EXAMPLES_URL);
          const response = await fetch(url);
          if (!response.ok) throw new Error(`cannot fetch example ${url.pathname} (HTTP ${response.status})`);
          return response.arrayBuffer();
        }),
      });
    },
    /** Another assembly (not from the mesh) is the input now: hide the panel. */
    forget() {
      clearTimeout(timer);
      dirty = false;
      mesh = null;
      pending = null;
      ui.panel.hidden = true;
      writeUrlState({ resolution: null });
    },
    /** While the worker designs, the mesh cannot be voxelized again. */
    setDisabled(disabled) {
      ui.slider.disabled = disabled;
      ui.number.disabled = disabled;
    },
    get exampleUrls() {
      return MESH_EXAMPLES.map((example) => new URL(example.file, MESH_EXAMPLES_URL).href);
    },
  };
}
