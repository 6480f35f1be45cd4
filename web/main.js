// SPDX-License-Identifier: GPL-3.0-or-later
//
// The desia playground page: picks an assembly (bundled example, file picker or drag-and-drop),
// sends it to the WebAssembly core running in a module worker, draws the parts with three.js
// and lists the interlocking report. The page itself never loads the WebAssembly module, so a
// slow check or a crashed core cannot freeze or break it.
//
// For tests the page exposes: body[data-status] = loading | ready | error, body[data-source] =
// the assembly shown, body[data-webgl] = on | off, #verdict (text, data-verdict, data-key) and
// #error.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

// ---------------------------------------------------------------------------------------------
// Configuration

/** Bundled voxel puzzles (copies of the original authors' results), served from this origin. */
const EXAMPLES = [
  { file: 'Cube_4x4x4_K9.puz', label: 'Cube 4×4×4, 9 parts' },
  { file: 'Cube_4x4x4_K9_01.puz', label: 'Cube 4×4×4, 7 parts' },
  { file: 'Cube_Hollow_4x4x4_K7.puz', label: 'Hollow cube 4×4×4, 7 parts' },
  { file: 'cube_5x5x5_K16.puz', label: 'Cube 5×5×5, 16 parts' },
  { file: 'cartoon_dog.puz', label: 'Cartoon dog, 14 parts' },
  { file: 'bunny_15x14x11_K80.puz', label: 'Bunny, 80 parts' },
];
const EXAMPLES_URL = new URL('../examples/voxel/', import.meta.url);
const USER_FILE_OPTION = '__user-file__';

/** Larger inputs are refused before reading: a voxel file this big is surely a mistake. */
const MAX_FILE_BYTES = 32 * 1024 * 1024;
/** A worker that has not reported `ready` by then is considered dead. */
const WORKER_START_TIMEOUT_MS = 30_000;
/** Consecutive failed worker starts before we stop restarting on our own. */
const MAX_FAILED_STARTS = 3;

const VERDICT_TITLES = {
  interlocking: 'Interlocking',
  deadlocked: 'Deadlocked',
  'not-interlocking': 'Not interlocking',
};

// ---------------------------------------------------------------------------------------------
// Small DOM helpers

const byId = (id) => {
  const element = document.getElementById(id);
  if (!element) throw new Error(`index.html lacks #${id}`);
  return element;
};

const ui = {
  exampleSelect: byId('example-select'),
  fileInput: byId('file-input'),
  methodSelect: byId('method-select'),
  statusText: byId('status-text'),
  viewport: byId('viewport'),
  viewerNotice: byId('viewer-notice'),
  disassemblyRange: byId('disassembly-range'),
  disassemblyStep: byId('disassembly-step'),
  error: byId('error'),
  sourceName: byId('source-name'),
  verdict: byId('verdict'),
  reason: byId('reason'),
  partsCount: byId('parts-count'),
  key: byId('key'),
  keyDirections: byId('key-directions'),
  baseDirections: byId('base-directions'),
  order: byId('order'),
  witness: byId('witness'),
  timing: byId('timing'),
  paths: byId('paths'),
  graphs: byId('graphs'),
  coreVersion: byId('core-version'),
  dropOverlay: byId('drop-overlay'),
};

const STATUS_LABELS = { loading: 'Working…', ready: 'Ready', error: 'Error' };

function setStatus(status, text = STATUS_LABELS[status]) {
  document.body.dataset.status = status;
  ui.statusText.textContent = text;
}

function showError(message) {
  ui.error.textContent = message;
  ui.error.hidden = false;
}

function hideError() {
  ui.error.textContent = '';
  ui.error.hidden = true;
}

function element(tag, text, className) {
  const node = document.createElement(tag);
  if (text !== undefined) node.textContent = text;
  if (className) node.className = className;
  return node;
}

// ---------------------------------------------------------------------------------------------
// The worker client: request/response over the typed protocol, with crash recovery.

class CoreWorker {
  #worker = null;
  #pending = new Map();
  #nextId = 1;
  #failedStarts = 0;
  #ready = false;
  #startTimer = 0;
  #onReady;
  #onCrash;

  /** `onReady(version)` after each successful start; `onCrash(message, willRestart)`. */
  constructor({ onReady, onCrash }) {
    this.#onReady = onReady;
    this.#onCrash = onCrash;
  }

  start() {
    const worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
    this.#worker = worker;
    this.#ready = false;
    worker.addEventListener('message', (event) => {
      if (worker === this.#worker) this.#handleMessage(event.data);
    });
    worker.addEventListener('error', (event) => {
      // Keep the failure out of the console's "uncaught" list: we report it ourselves.
      event.preventDefault();
      if (worker !== this.#worker) return;
      // A module worker that fails to load its imports gets an error event without a message.
      const detail = event.message || 'the worker script or one of its imports failed to load '
        + '(is the WebAssembly build there? run: bash scripts/build.sh wasm)';
      this.#crash(`worker crashed: ${detail}`);
    });
    worker.addEventListener('messageerror', () => {
      if (worker === this.#worker) this.#crash('worker sent a message the page could not read');
    });
    clearTimeout(this.#startTimer);
    this.#startTimer = setTimeout(() => {
      if (worker === this.#worker) this.#crash(`the WebAssembly core did not start within ${WORKER_START_TIMEOUT_MS / 1000} s`);
    }, WORKER_START_TIMEOUT_MS);
    worker.postMessage({ type: 'init' });
  }

  /** Runs `op` ('check' | 'parse') on `text`; resolves with `{ value, elapsedMs }`. */
  run(op, text, options = {}) {
    if (!this.#worker) {
      // We gave up restarting after repeated failures; a new request is worth one more try.
      this.#failedStarts = 0;
      this.start();
    }
    const id = this.#nextId++;
    return new Promise((resolve, reject) => {
      this.#pending.set(id, { resolve, reject });
      this.#worker.postMessage({ type: 'run', id, op, text, options });
    });
  }

  #handleMessage(message) {
    switch (message?.type) {
      case 'ready':
        clearTimeout(this.#startTimer);
        this.#ready = true;
        this.#failedStarts = 0;
        this.#onReady(message.version);
        break;
      case 'result':
        this.#settle(message.id, (request) => request.resolve({ value: message.value, elapsedMs: message.elapsedMs }));
        break;
      case 'error':
        if (message.id === null || message.id === undefined) {
          this.#crash(message.message);
          break;
        }
        this.#settle(message.id, (request) => request.reject(new Error(message.message)));
        // The module trapped or aborted: its state is gone, so is its usefulness.
        if (message.fatal) this.#crash(message.message);
        break;
      default:
        console.warn('desia playground: unexpected worker message', message);
    }
  }

  #settle(id, action) {
    const request = this.#pending.get(id);
    if (!request) return;
    this.#pending.delete(id);
    action(request);
  }

  /** Throws the worker away, fails what it still owed us, and starts a fresh one if sensible. */
  #crash(message) {
    // Only failures before `ready` count towards giving up: a worker that ran fine and then
    // crashed on one input deserves a fresh start every time.
    if (!this.#ready) this.#failedStarts += 1;
    clearTimeout(this.#startTimer);
    this.#worker?.terminate();
    this.#worker = null;
    const error = new Error(message);
    for (const request of this.#pending.values()) request.reject(error);
    this.#pending.clear();

    const willRestart = this.#failedStarts < MAX_FAILED_STARTS;
    this.#onCrash(message, willRestart);
    if (willRestart) this.start();
  }
}

// ---------------------------------------------------------------------------------------------
// Voxel geometry: one merged surface per part, only faces that do not touch the same part.

/** The six cube faces: neighbour offset (= outward normal) and corners in CCW order seen from outside. */
const CUBE_FACES = [
  { normal: [1, 0, 0], corners: [[1, 0, 0], [1, 1, 0], [1, 1, 1], [1, 0, 1]] },
  { normal: [-1, 0, 0], corners: [[0, 0, 0], [0, 0, 1], [0, 1, 1], [0, 1, 0]] },
  { normal: [0, 1, 0], corners: [[0, 1, 0], [0, 1, 1], [1, 1, 1], [1, 1, 0]] },
  { normal: [0, -1, 0], corners: [[0, 0, 0], [1, 0, 0], [1, 0, 1], [0, 0, 1]] },
  { normal: [0, 0, 1], corners: [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]] },
  { normal: [0, 0, -1], corners: [[0, 0, 0], [0, 1, 0], [1, 1, 0], [1, 0, 0]] },
];

/**
 * Builds, for every part id, the triangles of its boundary: a face between two voxels of the
 * same part is interior and skipped; faces against empty space or another part are kept (the
 * latter show up when parts move apart). Labels are in index order x + nx*(y + ny*z).
 * Returns Map(partId -> { positions, normals, indices }) as typed arrays, plus the bounds of
 * all occupied voxels.
 */
function buildPartSurfaces([nx, ny, nz], labels) {
  const labelAt = (x, y, z) => (x < 0 || y < 0 || z < 0 || x >= nx || y >= ny || z >= nz
    ? 0 : labels[x + nx * (y + ny * z)]);
  const builders = new Map();
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];

  for (let z = 0; z < nz; z += 1) {
    for (let y = 0; y < ny; y += 1) {
      for (let x = 0; x < nx; x += 1) {
        const part = labels[x + nx * (y + ny * z)];
        if (part <= 0) continue;
        const cell = [x, y, z];
        for (let axis = 0; axis < 3; axis += 1) {
          min[axis] = Math.min(min[axis], cell[axis]);
          max[axis] = Math.max(max[axis], cell[axis] + 1);
        }
        let builder = builders.get(part);
        if (!builder) {
          builder = { positions: [], normals: [], indices: [] };
          builders.set(part, builder);
        }
        for (const face of CUBE_FACES) {
          const [dx, dy, dz] = face.normal;
          if (labelAt(x + dx, y + dy, z + dz) === part) continue;
          appendFace(builder, cell, face);
        }
      }
    }
  }

  const surfaces = new Map();
  for (const [part, builder] of builders) {
    surfaces.set(part, {
      positions: new Float32Array(builder.positions),
      normals: new Float32Array(builder.normals),
      indices: new Uint32Array(builder.indices),
    });
  }
  return { surfaces, min, max };
}

function appendFace(builder, [x, y, z], face) {
  const base = builder.positions.length / 3;
  for (const [cx, cy, cz] of face.corners) {
    builder.positions.push(x + cx, y + cy, z + cz);
    builder.normals.push(...face.normal);
  }
  builder.indices.push(base, base + 1, base + 2, base, base + 2, base + 3);
}

function surfaceGeometry({ positions, normals, indices }) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  geometry.setIndex(new THREE.BufferAttribute(indices, 1));
  geometry.computeBoundingSphere();
  return geometry;
}

/** '+y' -> (0, 1, 0); uses the report's base directions first, then the axis notation. */
function directionVector(label, baseDirections = []) {
  const known = baseDirections.find((direction) => direction.label === label);
  if (known) return new THREE.Vector3(...known.vector);
  const match = /^([+-])([xyz])$/.exec(String(label).trim());
  if (!match) return new THREE.Vector3();
  const vector = new THREE.Vector3();
  vector[match[2]] = match[1] === '+' ? 1 : -1;
  return vector;
}

// ---------------------------------------------------------------------------------------------
// Colours: the key in a warm gold, every other part a well-separated hue away from it.

const KEY_COLOR = new THREE.Color(0xffc21a);
const GOLDEN_RATIO_CONJUGATE = 0.618033988749895;

function partColor(index) {
  let hue = (0.55 + index * GOLDEN_RATIO_CONJUGATE) % 1;
  // Keep clear of the key's gold so the key stays unmistakable.
  if (hue > 0.08 && hue < 0.18) hue = (hue + 0.12) % 1;
  const lightness = index % 2 === 0 ? 0.56 : 0.46;
  return new THREE.Color().setHSL(hue, 0.55, lightness);
}

// ---------------------------------------------------------------------------------------------
// The three.js view

class AssemblyView {
  #container;
  #notice;
  #renderer = null;
  #scene;
  #camera;
  #controls;
  #content = new THREE.Group();
  #meshes = new Map();
  #motions = new Map();
  #frameRequest = 0;
  #raycaster = new THREE.Raycaster();
  #hoverLabel;

  constructor(container, notice) {
    this.#container = container;
    this.#notice = notice;
    try {
      this.#renderer = new THREE.WebGLRenderer({ antialias: true });
    } catch (error) {
      // No WebGL (blocked GPU, old driver): the report panel still works without a picture.
      this.#showNotice(`3D view unavailable: ${error.message}`);
      document.body.dataset.webgl = 'off';
      return;
    }
    document.body.dataset.webgl = 'on';
    this.#renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    container.append(this.#renderer.domElement);
    this.#hoverLabel = element('div', '', 'hover-label');
    this.#hoverLabel.hidden = true;
    container.append(this.#hoverLabel);

    this.#scene = new THREE.Scene();
    this.#scene.background = new THREE.Color(0x1b1e24);
    this.#scene.add(this.#content);
    this.#camera = new THREE.PerspectiveCamera(40, 1, 0.1, 1000);
    this.#addLights();

    this.#controls = new OrbitControls(this.#camera, this.#renderer.domElement);
    this.#controls.addEventListener('change', () => this.requestRender());
    this.#renderer.domElement.addEventListener('pointermove', (event) => this.#updateHover(event));
    this.#renderer.domElement.addEventListener('pointerleave', () => { this.#hoverLabel.hidden = true; });
    new ResizeObserver(() => this.#resize()).observe(container);
    this.#resize();
  }

  get available() {
    return this.#renderer !== null;
  }

  #addLights() {
    this.#scene.add(new THREE.HemisphereLight(0xf4f6ff, 0x3a3328, 1.6));
    // A light riding on the camera keeps the faces facing the viewer readable from any angle.
    const headLight = new THREE.DirectionalLight(0xffffff, 1.6);
    headLight.position.set(0.6, 1, 0.4);
    this.#camera.add(headLight);
    this.#scene.add(this.#camera);
  }

  #showNotice(text) {
    this.#notice.textContent = text;
    this.#notice.hidden = !text;
  }

  /** Draws a parsed document; `applyReport` adds what the check found. */
  show(document_) {
    this.clear();
    if (!this.available) return;
    if (document_?.kind !== 'voxel' || !document_.voxel) {
      this.#showNotice(`No 3D view for "${document_?.kind ?? 'unknown'}" documents yet.`);
      return;
    }
    const { size, labels } = document_.voxel;
    const { surfaces, min, max } = buildPartSurfaces(size, labels);
    if (surfaces.size === 0) {
      this.#showNotice('The assembly has no voxels.');
      return;
    }
    // Integer offsets keep voxel boundaries on the grid lines.
    const offset = new THREE.Vector3(-Math.floor((min[0] + max[0]) / 2), -min[1], -Math.floor((min[2] + max[2]) / 2));
    this.#content.position.copy(offset);
    this.#addParts(surfaces);
    this.#addGrid(min, max, offset);
    this.#fitCamera(min, max, offset);
    this.#container.dataset.parts = String(this.#meshes.size);
    this.requestRender();
  }

  #addParts(surfaces) {
    const partIds = [...surfaces.keys()].sort((a, b) => a - b);
    partIds.forEach((partId, index) => {
      const geometry = surfaceGeometry(surfaces.get(partId));
      const material = new THREE.MeshStandardMaterial({
        color: partColor(index),
        roughness: 0.7,
        metalness: 0.0,
        // Push the faces back a little so the outline edges win the depth test.
        polygonOffset: true,
        polygonOffsetFactor: 1,
        polygonOffsetUnits: 1,
      });
      const mesh = new THREE.Mesh(geometry, material);
      mesh.name = `part ${partId}`;
      mesh.userData.partId = partId;
      const edges = new THREE.LineSegments(
        new THREE.EdgesGeometry(geometry, 30),
        new THREE.LineBasicMaterial({ color: 0x101215, transparent: true, opacity: 0.55 }),
      );
      mesh.add(edges);
      this.#content.add(mesh);
      this.#meshes.set(partId, mesh);
    });
  }

  #addGrid(min, max, offset) {
    const extent = Math.max(max[0] - min[0], max[2] - min[2]);
    // An even size keeps grid lines on integer coordinates, i.e. on voxel boundaries.
    const size = 2 * Math.ceil((extent + 4) / 2);
    const grid = new THREE.GridHelper(size, size, 0x59606e, 0x353a44);
    grid.name = 'grid';
    grid.position.set(0, min[1] + offset.y - 0.001, 0);
    this.#scene.add(grid);
  }

  #fitCamera(min, max, offset) {
    const box = new THREE.Box3(new THREE.Vector3(...min), new THREE.Vector3(...max));
    box.translate(offset);
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1);
    // The narrower of the vertical and horizontal fields of view decides what fits.
    const verticalHalfFov = THREE.MathUtils.degToRad(this.#camera.fov / 2);
    const horizontalHalfFov = Math.atan(Math.tan(verticalHalfFov) * this.#camera.aspect);
    const distance = (radius / Math.sin(Math.min(verticalHalfFov, horizontalHalfFov))) * 1.25;
    const viewDirection = new THREE.Vector3(1, 0.85, 1.5).normalize();
    this.#camera.position.copy(center).addScaledVector(viewDirection, distance);
    this.#camera.near = distance / 100;
    this.#camera.far = distance * 50;
    this.#camera.updateProjectionMatrix();
    this.#controls.target.copy(center);
    this.#controls.maxDistance = distance * 10;
    this.#controls.update();
  }

  /** Highlights the key (or the witness group on failure) and prepares the removal animation. */
  applyReport(report) {
    if (!this.available) return;
    const keyId = report.key;
    const witnessParts = new Set(report.witness?.parts ?? []);
    for (const [partId, mesh] of this.#meshes) {
      const isKey = partId === keyId;
      const dimmed = witnessParts.size > 0 && !witnessParts.has(partId);
      const material = mesh.material;
      if (isKey) {
        material.color.copy(KEY_COLOR);
        material.emissive.copy(KEY_COLOR).multiplyScalar(0.35);
        mesh.children[0].material.color.set(0xfff3c4);
        mesh.children[0].material.opacity = 1;
      }
      material.transparent = dimmed;
      material.opacity = dimmed ? 0.18 : 1;
      material.depthWrite = !dimmed;
      material.needsUpdate = true;
      if (dimmed) mesh.children[0].material.opacity = 0.12;
    }
    this.#motions = removalMotions(report);
    this.setDisassemblyStep(0);
  }

  /**
   * Shows the disassembly at `step` (0 = assembled): the part at position i of the order is on
   * its way out while step is between i and i + 1, and gone after that. Only the last part,
   * which has no path, stays.
   */
  setDisassemblyStep(step) {
    for (const [partId, mesh] of this.#meshes) {
      const motion = this.#motions.get(partId);
      if (!motion) {
        mesh.position.set(0, 0, 0);
        mesh.visible = true;
        continue;
      }
      const progress = THREE.MathUtils.clamp(step - motion.index, 0, 1);
      mesh.visible = progress < 1 || motion.waypoints.length === 1;
      mesh.position.copy(pointAlong(motion.waypoints, progress));
    }
    this.requestRender();
  }

  clear() {
    if (this.#hoverLabel) this.#hoverLabel.hidden = true;
    for (const mesh of this.#meshes.values()) {
      mesh.children[0].geometry.dispose();
      mesh.children[0].material.dispose();
      mesh.geometry.dispose();
      mesh.material.dispose();
    }
    this.#content.clear();
    this.#meshes.clear();
    this.#motions = new Map();
    if (!this.available) return;
    this.#showNotice('');
    const grid = this.#scene.getObjectByName('grid');
    if (grid) {
      grid.geometry.dispose();
      grid.material.dispose();
      this.#scene.remove(grid);
    }
    this.#container.dataset.parts = '0';
    this.requestRender();
  }

  /** Renders on demand (at most once per frame) instead of spinning a render loop. */
  requestRender() {
    if (!this.available || this.#frameRequest) return;
    this.#frameRequest = requestAnimationFrame(() => {
      this.#frameRequest = 0;
      this.#renderer.render(this.#scene, this.#camera);
    });
  }

  #resize() {
    const width = Math.max(this.#container.clientWidth, 1);
    const height = Math.max(this.#container.clientHeight, 1);
    this.#renderer.setSize(width, height, false);
    this.#camera.aspect = width / height;
    this.#camera.updateProjectionMatrix();
    this.requestRender();
  }

  #updateHover(event) {
    const bounds = this.#renderer.domElement.getBoundingClientRect();
    const pointer = new THREE.Vector2(
      ((event.clientX - bounds.left) / bounds.width) * 2 - 1,
      -((event.clientY - bounds.top) / bounds.height) * 2 + 1,
    );
    this.#raycaster.setFromCamera(pointer, this.#camera);
    const hit = this.#raycaster
      .intersectObjects([...this.#meshes.values()], false)
      .find((candidate) => candidate.object.visible && candidate.object.material.opacity === 1);
    this.#hoverLabel.hidden = !hit;
    if (hit) this.#hoverLabel.textContent = `part ${hit.object.userData.partId}`;
  }
}

/** How far a part keeps going after its last move before it disappears, in voxels. */
const RUN_OUT_VOXELS = 2;

/**
 * The removal motion of each part, from the report's disassembly: the waypoints of its path
 * (each move translates it by `steps` voxels along `dir`) plus a short run-out along its last
 * move. Returns Map(partId -> { index in the order, waypoints }).
 */
function removalMotions(report) {
  const motions = new Map();
  const disassembly = report.disassembly;
  if (!disassembly?.order?.length) return motions;
  disassembly.order.forEach((partId, index) => {
    const path = disassembly.paths?.[index] ?? [];
    const waypoints = [new THREE.Vector3()];
    for (const move of path) {
      const step = directionVector(move.dir, report.baseDirections).multiplyScalar(Number(move.steps) || 0);
      waypoints.push(waypoints[waypoints.length - 1].clone().add(step));
    }
    if (path.length > 0) {
      const last = directionVector(path[path.length - 1].dir, report.baseDirections);
      waypoints.push(waypoints[waypoints.length - 1].clone().addScaledVector(last, RUN_OUT_VOXELS));
    }
    motions.set(partId, { index, waypoints });
  });
  return motions;
}

/** The point at `fraction` (0..1) of the polyline's length. */
function pointAlong(waypoints, fraction) {
  let total = 0;
  for (let i = 1; i < waypoints.length; i += 1) total += waypoints[i].distanceTo(waypoints[i - 1]);
  let remaining = fraction * total;
  for (let i = 1; i < waypoints.length; i += 1) {
    const length = waypoints[i].distanceTo(waypoints[i - 1]);
    if (remaining <= length && length > 0) return waypoints[i - 1].clone().lerp(waypoints[i], remaining / length);
    remaining -= length;
  }
  return waypoints[waypoints.length - 1].clone();
}

// ---------------------------------------------------------------------------------------------
// The report panel

function formatList(values, empty = 'none') {
  return values?.length ? values.join(', ') : empty;
}

/** Long orders are shortened here; the full list is under "Removal paths". */
function formatOrder(order) {
  if (order.length <= 12) return order.join(' → ');
  return `${order.slice(0, 8).join(' → ')} → … → ${order.slice(-2).join(' → ')}`;
}

function formatDisassemblyFailure(failure) {
  if (!failure) return 'none found';
  const removed = failure.removed?.length ? `after removing ${formatList(failure.removed)}, ` : '';
  return `none: ${removed}parts ${formatList(failure.stuck)} are stuck`;
}

function formatWitness(witness) {
  if (!witness) return 'none';
  const how = witness.direction ? `along ${witness.direction}` : 'in different directions';
  const noun = witness.parts?.length === 1 ? 'part' : 'parts';
  return `${noun} ${formatList(witness.parts)} can move ${how}`;
}

/** With method 'both' the report carries each test's verdict; show them when they differ or agree. */
function formatMethods(methods) {
  if (!methods) return '';
  const name = (verdict) => VERDICT_TITLES[verdict?.verdict]?.toLowerCase() ?? 'unknown';
  return `Graph test: ${name(methods.dbg)}; LP test: ${name(methods.lp)}`;
}

function formatMoves(path) {
  if (!path?.length) return 'stays (last part)';
  return path.map((move) => `${move.dir}×${move.steps}`).join(', then ');
}

function formatComponents(components) {
  if (!components?.length) return '—';
  const describe = (component) => (component.length <= 4
    ? `{${component.join(', ')}}`
    : `{${component.length} parts}`);
  return `${components.length}: ${components.map(describe).join(' + ')}`;
}

function renderReport(report, elapsedMs) {
  const verdict = report.verdict ?? (report.interlocking ? 'interlocking' : 'not-interlocking');
  const title = VERDICT_TITLES[verdict] ?? verdict;
  const hasKey = report.key !== null && report.key !== undefined;
  ui.verdict.textContent = verdict === 'interlocking' && hasKey ? `${title}, key: part ${report.key}` : title;
  ui.verdict.dataset.verdict = verdict;
  ui.verdict.dataset.key = hasKey ? String(report.key) : '';
  ui.reason.textContent = [report.reason, formatMethods(report.methods)].filter(Boolean).join('. ');
  ui.partsCount.textContent = String(report.parts ?? report.partIds?.length ?? '—');
  ui.key.textContent = hasKey ? `part ${report.key}` : 'none';
  ui.keyDirections.textContent = formatList(report.keyDirections);
  ui.baseDirections.textContent = formatList(report.baseDirections?.map((direction) => direction.label));
  ui.order.textContent = report.disassembly
    ? formatOrder(report.disassembly.order)
    : formatDisassemblyFailure(report.disassemblyFailure);
  ui.witness.textContent = formatWitness(report.witness);
  ui.timing.textContent = Number.isFinite(elapsedMs) ? `${elapsedMs.toFixed(1)} ms` : '—';
  renderPaths(report.disassembly);
  renderGraphs(report.graphs);
}

function renderPaths(disassembly) {
  const items = (disassembly?.order ?? []).map((partId, index) => element(
    'li',
    `part ${partId}: ${formatMoves(disassembly.paths?.[index])}`,
  ));
  ui.paths.replaceChildren(...(items.length ? items : [element('li', 'no disassembly found')]));
}

function renderGraphs(graphs) {
  const rows = (graphs ?? []).map((graph) => {
    const row = document.createElement('tr');
    row.append(
      element('td', graph.direction),
      element('td', String(graph.edges?.length ?? 0)),
      element('td', formatComponents(graph.components)),
    );
    return row;
  });
  ui.graphs.replaceChildren(...rows);
}

function resetReport(message) {
  ui.verdict.textContent = message;
  ui.verdict.dataset.verdict = '';
  ui.verdict.dataset.key = '';
  ui.reason.textContent = '';
  for (const field of [ui.partsCount, ui.key, ui.keyDirections, ui.baseDirections, ui.order, ui.witness, ui.timing]) {
    field.textContent = '—';
  }
  ui.paths.replaceChildren();
  ui.graphs.replaceChildren();
}

// ---------------------------------------------------------------------------------------------
// Loading assemblies

const view = new AssemblyView(ui.viewport, ui.viewerNotice);
let coreReady = false;
let current = null; // { name, text } of the assembly on screen, to re-check with another method.
let loadGeneration = 0; // Only the newest load may touch the page.
let lastUserFile = null; // The user's last file, so its select entry can load it again.

const core = new CoreWorker({
  onReady(version) {
    coreReady = true;
    ui.coreVersion.textContent = version;
  },
  onCrash(message, willRestart) {
    coreReady = false;
    showError(willRestart
      ? `${message}. A fresh worker was started; choose an assembly to try again.`
      : `${message}. The worker failed ${MAX_FAILED_STARTS} times in a row; choosing an assembly tries once more.`);
    setStatus('error');
  },
});

/**
 * Shows one assembly: `readText` yields its text (a fetch or a file read, so that their errors
 * land in the same error box as the core's).
 */
async function loadAssembly(name, readText) {
  const generation = ++loadGeneration;
  const isCurrent = () => generation === loadGeneration;
  setStatus('loading', coreReady ? 'Checking…' : 'Starting the core…');
  document.body.dataset.source = name;
  ui.sourceName.textContent = name;
  hideError();
  resetReport('Checking…');
  try {
    const text = await readText();
    if (!isCurrent()) return;
    // `source` makes the core's error messages name the file (and line) they are about.
    const { value: document_ } = await core.run('parse', text, { source: name });
    if (!isCurrent()) return;
    view.show(document_);
    const { value: report, elapsedMs } = await core.run('check', text, { method: ui.methodSelect.value, source: name });
    if (!isCurrent()) return;
    current = { name, text };
    renderReport(report, elapsedMs);
    view.applyReport(report);
    setUpDisassemblySlider(view.available ? report.disassembly : null);
    setStatus('ready');
  } catch (error) {
    if (!isCurrent()) return;
    current = null;
    view.clear();
    setUpDisassemblySlider(null);
    resetReport('No result');
    // The core's messages start with the source name already; others (fetch, worker) get it here.
    const message = error.message.startsWith(name) ? error.message : `${name}: ${error.message}`;
    showError(message);
    setStatus('error');
  }
}

async function fetchExampleText(file) {
  const url = new URL(file, EXAMPLES_URL);
  const response = await fetch(url);
  if (!response.ok) throw new Error(`cannot fetch example ${url.pathname} (HTTP ${response.status})`);
  return response.text();
}

function loadExample(file) {
  return loadAssembly(file, () => fetchExampleText(file));
}

function loadUserFile(file) {
  lastUserFile = file;
  const option = ui.exampleSelect.querySelector(`option[value="${USER_FILE_OPTION}"]`);
  option.textContent = `Your file: ${file.name}`;
  option.hidden = false;
  ui.exampleSelect.value = USER_FILE_OPTION;
  return loadAssembly(file.name, async () => {
    if (file.size > MAX_FILE_BYTES) {
      throw new Error(`the file is ${(file.size / 1048576).toFixed(1)} MiB; the playground accepts up to ${MAX_FILE_BYTES / 1048576} MiB`);
    }
    return decodeText(file.name, await file.arrayBuffer());
  });
}

/**
 * Strict UTF-8 decoding: a lenient decoder would turn a binary file into U+FFFD characters and
 * the core would then report bytes the user's file never contained.
 */
function decodeText(name, buffer) {
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(buffer);
  } catch {
    throw new Error(`${name}: not a text file (it is not valid UTF-8); expected a .puz or desia .json assembly`);
  }
}

// ---------------------------------------------------------------------------------------------
// The disassembly slider: 0 = assembled, i..i+1 = the (i+1)-th part of the order moving out.

let shownDisassembly = null;

function setUpDisassemblySlider(disassembly) {
  const removable = (disassembly?.order?.length ?? 0) - 1;
  shownDisassembly = removable > 0 ? disassembly : null;
  ui.disassemblyRange.disabled = !shownDisassembly;
  ui.disassemblyRange.max = String(Math.max(removable, 1));
  ui.disassemblyRange.value = '0';
  ui.disassemblyStep.textContent = shownDisassembly ? 'assembled' : '';
}

function showDisassemblyStep() {
  const step = Number(ui.disassemblyRange.value);
  view.setDisassemblyStep(step);
  if (!shownDisassembly) return;
  const { order } = shownDisassembly;
  const index = Math.min(Math.floor(step), order.length - 1);
  if (step === 0) ui.disassemblyStep.textContent = 'assembled';
  else if (index >= order.length - 1) ui.disassemblyStep.textContent = `part ${order[order.length - 1]} left`;
  else ui.disassemblyStep.textContent = `removing part ${order[index]} (${index + 1} of ${order.length - 1})`;
}

// ---------------------------------------------------------------------------------------------
// Wiring

function fillExampleSelect() {
  const userOption = element('option', 'Your file');
  userOption.value = USER_FILE_OPTION;
  userOption.hidden = true;
  const options = EXAMPLES.map(({ file, label }) => {
    const option = element('option', `${label} (${file})`);
    option.value = file;
    return option;
  });
  ui.exampleSelect.replaceChildren(userOption, ...options);
}

function initialExample() {
  const requested = new URLSearchParams(location.search).get('example');
  return EXAMPLES.some((example) => example.file === requested) ? requested : EXAMPLES[0].file;
}

function wireDragAndDrop() {
  let depth = 0; // dragenter/dragleave fire for every child element crossed.
  const carriesFiles = (event) => [...(event.dataTransfer?.types ?? [])].includes('Files');
  document.addEventListener('dragenter', (event) => {
    if (!carriesFiles(event)) return;
    event.preventDefault();
    depth += 1;
    ui.dropOverlay.hidden = false;
  });
  document.addEventListener('dragover', (event) => {
    if (carriesFiles(event)) event.preventDefault();
  });
  document.addEventListener('dragleave', () => {
    depth = Math.max(depth - 1, 0);
    if (depth === 0) ui.dropOverlay.hidden = true;
  });
  document.addEventListener('drop', (event) => {
    event.preventDefault();
    depth = 0;
    ui.dropOverlay.hidden = true;
    const file = event.dataTransfer?.files?.[0];
    if (file) loadUserFile(file);
  });
}

function wireControls() {
  ui.exampleSelect.addEventListener('change', () => {
    if (ui.exampleSelect.value !== USER_FILE_OPTION) loadExample(ui.exampleSelect.value);
    else if (lastUserFile) loadUserFile(lastUserFile);
  });
  ui.fileInput.addEventListener('change', () => {
    const file = ui.fileInput.files?.[0];
    // Clear the input so picking the same file again still fires `change`.
    ui.fileInput.value = '';
    if (file) loadUserFile(file);
  });
  ui.methodSelect.addEventListener('change', () => {
    if (!current) return;
    const { name, text } = current;
    loadAssembly(name, async () => text);
  });
  ui.disassemblyRange.addEventListener('input', showDisassemblyStep);
}

function main() {
  fillExampleSelect();
  wireControls();
  wireDragAndDrop();
  setStatus('loading', 'Starting the core…');
  core.start();
  const file = initialExample();
  ui.exampleSelect.value = file;
  loadExample(file);
}

main();
