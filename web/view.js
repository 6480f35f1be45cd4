// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shared three.js renderer of the playground and of the drop-in viewer (viewer.js): one
// merged surface per voxel part in its own colour, the key highlighted, the computed disassembly
// played back along the report's removal paths, and an exploded view. It only draws: every fact
// it shows (parts, key, order, paths) comes from the core's report, and the part surfaces from
// the core's partSurfaces (the triangles of the STL/OBJ export).
//
// Exports: AssemblyView (the 3D view inside a container element), DisassemblyPlayer (the
// play/pause clock of the disassembly), createPlaybackControls (wires a slider, a play button, a
// speed select and an explode slider to a view), describeDisassemblyStep, partColorCss, and for
// plate plans formatDirection, planDisassembly and withPlannedRemoval.
//
// Voxel plans that move several parts together (the report's `steps`, issue 27) play move by
// move instead (stepsToPlay says which plan plays): the parts of a move slide together by its
// offset and glow; a part going out alone leaves like a removed part, a group going out moves just
// clear of the rest of its sub-assembly and stays there. Only the offsets are computed here.
//
// For tests the container gets data-parts (meshes drawn), data-step (the disassembly step shown),
// data-move and data-moving (playing moves: the move shown, 1-based, and its parts) and
// data-exploded (the explode factor); AssemblyView.partPositions() reads the parts back.
// With the playground's playback aids (options `tray` and `arrows`): data-visible (meshes shown,
// the tray included), data-tray (removed parts laid out in the tray), data-arrow (the part whose
// way out is drawn), data-selected and data-hidden (the part list's selection and hidden parts).

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

// ---------------------------------------------------------------------------------------------
// Voxel geometry. The part surfaces come from the core (desia.partSurfaces: the same triangles as
// the STL/OBJ export); here only the bounds and centroids used to place the camera and explode.

/**
 * The bounds of all occupied voxels and, per part id, the sum and count of its voxel centres
 * (voxelSum / voxelCount is the part's centroid). Labels are in index order x + nx*(y + ny*z).
 */
function voxelExtents([nx, ny, nz], labels) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  const centroids = new Map();
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
        let sums = centroids.get(part);
        if (!sums) {
          sums = { voxelSum: [0, 0, 0], voxelCount: 0 };
          centroids.set(part, sums);
        }
        for (let axis = 0; axis < 3; axis += 1) sums.voxelSum[axis] += cell[axis] + 0.5;
        sums.voxelCount += 1;
      }
    }
  }
  return { centroids, min, max };
}

/**
 * The bounds of the core's part surfaces and, per part id, the sum and count of its vertices
 * (for documents measured in their own units, such as plates in mm): the same shape of result
 * as voxelExtents, used only to frame the camera, size the grid and explode the parts.
 */
function surfaceExtents(surfaces) {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  const centroids = new Map();
  for (const { partId, positions } of surfaces) {
    if (!(positions?.length >= 3)) continue;
    const sums = { voxelSum: [0, 0, 0], voxelCount: 0 };
    for (let i = 0; i + 2 < positions.length; i += 3) {
      for (let axis = 0; axis < 3; axis += 1) {
        const value = positions[i + axis];
        if (value < min[axis]) min[axis] = value;
        if (value > max[axis]) max[axis] = value;
        sums.voxelSum[axis] += value;
      }
      sums.voxelCount += 1;
    }
    centroids.set(partId, sums);
  }
  return { centroids, min, max };
}

/** 1, 2 or 5 times a power of ten, close to `value` (grid spacing in the document's units). */
function niceStep(value) {
  if (!(value > 0) || !Number.isFinite(value)) return 1;
  const power = 10 ** Math.floor(Math.log10(value));
  const mantissa = value / power;
  return (mantissa < 1.5 ? 1 : mantissa < 3.5 ? 2 : mantissa < 7.5 ? 5 : 10) * power;
}

/** A core part surface (non-indexed triangles with flat normals) as a three.js geometry. */
function surfaceGeometry({ positions, normals }) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  geometry.computeBoundingSphere();
  geometry.computeBoundingBox();
  return geometry;
}

/**
 * '+y' -> (0, 1, 0); a move's own `vector` (a plate plan's removal direction) first, then the
 * report's base directions, then the axis notation.
 */
function directionVector(label, baseDirections = [], vector = null) {
  if (Array.isArray(vector) && vector.length === 3 && vector.every(Number.isFinite)) {
    const own = new THREE.Vector3(...vector);
    if (own.lengthSq() > 0) return own.normalize();
  }
  const known = baseDirections.find((direction) => direction.label === label);
  if (known) return new THREE.Vector3(...known.vector);
  const match = /^([+-])([xyz])$/.exec(String(label).trim());
  if (!match) return new THREE.Vector3();
  const axis = new THREE.Vector3();
  axis[match[2]] = match[1] === '+' ? 1 : -1;
  return axis;
}

// ---------------------------------------------------------------------------------------------
// Colours: the key in a warm gold, every other part a well-separated hue away from it. A part's
// colour depends on its id only, so the 3D view and the blocking-graph drawing (dbg-panel.js)
// agree without talking to each other.

const KEY_COLOR = new THREE.Color(0xffc21a);
export const KEY_COLOR_CSS = `#${KEY_COLOR.getHexString()}`;
const GOLDEN_RATIO_CONJUGATE = 0.618033988749895;
const GOLD_HUE_BAND = 0.13;

/** The colour of part `partId` (ids start at 1): hues a golden angle apart, two lightness levels. */
export function partColor(partId) {
  const index = Math.max(Math.trunc(Number(partId)) - 1, 0);
  // Golden-ratio steps spread any number of hues evenly; they are squeezed into the circle minus
  // the key's gold (hues 0.07 to 0.2), so no part looks like the key.
  const spread = (0.55 + index * GOLDEN_RATIO_CONJUGATE) % 1;
  const hue = (0.2 + spread * (1 - GOLD_HUE_BAND)) % 1;
  const lightness = index % 2 === 0 ? 0.58 : 0.45;
  const saturation = index % 3 === 2 ? 0.42 : 0.6;
  return new THREE.Color().setHSL(hue, saturation, lightness);
}

/** The CSS colour of part `partId` as drawn: gold when it is the key. */
export function partColorCss(partId, keyId = null) {
  return partId === keyId ? KEY_COLOR_CSS : `#${partColor(partId).getHexString()}`;
}

// ---------------------------------------------------------------------------------------------
// The three.js view

const EDGE_COLOR = 0x101215;
const KEY_EDGE_COLOR = 0xfff3c4;
/** A plate that is a cut point of its design's parts-graph. */
const CUT_POINT_COLOR = new THREE.Color(0xff5a3c);
const CUT_POINT_EDGE_COLOR = 0xffd2c8;
const MOVING_EDGE_COLOR = 0xffffff;
/** The selected part (part list, click, graph): a cool glow and edges no part colour has. */
const SELECTION_COLOR = new THREE.Color(0x4fd1ff);
const SELECTION_GLOW = 0.4;
const NO_GLOW = new THREE.Color(0);
/** The arrows of the part leaving: light, drawn over the parts so they show inside the assembly. */
const ARROW_COLOR = 0xfff3c4;
/**
 * With the tray, a removal step is its path (and run-out) for this share of the step, then the
 * flight over the assembly to the part's place in the tray.
 */
const TRAY_PATH_SHARE = 0.6;
/** A pointer that moves less than this between press and release is a click, not an orbit. */
const CLICK_SLOP_PX = 5;
/** Step by step: the new part's edges and glow, and how see-through the remainder is. */
const HIGHLIGHT_EDGE_COLOR = 0xffffff;
const HIGHLIGHT_GLOW = 0.45;
const GHOST_OPACITY = 0.22;
const GHOST_EDGE_OPACITY = 0.2;
/** At explode factor 1 every part sits this many times farther from the centre than assembled. */
const EXPLODE_SCALE = 1.2;
/** How far a part keeps going after its last move before it disappears, in voxels. */
const RUN_OUT_VOXELS = 2;
/**
 * Documents in their own units (plates in mm) have symbolic removal steps ("along -z"): one step
 * moves a part this fraction of the assembly's largest extent, and the run-out is a fraction too.
 */
const STEP_EXTENT_FRACTION = 0.5;
const RUN_OUT_EXTENT_FRACTION = 0.25;
/** Grid cells per largest extent for documents in their own units (a voxel grid has 1-unit cells). */
const GRID_CELLS_PER_EXTENT = 10;
/** The size of the way-out arrows for documents in their own units (a voxel for voxel puzzles). */
const ARROW_EXTENT_FRACTION = 0.05;

export class AssemblyView {
  #container;
  #notice;
  #renderer = null;
  #scene;
  #camera;
  #controls;
  #lift = new THREE.Group(); // Raises exploded parts above the floor.
  #content = new THREE.Group();
  #meshes = new Map();
  #motions = new Map();
  /** Per part: the direction (and length) it moves at explode factor 1. */
  #explodeOffsets = new Map();
  #floorY = 0;
  #step = 0;
  #exploded = 0;
  #keyId = null;
  /** Lengths in scene units: one removal step, the run-out after the last one, a grid cell. */
  #scale = { step: 1, runOut: RUN_OUT_VOXELS, cell: 1 };
  /** Part names for the hover label (plates have names), and what a part is called. */
  #partNames = new Map();
  #partNoun = 'part';
  #cutPoints = new Set();
  #frameRequest = 0;
  #raycaster = new THREE.Raycaster();
  #hoverLabel = null;
  /** The part list's state: the selected part (or null) and the parts the user hid. */
  #selected = null;
  #hiddenParts = new Set();
  #onPartClick;
  #pointerDown = null;
  /** Playback aids: removed parts laid out in a tray (partId -> translation), arrows of the way out. */
  #trayEnabled = false;
  #arrowsEnabled = false;
  #traySlots = new Map();
  #trayBox = null;
  #removalOrder = [];
  /**
   * A plan of moves of several parts (the report's `steps`, see stepsToPlay), played instead of
   * the removal paths: stepMotions' result, or null.
   */
  #stepPlay = null;
  #arrow = new THREE.Group();
  #arrowKey = '';
  /** What show() measured, to size the grid again once the tray is known. */
  #bounds = null;
  #resizeObserver = null;
  #disposed = false;

  /**
   * `container` receives the canvas (and must have a size). Options: `notice` (an element for
   * messages such as "no WebGL"; one is created in the container when missing), `onWebGL(on)`
   * (told once whether WebGL works), `background` (a CSS colour), `onPartClick(partId)` (a
   * click, not a drag, on the view: the part under the pointer, or null on empty space),
   * `tray` (removed parts are laid out beside the assembly instead of vanishing) and `arrows`
   * (the way out of the part leaving is drawn as arrows).
   * A second argument that is an element is taken as `notice`.
   */
  constructor(container, options = {}) {
    const {
      notice = null, onWebGL = () => {}, background = 0x1b1e24, onPartClick = null, tray = false, arrows = false,
    } = options instanceof Element ? { notice: options } : options;
    this.#container = container;
    this.#onPartClick = onPartClick;
    this.#trayEnabled = Boolean(tray);
    this.#arrowsEnabled = Boolean(arrows);
    const ownerDocument = container.ownerDocument;
    this.#notice = notice ?? this.#makeNotice(ownerDocument);
    try {
      this.#renderer = new THREE.WebGLRenderer({ antialias: true });
    } catch (error) {
      // No WebGL (blocked GPU, old driver): the report still works without a picture.
      this.#showNotice(`3D view unavailable: ${error.message}`);
      onWebGL(false);
      return;
    }
    onWebGL(true);
    const view = ownerDocument.defaultView ?? window;
    this.#renderer.setPixelRatio(Math.min(view.devicePixelRatio || 1, 2));
    this.#renderer.domElement.setAttribute('role', 'img');
    this.#renderer.domElement.setAttribute('aria-label', '3D view of the assembly');
    container.append(this.#renderer.domElement);
    this.#hoverLabel = ownerDocument.createElement('div');
    this.#hoverLabel.className = 'hover-label';
    this.#hoverLabel.hidden = true;
    container.append(this.#hoverLabel);

    this.#scene = new THREE.Scene();
    this.#scene.background = new THREE.Color(background);
    this.#lift.add(this.#content);
    this.#scene.add(this.#lift);
    this.#camera = new THREE.PerspectiveCamera(40, 1, 0.1, 1000);
    this.#addLights();

    this.#controls = new OrbitControls(this.#camera, this.#renderer.domElement);
    this.#controls.addEventListener('change', () => this.requestRender());
    this.#renderer.domElement.addEventListener('pointermove', (event) => this.#updateHover(event));
    this.#renderer.domElement.addEventListener('pointerleave', () => { this.#hoverLabel.hidden = true; });
    this.#renderer.domElement.addEventListener('pointerdown', (event) => {
      this.#pointerDown = event.button === 0 ? { x: event.clientX, y: event.clientY } : null;
    });
    this.#renderer.domElement.addEventListener('pointerup', (event) => this.#handleClick(event));
    this.#renderer.domElement.addEventListener('dblclick', () => this.fit());
    this.#resizeObserver = new ResizeObserver(() => this.#resize());
    this.#resizeObserver.observe(container);
    this.#resize();
  }

  get available() {
    return this.#renderer !== null && !this.#disposed;
  }

  /** The disassembly step shown (0 = assembled; see setDisassemblyStep). */
  get disassemblyStep() {
    return this.#step;
  }

  /**
   * Playing a plan of moves (the report's `steps`): the parts of the move shown (moving now, or
   * the move just made at a whole step), else an empty list.
   */
  get movingParts() {
    const index = this.#currentMove();
    return index >= 0 ? [...this.#stepPlay.moving[index]] : [];
  }

  /** The move shown when playing `steps`: the one under way, or just made at a whole step; -1 for none. */
  #currentMove() {
    if (!this.#stepPlay || this.#step <= 0) return -1;
    return Math.min(Math.ceil(this.#step - 1e-9), this.#stepPlay.steps.length) - 1;
  }

  get exploded() {
    return this.#exploded;
  }

  #makeNotice(ownerDocument) {
    const notice = ownerDocument.createElement('p');
    notice.className = 'viewer-notice';
    notice.hidden = true;
    this.#container.append(notice);
    return notice;
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

  /**
   * Draws a parsed document with its part surfaces (desia.partSurfaces of that document: an
   * array of { partId, positions, normals }); `applyReport` adds what the check found.
   * `keepCamera`: leave the camera where the user put it (step by step: every child of a session
   * is seen from the same place, so they compare at one zoom); the first assembly is still framed.
   */
  show(document_, surfaces, { keepCamera = false } = {}) {
    const kept = keepCamera ? this.#framed : null;
    this.clear();
    if (!this.available) return;
    const voxel = document_?.kind === 'voxel' && document_.voxel;
    // Plates (and any other kind the core gives surfaces for) are drawn in their own units.
    if (!voxel && !(Array.isArray(surfaces) && surfaces.length > 0)) {
      this.#showNotice(`No 3D view for "${document_?.kind ?? 'unknown'}" documents yet.`);
      return;
    }
    const { centroids, min, max } = voxel ? voxelExtents(document_.voxel.size, document_.voxel.labels) : surfaceExtents(surfaces);
    if (centroids.size === 0) {
      this.#showNotice(voxel ? 'The assembly has no voxels.' : 'The assembly has no part surfaces.');
      return;
    }
    if (!Array.isArray(surfaces)) {
      this.#showNotice('No part surfaces were given for this assembly.');
      return;
    }
    const extent = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
    this.#scale = voxel
      ? { step: 1, runOut: RUN_OUT_VOXELS, cell: 1, arrow: 1 }
      : {
        step: extent * STEP_EXTENT_FRACTION,
        runOut: extent * RUN_OUT_EXTENT_FRACTION,
        cell: niceStep(extent / GRID_CELLS_PER_EXTENT),
        arrow: extent * ARROW_EXTENT_FRACTION,
      };
    this.#partNoun = document_?.kind === 'plate' ? 'plate' : document_?.kind === 'frame' ? 'beam' : 'part';
    for (const plate of Array.isArray(document_?.plates) ? document_.plates : []) {
      if (Number.isInteger(plate?.id) && typeof plate.name === 'string' && plate.name) this.#partNames.set(plate.id, plate.name);
    }
    // A designed frame's beams keep the id they had in the input.
    for (const beam of document_?.kind === 'frame' && Array.isArray(document_.beams) ? document_.beams : []) {
      if (Number.isInteger(beam?.id) && Number.isInteger(beam.inputId) && beam.inputId !== beam.id) {
        this.#partNames.set(beam.id, `input beam ${beam.inputId}`);
      }
    }
    if (document_?.kind === 'frame') this.#partNames.set(0, 'joint cubes (no joints designed yet)');
    // Whole-cell offsets keep voxel boundaries (and round plate coordinates) on the grid lines.
    const cell = this.#scale.cell;
    const snap = (value) => Math.floor(value / cell) * cell;
    const offset = new THREE.Vector3(-snap((min[0] + max[0]) / 2), -min[1], -snap((min[2] + max[2]) / 2));
    this.#content.position.copy(offset);
    this.#floorY = min[1] + offset.y;
    this.#addParts(surfaces, centroids, min, max);
    this.#content.add(this.#arrow);
    this.#bounds = { min, max, offset };
    this.#addGrid(min, max, offset);
    this.#container.dataset.parts = String(this.#meshes.size);
    this.#updatePositions();
    // The explode factor outlives the assembly: frame what is actually shown.
    if (kept) this.#framed = kept;
    else this.#fitCamera(this.#framingBox());
  }

  /** Frames the assembly again from the usual three-quarter view (double-click on the view). */
  fit() {
    if (!this.available || this.#meshes.size === 0) return;
    if (this.#step === 0) this.#widened = false; // assembled: the assembly alone again
    this.#fitCamera(this.#framingBox());
    this.requestRender();
  }

  /**
   * Step by step: the parts in `highlight` (the new part) glow with bright edges, those in
   * `ghost` (the remainder not yet split) are drawn see-through; the others as the report left
   * them. Call after applyReport. The container's data-highlight / data-ghost list them.
   */
  setEmphasis({ highlight = [], ghost = [] } = {}) {
    if (!this.available) return;
    const glowing = new Set(highlight);
    const ghosted = new Set(ghost);
    for (const [partId, mesh] of this.#meshes) {
      if (ghosted.has(partId)) {
        mesh.userData.baseOpacity = GHOST_OPACITY;
        mesh.userData.baseEdgeOpacity = GHOST_EDGE_OPACITY;
      } else if (glowing.has(partId)) {
        mesh.userData.emissive = mesh.material.color.clone().multiplyScalar(HIGHLIGHT_GLOW);
        mesh.userData.edgeColor = HIGHLIGHT_EDGE_COLOR;
        mesh.userData.baseEdgeOpacity = 1;
      }
    }
    this.#container.dataset.highlight = [...glowing].join(' ');
    this.#container.dataset.ghost = [...ghosted].join(' ');
    this.#updatePositions();
  }

  #addParts(surfaces, centroids, min, max) {
    const center = new THREE.Vector3(...min).add(new THREE.Vector3(...max)).multiplyScalar(0.5);
    for (const surface of [...surfaces].sort((a, b) => a.partId - b.partId)) {
      const { partId } = surface;
      const sums = centroids.get(partId);
      if (!sums) continue;
      const geometry = surfaceGeometry(surface);
      const material = new THREE.MeshStandardMaterial({
        color: partColor(partId),
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
      mesh.userData.edgeColor = EDGE_COLOR;
      const edges = new THREE.LineSegments(
        new THREE.EdgesGeometry(geometry, 30),
        new THREE.LineBasicMaterial({ color: EDGE_COLOR, transparent: true, opacity: 0.55 }),
      );
      mesh.add(edges);
      this.#content.add(mesh);
      this.#meshes.set(partId, mesh);
      // Exploded view: every part moves away from the assembly's centre along the line through
      // its centroid, proportionally to its distance (the usual exploded drawing).
      const centroid = new THREE.Vector3(...sums.voxelSum).divideScalar(sums.voxelCount);
      this.#explodeOffsets.set(partId, centroid.sub(center).multiplyScalar(EXPLODE_SCALE));
    }
  }

  /** The floor grid under the assembly (and under the tray, `trayBox` in the content's frame). */
  #addGrid(min, max, offset, trayBox = null) {
    const { cell } = this.#scale;
    const old = this.#scene.getObjectByName('grid');
    if (old) {
      old.geometry.dispose();
      old.material.dispose();
      this.#scene.remove(old);
    }
    const extent = (Math.max(max[0] - min[0], max[2] - min[2]) * (1 + EXPLODE_SCALE)) / cell;
    // An even number of cells keeps grid lines on whole cells, i.e. on voxel boundaries.
    let divisions = 2 * Math.ceil((extent + 4) / 2);
    if (trayBox) {
      // The grid stays centred on the assembly, so it reaches as far as the tray's farthest corner.
      const reach = Math.max(
        Math.abs(trayBox.min.x + offset.x), Math.abs(trayBox.max.x + offset.x),
        Math.abs(trayBox.min.z + offset.z), Math.abs(trayBox.max.z + offset.z),
      );
      divisions = Math.max(divisions, 2 * Math.ceil(reach / cell + 2));
    }
    const grid = new THREE.GridHelper(divisions * cell, divisions, 0x59606e, 0x353a44);
    grid.name = 'grid';
    grid.position.set(0, min[1] + offset.y - 0.001 * cell, 0);
    this.#scene.add(grid);
  }

  /** Puts the camera in front of `box` from the usual three-quarter view. */
  #fitCamera(box) {
    const center = box.getCenter(new THREE.Vector3());
    const distance = this.#fitDistance(box);
    const viewDirection = new THREE.Vector3(1, 0.85, 1.5).normalize();
    this.#camera.position.copy(center).addScaledVector(viewDirection, distance);
    this.#controls.target.copy(center);
    this.#setDepthRange(distance);
    this.#controls.update();
    this.#framed = { center, distance };
  }

  /** What the camera was last fitted to, so explode changes can keep the same framing. */
  #framed = null;

  /**
   * Whether the framing takes in the removal paths and the tray: not until the disassembly is
   * played (a step past 0), so that a result first fills the view; playing widens it once.
   */
  #widened = false;

  #fitDistance(box) {
    const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1);
    // The narrower of the vertical and horizontal fields of view decides what fits.
    const verticalHalfFov = THREE.MathUtils.degToRad(this.#camera.fov / 2);
    const horizontalHalfFov = Math.atan(Math.tan(verticalHalfFov) * this.#camera.aspect);
    return (radius / Math.sin(Math.min(verticalHalfFov, horizontalHalfFov))) * 1.25;
  }

  #setDepthRange(distance) {
    this.#camera.near = distance / 100;
    this.#camera.far = distance * 50;
    this.#camera.updateProjectionMatrix();
    this.#controls.maxDistance = distance * 10;
  }

  /**
   * Highlights the key (or, on failure, the cut points of a plate design, else the witness
   * group) and prepares the removal animation.
   */
  applyReport(report, { keepCamera = false } = {}) {
    if (!this.available) return;
    if (!keepCamera) this.#widened = false;
    this.#keyId = report?.key ?? null;
    // A plate design without joints is not interlocking by nature: greying out all but its
    // witness would hide the design. Its cut points (no joints can help) are marked instead.
    const plate = report?.kind === 'plate';
    // The same for a frame without joints: its beams merely touch.
    const structure = plate || report?.kind === 'frame';
    const witnessParts = new Set(structure ? [] : (report?.witness?.parts ?? []));
    // Cut points: a plate's from its check; a frame's once the core's frame check reports them.
    this.#cutPoints = new Set(structure ? (report?.cutPoints ?? []) : []);
    for (const [partId, mesh] of this.#meshes) {
      const isKey = partId === this.#keyId;
      const isCut = this.#cutPoints.has(partId);
      const dimmed = witnessParts.size > 0 && !witnessParts.has(partId);
      const material = mesh.material;
      const edges = mesh.children[0].material;
      const color = isKey ? KEY_COLOR : (isCut ? CUT_POINT_COLOR : null);
      material.color.copy(color ?? partColor(partId));
      mesh.userData.emissive = (color ?? new THREE.Color(0)).clone().multiplyScalar(color ? 0.35 : 0);
      mesh.userData.edgeColor = isKey ? KEY_EDGE_COLOR : (isCut ? CUT_POINT_EDGE_COLOR : EDGE_COLOR);
      edges.color.set(mesh.userData.edgeColor);
      mesh.userData.baseEdgeOpacity = dimmed ? 0.12 : (color ? 1 : 0.55);
      mesh.userData.baseOpacity = dimmed ? 0.18 : 1;
      material.needsUpdate = true;
    }
    // A plan that moves parts together plays its moves; any other its removal order and paths.
    const steps = stepsToPlay(report?.disassembly) ?? stepsToPlay(report?.disassemblyFailure);
    if (steps && this.#meshes.size > 0) {
      const boxes = new Map([...this.#meshes].map(([partId, mesh]) => [partId, mesh.geometry.boundingBox]));
      this.#stepPlay = stepMotions(steps, boxes, this.#scale);
      this.#motions = new Map();
      this.#removalOrder = [...this.#stepPlay.leaves.keys()];
    } else {
      this.#stepPlay = null;
      this.#motions = removalMotions(report ?? {}, this.#scale);
      this.#removalOrder = [...(report?.disassembly?.order ?? [])];
    }
    this.#layOutTray();
    this.setDisassemblyStep(0);
    // Parts leaving along their paths should stay in the picture: frame their way out too.
    if (!keepCamera && (this.#motions.size > 0 || this.#stepPlay) && this.#meshes.size > 0) this.#fitCamera(this.#framingBox());
  }

  /**
   * Shows the disassembly at `step` (0 = assembled): the part at position i of the order is on
   * its way out while step is between i and i + 1, and gone after that. Only the last part,
   * which has no path, stays.
   */
  setDisassemblyStep(step) {
    this.#step = Number.isFinite(step) ? Math.max(step, 0) : 0;
    this.#updatePositions();
    // The first step of a played disassembly widens the framing to the paths and the tray.
    if (this.#step > 0 && !this.#widened && this.#meshes.size > 0) {
      this.#widened = true;
      this.#reframe();
    }
  }

  /**
   * Exploded view, composable with the disassembly: 0 = assembled, 1 = every part
   * 1 + EXPLODE_SCALE times as far from the centre. The camera keeps its direction and zoom
   * relative to the assembly's size, so the whole exploded assembly stays in view.
   */
  setExploded(factor) {
    const clamped = THREE.MathUtils.clamp(Number(factor) || 0, 0, 1);
    if (clamped === this.#exploded) return;
    this.#exploded = clamped;
    this.#updatePositions();
    this.#reframe();
  }

  /**
   * Every mesh at its exploded position plus its removal motion (or in the tray once removed);
   * the moving part and the selected part outlined, hidden parts left out, the arrows updated.
   */
  #updatePositions() {
    if (!this.available) return;
    // Exploding moves the lower parts down: lift everything so the lowest stays on the floor.
    const assembly = this.#explodedBox();
    const lift = Math.max(this.#floorY - assembly.min.y, 0);
    this.#lift.position.y = lift;
    const top = assembly.max.y - this.#content.position.y;
    let visible = 0;
    let inTray = 0;
    for (const [partId, mesh] of this.#meshes) {
      const placement = this.#placement(partId, mesh, lift, top);
      mesh.visible = placement.visible && !this.#hiddenParts.has(partId);
      mesh.userData.inTray = placement.inTray;
      mesh.position.copy(placement.position);
      this.#setFade(mesh, placement.fade);
      const selected = partId === this.#selected;
      const glow = placement.marked ? mesh.material.color.clone().multiplyScalar(HIGHLIGHT_GLOW) : (mesh.userData.emissive ?? NO_GLOW);
      mesh.material.emissive.copy(selected ? SELECTION_COLOR : glow).multiplyScalar(selected ? SELECTION_GLOW : 1);
      const edges = mesh.children[0].material;
      edges.color.set(selected ? SELECTION_COLOR : (placement.moving || placement.marked ? MOVING_EDGE_COLOR : mesh.userData.edgeColor));
      if (selected || placement.marked) edges.opacity = 1;
      if (mesh.visible) visible += 1;
      if (placement.inTray) inTray += 1;
    }
    this.#updateArrow();
    const move = this.#currentMove();
    Object.assign(this.#container.dataset, {
      step: this.#step.toFixed(2),
      move: move >= 0 ? String(move + 1) : '',
      moving: this.movingParts.join(' '),
      exploded: this.#exploded.toFixed(2),
      visible: String(visible),
      tray: String(inTray),
      selected: this.#selected === null ? '' : String(this.#selected),
      hidden: [...this.#hiddenParts].sort((a, b) => a - b).join(' '),
    });
    this.requestRender();
  }

  /**
   * Where part `partId` is at the current step, as the translation of its mesh: { position,
   * visible, fade, moving, inTray }. Without a tray a removed part runs out, fades and vanishes;
   * with one it follows its path, then flies over the assembly (`top`: its highest point in the
   * content's frame) to its place in the tray, on the floor (`lift` taken back).
   */
  #placement(partId, mesh, lift, top) {
    if (this.#stepPlay) return this.#stepPlacement(partId, mesh, lift, top);
    const exploded = this.#explodeOffsets.get(partId).clone().multiplyScalar(this.#exploded);
    const motion = this.#motions.get(partId);
    if (!motion) return { position: exploded, visible: true, fade: 1, moving: false, inTray: false };
    const progress = THREE.MathUtils.clamp(this.#step - motion.index, 0, 1);
    const slot = this.#traySlots.get(partId);
    if (!slot) {
      // Past the end of its path the part runs out and fades away.
      const fade = progress > motion.fadeFrom && motion.fadeFrom < 1 ? 1 - (progress - motion.fadeFrom) / (1 - motion.fadeFrom) : 1;
      return {
        position: exploded.add(pointAlong(motion.waypoints, progress)),
        visible: progress < 1 || motion.waypoints.length === 1,
        fade,
        moving: progress > 0 && progress < 1,
        inTray: false,
      };
    }
    const resting = slot.clone().setY(slot.y - lift);
    resting.x += this.#trayShift();
    if (progress >= 1) return { position: resting, visible: true, fade: 1, moving: false, inTray: true };
    if (progress <= TRAY_PATH_SHARE) {
      return { position: exploded.add(pointAlong(motion.waypoints, progress / TRAY_PATH_SHARE)), visible: true, fade: 1, moving: progress > 0, inTray: false };
    }
    // Up from where its way out ended, across above everything, down into the tray.
    const from = exploded.add(motion.waypoints[motion.waypoints.length - 1]);
    const above = Math.max(from.y, resting.y, top - mesh.geometry.boundingBox.min.y + this.#scale.cell);
    const flight = [from, new THREE.Vector3(from.x, above, from.z), new THREE.Vector3(resting.x, above, resting.z), resting];
    return { position: pointAlong(flight, (progress - TRAY_PATH_SHARE) / (1 - TRAY_PATH_SHARE)), visible: true, fade: 1, moving: true, inTray: false };
  }

  /**
   * #placement for a plan of moves: between whole steps i and i + 1 the parts of move i slide
   * from where the moves before put them by the move's offset (stepMotions); the others stand
   * still. A single part going out then flies to its place in the tray (without a tray it runs
   * out and fades), as a removed part does; a group going out stays where it went. `marked`: the
   * part belongs to the move shown (#currentMove), which glows.
   */
  #stepPlacement(partId, mesh, lift, top) {
    const play = this.#stepPlay;
    const exploded = this.#explodeOffsets.get(partId).clone().multiplyScalar(this.#exploded);
    const count = play.steps.length;
    const step = THREE.MathUtils.clamp(this.#step, 0, count);
    const index = Math.min(Math.floor(step), count - 1);
    const progress = step - index;
    const current = this.#currentMove();
    const marked = current >= 0 && play.moving[current].has(partId);
    const left = play.leaves.get(partId);
    const base = play.before[index].get(partId) ?? new THREE.Vector3();
    const slot = this.#traySlots.get(partId);
    if (left !== undefined && (left < index || (left === index && progress >= 1))) {
      if (!slot) return { position: exploded.add(base), visible: false, fade: 0, moving: false, marked, inTray: false };
      const resting = slot.clone().setY(slot.y - lift);
      resting.x += this.#trayShift();
      return { position: resting, visible: true, fade: 1, moving: false, marked, inTray: true };
    }
    const still = { position: exploded.clone().add(base), visible: true, fade: 1, moving: false, marked, inTray: false };
    if (progress <= 0 || !play.moving[index].has(partId)) return still;
    const delta = play.deltas[index];
    if (left !== index) return { ...still, position: exploded.add(base).addScaledVector(delta, progress), moving: true };
    if (!slot) {
      // Out and on a little further, fading away over that last stretch.
      const runOut = delta.clone().setLength(this.#scale.runOut);
      const waypoints = [base.clone(), base.clone().add(delta), base.clone().add(delta).add(runOut)];
      const fadeFrom = delta.length() / (delta.length() + runOut.length());
      const fade = progress > fadeFrom ? 1 - (progress - fadeFrom) / (1 - fadeFrom) : 1;
      return { ...still, position: exploded.add(pointAlong(waypoints, progress)), fade, moving: true };
    }
    const resting = slot.clone().setY(slot.y - lift);
    resting.x += this.#trayShift();
    if (progress <= TRAY_PATH_SHARE) {
      return { ...still, position: exploded.add(base).addScaledVector(delta, progress / TRAY_PATH_SHARE), moving: true };
    }
    const from = exploded.add(base).add(delta);
    const above = Math.max(from.y, resting.y, top - mesh.geometry.boundingBox.min.y + this.#scale.cell);
    const flight = [from, new THREE.Vector3(from.x, above, from.z), new THREE.Vector3(resting.x, above, resting.z), resting];
    return { ...still, position: pointAlong(flight, (progress - TRAY_PATH_SHARE) / (1 - TRAY_PATH_SHARE)), moving: true };
  }

  /**
   * The tray: every part that leaves gets a place on the floor beside the assembly, in removal
   * order, in rows (layOutTray). Only where it lands is computed here; the moves are the core's.
   */
  #layOutTray() {
    this.#traySlots = new Map();
    this.#trayBox = null;
    if (!this.#trayEnabled || !this.#bounds) return;
    const leaving = this.#removalOrder
      .filter((partId) => this.#meshes.has(partId) && (this.#stepPlay?.leaves.has(partId) || (this.#motions.get(partId)?.waypoints.length ?? 0) > 1))
      .map((partId) => ({ partId, box: this.#meshes.get(partId).geometry.boundingBox }));
    if (leaving.length === 0) return;
    const { min, max, offset } = this.#bounds;
    const tray = layOutTray(leaving, { min, max }, this.#scale.cell);
    this.#traySlots = tray.slots;
    this.#trayBox = tray.box;
    // The grid reaches the tray where the fully exploded assembly pushes it.
    this.#addGrid(min, max, offset, tray.box.clone().translate(new THREE.Vector3(this.#trayShift(1), 0, 0)));
  }

  /**
   * How far the tray moves out (+x) at explode factor `exploded`, so that the exploded assembly
   * never reaches it: as far as the assembly's half width grows, in whole grid cells.
   */
  #trayShift(exploded = this.#exploded) {
    if (!this.#bounds) return 0;
    const halfWidth = (this.#bounds.max[0] - this.#bounds.min[0]) / 2;
    return Math.ceil((halfWidth * EXPLODE_SCALE * exploded) / this.#scale.cell - 1e-9) * this.#scale.cell;
  }

  /**
   * Arrows along the way out of the part leaving now (or next, between two removals): a shaft and
   * a head per move of its path from the core, the run-out included, from the part's centre.
   */
  #updateArrow() {
    if (this.#stepPlay) {
      this.#updateMoveArrow();
      return;
    }
    const index = Math.floor(this.#step);
    const partId = this.#arrowsEnabled && this.#step > 0 ? this.#removalOrder[index] : undefined;
    const motion = partId === undefined ? null : this.#motions.get(partId);
    const mesh = this.#meshes.get(partId);
    const show = Boolean(motion && mesh && motion.waypoints.length > 1 && !this.#hiddenParts.has(partId));
    const key = show ? `${partId}@${this.#exploded}` : '';
    this.#container.dataset.arrow = show ? String(partId) : '';
    if (key === this.#arrowKey) return;
    this.#arrowKey = key;
    disposeChildren(this.#arrow);
    if (!show) return;
    const start = mesh.geometry.boundingBox.getCenter(new THREE.Vector3())
      .add(this.#explodeOffsets.get(partId).clone().multiplyScalar(this.#exploded));
    this.#drawArrow(motion.waypoints.map((point) => start.clone().add(point)));
  }

  /**
   * #updateArrow for a plan of moves: one arrow for the move shown, from the centre of the parts
   * moved together (where the moves before put them) along the move (data-arrow lists the parts).
   */
  #updateMoveArrow() {
    const index = this.#currentMove();
    const parts = this.#arrowsEnabled && index >= 0
      ? [...this.#stepPlay.moving[index]].filter((partId) => this.#meshes.has(partId) && !this.#hiddenParts.has(partId)) : [];
    const delta = index >= 0 ? this.#stepPlay.deltas[index] : null;
    const show = parts.length > 0 && delta.lengthSq() > 0;
    const key = show ? `move ${index}@${this.#exploded}` : '';
    this.#container.dataset.arrow = show ? parts.join(' ') : '';
    if (key === this.#arrowKey) return;
    this.#arrowKey = key;
    disposeChildren(this.#arrow);
    if (!show) return;
    const box = new THREE.Box3();
    for (const partId of parts) {
      box.union(this.#meshes.get(partId).geometry.boundingBox.clone()
        .translate(this.#stepPlay.before[index].get(partId))
        .translate(this.#explodeOffsets.get(partId).clone().multiplyScalar(this.#exploded)));
    }
    const start = box.getCenter(new THREE.Vector3());
    this.#drawArrow([start, start.clone().add(delta)]);
  }

  /** Arrows (a shaft and a head per segment) along `points`, in the content's frame. */
  #drawArrow(points) {
    const size = this.#scale.arrow ?? 1;
    const material = new THREE.MeshBasicMaterial({ color: ARROW_COLOR, depthTest: false, transparent: true, opacity: 0.9 });
    for (let i = 1; i < points.length; i += 1) {
      const direction = points[i].clone().sub(points[i - 1]);
      const length = direction.length();
      if (!(length > 0)) continue;
      direction.divideScalar(length);
      const headLength = Math.min(0.7 * size, 0.6 * length);
      const turn = new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 1, 0), direction);
      const shaft = new THREE.Mesh(new THREE.CylinderGeometry(0.09 * size, 0.09 * size, length - headLength, 8), material);
      shaft.position.copy(points[i - 1]).addScaledVector(direction, (length - headLength) / 2);
      shaft.quaternion.copy(turn);
      const head = new THREE.Mesh(new THREE.ConeGeometry(0.3 * size, headLength, 12), material);
      head.position.copy(points[i]).addScaledVector(direction, -headLength / 2);
      head.quaternion.copy(turn);
      for (const piece of [shaft, head]) {
        piece.renderOrder = 10;
        this.#arrow.add(piece);
      }
    }
  }

  /** Multiplies the part's own opacity (1, or dimmed for a witness) by `fade`. */
  #setFade(mesh, fade) {
    const material = mesh.material;
    const base = mesh.userData.baseOpacity ?? 1;
    const opacity = base * fade;
    const transparent = opacity < 1;
    if (material.transparent !== transparent) material.needsUpdate = true;
    material.transparent = transparent;
    material.opacity = opacity;
    material.depthWrite = !transparent;
    mesh.children[0].material.opacity = (mesh.userData.baseEdgeOpacity ?? 0.55) * fade;
  }

  /**
   * What the camera frames: the parts as exploded; once the disassembly is played (#widened), also
   * where their removal paths take them and the tray.
   */
  #framingBox() {
    const box = this.#explodedBox();
    if (!this.#widened) return box.translate(new THREE.Vector3(0, this.#lift.position.y, 0));
    const partBox = new THREE.Box3();
    for (const [partId, mesh] of this.#meshes) {
      const motion = this.#motions.get(partId);
      if (!motion || motion.waypoints.length < 2) continue;
      partBox.copy(mesh.geometry.boundingBox)
        .translate(this.#content.position)
        .translate(this.#explodeOffsets.get(partId).clone().multiplyScalar(this.#exploded))
        .translate(motion.pathEnd);
      box.union(partBox);
    }
    // A plan of moves: wherever its parts go before they leave (groups that went out stay there).
    if (this.#stepPlay) box.union(this.#stepPlay.framing.clone().translate(this.#content.position));
    box.translate(new THREE.Vector3(0, this.#lift.position.y, 0));
    // The tray lies on the floor: what is removed stays in the picture.
    if (this.#trayBox) box.union(this.#trayBox.clone().translate(this.#content.position).translate(new THREE.Vector3(this.#trayShift(), 0, 0)));
    return box;
  }

  /** The bounds of all parts at the current explode factor, before the lift (removal motions left out). */
  #explodedBox() {
    const box = new THREE.Box3();
    const partBox = new THREE.Box3();
    for (const [partId, mesh] of this.#meshes) {
      partBox.copy(mesh.geometry.boundingBox)
        .translate(this.#content.position)
        .translate(this.#explodeOffsets.get(partId).clone().multiplyScalar(this.#exploded));
      box.union(partBox);
    }
    return box;
  }

  /** Keeps the user's viewing direction and relative zoom while the exploded assembly grows or shrinks. */
  #reframe() {
    if (!this.#framed || this.#meshes.size === 0) return;
    const box = this.#framingBox();
    const center = box.getCenter(new THREE.Vector3());
    const distance = this.#fitDistance(box);
    const ratio = distance / this.#framed.distance;
    const offset = this.#camera.position.clone().sub(this.#controls.target).multiplyScalar(ratio);
    this.#controls.target.copy(center);
    this.#camera.position.copy(center).add(offset);
    this.#setDepthRange(Math.max(distance, offset.length()));
    this.#controls.update();
    this.#framed = { center, distance };
    this.requestRender();
  }

  /**
   * How the view is framed (for tests and debugging), in scene units (the document's: voxels,
   * or mm for plates): the camera's distance to its target, the grid cell, one removal step.
   */
  framing() {
    return {
      distance: this.available ? this.#camera.position.distanceTo(this.#controls.target) : 0,
      camera: this.available ? this.#camera.position.toArray() : null,
      target: this.available ? this.#controls.target.toArray() : null,
      gridCell: this.#scale.cell,
      removalStep: this.#scale.step,
      widened: this.#widened,
      ...this.#screenFill(),
    };
  }

  /**
   * The share of the view's width and height the visible parts cover on screen (0..1 each; the
   * box around their projected bounding-box corners, clipped to the view).
   */
  #screenFill() {
    if (!this.available || this.#meshes.size === 0) return { fillWidth: 0, fillHeight: 0 };
    this.#camera.updateMatrixWorld();
    this.#scene.updateMatrixWorld();
    const box = new THREE.Box3();
    const corner = new THREE.Vector3();
    let minX = Infinity; let maxX = -Infinity; let minY = Infinity; let maxY = -Infinity;
    for (const mesh of this.#meshes.values()) {
      if (!mesh.visible) continue;
      box.copy(mesh.geometry.boundingBox).applyMatrix4(mesh.matrixWorld);
      for (let k = 0; k < 8; k += 1) {
        corner.set(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z).project(this.#camera);
        minX = Math.min(minX, corner.x); maxX = Math.max(maxX, corner.x);
        minY = Math.min(minY, corner.y); maxY = Math.max(maxY, corner.y);
      }
    }
    const clip = (value) => Math.min(Math.max(value, -1), 1);
    if (!Number.isFinite(minX)) return { fillWidth: 0, fillHeight: 0 };
    return { fillWidth: (clip(maxX) - clip(minX)) / 2, fillHeight: (clip(maxY) - clip(minY)) / 2 };
  }

  /**
   * Positions of the visible parts still in the assembly or on their way out (for tests and
   * debugging; removed parts in the tray are trayPositions()): { partId: [x, y, z] } in scene units.
   */
  partPositions() {
    return this.#positions((mesh) => mesh.visible && !mesh.userData.inTray);
  }

  /** Positions of the removed parts lying in the tray, as partPositions() gives them. */
  trayPositions() {
    return this.#positions((mesh) => mesh.visible && mesh.userData.inTray);
  }

  /** The bounds of the parts as assembled, in scene units: { min, max } (for tests: the tray lies outside). */
  assemblyBounds() {
    const box = this.#explodedBox().translate(new THREE.Vector3(0, this.#lift.position.y, 0));
    return { min: box.min.toArray(), max: box.max.toArray() };
  }

  /** Part `partId`'s bounds where it is drawn now, in scene units: { min, max } (null when not drawn). */
  partBounds(partId) {
    const mesh = this.#meshes.get(partId);
    if (!this.available || !mesh?.visible) return null;
    mesh.updateWorldMatrix(true, false);
    const box = mesh.geometry.boundingBox.clone().applyMatrix4(mesh.matrixWorld);
    return { min: box.min.toArray(), max: box.max.toArray() };
  }

  /** The part ids drawn, ascending. */
  get partIds() {
    return [...this.#meshes.keys()];
  }

  get selectedPart() {
    return this.#selected;
  }

  /** Selects part `partId` (null: none): it glows and its edges are drawn in the selection colour. */
  setSelection(partId) {
    this.#selected = Number.isInteger(partId) ? partId : null;
    if (this.available) this.#updatePositions();
  }

  /** The parts not to draw (the part list's Hide and Isolate); all others are shown. */
  setHiddenParts(partIds) {
    this.#hiddenParts = new Set([...(partIds ?? [])].filter((partId) => this.#meshes.has(partId)));
    if (this.available) this.#updatePositions();
  }

  /** The part drawn at client coordinates (x, y), or null: what a click there would pick. */
  partAt(clientX, clientY) {
    if (!this.available) return null;
    const bounds = this.#renderer.domElement.getBoundingClientRect();
    if (!(bounds.width > 0 && bounds.height > 0)) return null;
    const pointer = new THREE.Vector2(
      ((clientX - bounds.left) / bounds.width) * 2 - 1,
      -((clientY - bounds.top) / bounds.height) * 2 + 1,
    );
    this.#raycaster.setFromCamera(pointer, this.#camera);
    // See-through parts (a witness's others, a session's remainder) let the pointer through.
    const hit = this.#raycaster
      .intersectObjects([...this.#meshes.values()], false)
      .find((candidate) => candidate.object.visible && (candidate.object.userData.baseOpacity ?? 1) === 1);
    return hit ? hit.object.userData.partId : null;
  }

  /** Where the centre of part `partId`'s bounding box is on the screen, in client coordinates (or null). */
  screenPoint(partId) {
    const mesh = this.#meshes.get(partId);
    if (!this.available || !mesh?.visible) return null;
    mesh.updateWorldMatrix(true, false);
    const centre = mesh.geometry.boundingBox.getCenter(new THREE.Vector3()).applyMatrix4(mesh.matrixWorld).project(this.#camera);
    const bounds = this.#renderer.domElement.getBoundingClientRect();
    return { x: bounds.left + ((centre.x + 1) / 2) * bounds.width, y: bounds.top + ((1 - centre.y) / 2) * bounds.height };
  }

  #positions(include) {
    const positions = {};
    const world = new THREE.Vector3();
    for (const [partId, mesh] of this.#meshes) {
      if (!include(mesh)) continue;
      mesh.getWorldPosition(world);
      positions[partId] = world.toArray().map((value) => Math.round(value * 1000) / 1000);
    }
    return positions;
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
    this.#explodeOffsets.clear();
    this.#keyId = null;
    this.#cutPoints = new Set();
    // The selection and the hidden parts stay (they are the part list's, which sets them again
    // for every assembly it lists; a live design redraws the view many times in between).
    this.#traySlots = new Map();
    this.#trayBox = null;
    this.#removalOrder = [];
    this.#stepPlay = null;
    disposeChildren(this.#arrow);
    this.#arrowKey = '';
    this.#bounds = null;
    this.#partNames.clear();
    this.#partNoun = 'part';
    this.#step = 0;
    this.#framed = null;
    this.#lift.position.set(0, 0, 0);
    if (!this.available) return;
    this.#showNotice('');
    const grid = this.#scene.getObjectByName('grid');
    if (grid) {
      grid.geometry.dispose();
      grid.material.dispose();
      this.#scene.remove(grid);
    }
    this.#container.dataset.parts = '0';
    this.#container.dataset.highlight = '';
    this.#container.dataset.ghost = '';
    Object.assign(this.#container.dataset, { visible: '0', tray: '0', arrow: '', hover: '', move: '', moving: '' });
    this.requestRender();
  }

  /** Frees the GPU resources and removes the canvas; the view cannot be used afterwards. */
  dispose() {
    if (this.#disposed) return;
    this.clear();
    this.#disposed = true;
    if (this.#frameRequest) cancelAnimationFrame(this.#frameRequest);
    this.#frameRequest = 0;
    this.#resizeObserver?.disconnect();
    this.#controls?.dispose();
    if (this.#renderer) {
      this.#renderer.dispose();
      this.#renderer.forceContextLoss();
      this.#renderer.domElement.remove();
    }
    this.#hoverLabel?.remove();
  }

  /** Renders on demand (at most once per frame) instead of spinning a render loop. */
  requestRender() {
    if (!this.available || this.#frameRequest) return;
    this.#frameRequest = requestAnimationFrame(() => {
      this.#frameRequest = 0;
      if (this.available) this.#renderer.render(this.#scene, this.#camera);
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
    const partId = this.partAt(event.clientX, event.clientY);
    this.#hoverLabel.hidden = partId === null;
    this.#container.dataset.hover = partId === null ? '' : String(partId);
    if (partId !== null) this.#hoverLabel.textContent = this.describePart(partId);
  }

  /** 'part 3 (key)', 'plate 2: left side', 'beam 5: input beam 7': what the hover label says. */
  describePart(partId) {
    const name = this.#partNames.get(partId);
    const role = partId === this.#keyId ? ' (key)' : (this.#cutPoints.has(partId) ? ' (cut point)' : '');
    return `${this.#partNoun} ${partId}${role}${name ? `: ${name}` : ''}`;
  }

  /** A click (press and release in about one place, so not an orbit) picks the part under it. */
  #handleClick(event) {
    const down = this.#pointerDown;
    this.#pointerDown = null;
    if (!down || !this.#onPartClick || this.#meshes.size === 0) return;
    if (Math.hypot(event.clientX - down.x, event.clientY - down.y) > CLICK_SLOP_PX) return;
    this.#onPartClick(this.partAt(event.clientX, event.clientY));
  }
}

/** Removes and frees the meshes of `group` (the arrows). */
function disposeChildren(group) {
  const materials = new Set();
  for (const child of group.children) {
    child.geometry?.dispose();
    if (child.material) materials.add(child.material);
  }
  for (const material of materials) material.dispose();
  group.clear();
}

/**
 * Places the removed parts (`parts`: { partId, box } in removal order, boxes in the content's
 * frame) on the floor beside the assembly (`assembly`: { min, max } arrays): rows running along
 * +x, starting past where the exploded assembly can reach, the next row behind (+z); the rows
 * are about as long as the tray is deep. Places snap to `cell` (voxels stay on the grid).
 * Returns { slots: Map(partId -> translation of the part), box: the tray's bounds }.
 */
function layOutTray(parts, assembly, cell) {
  const snapUp = (value) => Math.ceil(value / cell - 1e-9) * cell;
  const gap = cell;
  const sizes = parts.map(({ box }) => box.getSize(new THREE.Vector3()));
  const area = sizes.reduce((sum, size) => sum + (snapUp(size.x) + gap) * (snapUp(size.z) + gap), 0);
  const rowLength = Math.max(Math.sqrt(area) * 1.2, ...sizes.map((size) => snapUp(size.x)));
  const centreX = (assembly.min[0] + assembly.max[0]) / 2;
  const halfWidth = (assembly.max[0] - assembly.min[0]) / 2;
  // Just past the assembly (exploding it moves the tray out as well: AssemblyView.#trayShift).
  const startX = Math.floor(centreX / cell) * cell + snapUp(halfWidth) + 2 * gap;
  let x = startX;
  let z = Math.floor(assembly.min[2] / cell) * cell;
  let rowDepth = 0;
  const slots = new Map();
  const box = new THREE.Box3();
  parts.forEach(({ partId, box: partBox }, index) => {
    const size = sizes[index];
    if (x > startX && x + size.x > startX + rowLength) {
      x = startX;
      z += snapUp(rowDepth) + gap;
      rowDepth = 0;
    }
    const translation = new THREE.Vector3(x - partBox.min.x, assembly.min[1] - partBox.min.y, z - partBox.min.z);
    slots.set(partId, translation);
    box.union(partBox.clone().translate(translation));
    x += snapUp(size.x) + gap;
    rowDepth = Math.max(rowDepth, size.z);
  });
  return { slots, box };
}

/**
 * The removal motion of each part, from the report's disassembly: the waypoints of its path
 * (each move translates it by `steps` times `scale.step` along `dir`, or along its own `vector`)
 * plus a run-out of `scale.runOut` along its last move. Returns Map(partId -> { index in the
 * order, waypoints }).
 */
function removalMotions(report, scale = { step: 1, runOut: RUN_OUT_VOXELS }) {
  const motions = new Map();
  const disassembly = report.disassembly;
  if (!disassembly?.order?.length) return motions;
  disassembly.order.forEach((partId, index) => {
    const path = disassembly.paths?.[index] ?? [];
    const waypoints = [new THREE.Vector3()];
    for (const move of path) {
      const step = directionVector(move.dir, report.baseDirections, move.vector).multiplyScalar((Number(move.steps) || 0) * scale.step);
      waypoints.push(waypoints[waypoints.length - 1].clone().add(step));
    }
    const pathEnd = waypoints[waypoints.length - 1].clone();
    const pathLength = polylineLength(waypoints);
    let fadeFrom = 1;
    if (path.length > 0) {
      const lastMove = path[path.length - 1];
      const last = directionVector(lastMove.dir, report.baseDirections, lastMove.vector);
      waypoints.push(pathEnd.clone().addScaledVector(last, scale.runOut));
      fadeFrom = pathLength / (pathLength + scale.runOut);
    }
    motions.set(partId, { index, waypoints, pathEnd, fadeFrom });
  });
  return motions;
}

function polylineLength(waypoints) {
  let total = 0;
  for (let i = 1; i < waypoints.length; i += 1) total += waypoints[i].distanceTo(waypoints[i - 1]);
  return total;
}

/** The point at `fraction` (0..1) of the polyline's length. */
function pointAlong(waypoints, fraction) {
  let remaining = fraction * polylineLength(waypoints);
  for (let i = 1; i < waypoints.length; i += 1) {
    const length = waypoints[i].distanceTo(waypoints[i - 1]);
    if (remaining <= length && length > 0) return waypoints[i - 1].clone().lerp(waypoints[i], remaining / length);
    remaining -= length;
  }
  return waypoints[waypoints.length - 1].clone();
}

// ---------------------------------------------------------------------------------------------
// Voxel plans of several parts moved together: the report's `steps` (issue 27).

/**
 * The moves to play for a disassembly (or a disassemblyFailure): its `steps` when the plan needs
 * parts moved together (`paths` null, or no paths at all: a partial plan) or when the steps are
 * fewer than the single-part paths' moves; otherwise null, and the order and paths are played.
 */
export function stepsToPlay(disassembly) {
  const steps = disassembly?.steps;
  if (!Array.isArray(steps) || steps.length === 0) return null;
  if (Array.isArray(disassembly.paths)) {
    const segments = disassembly.paths.reduce((sum, path) => sum + (Array.isArray(path) ? path.length : 0), 0);
    if (steps.length >= segments) return null;
  }
  return steps;
}

/** A step's move as the CLI writes it: '+x 1', '-z 6', '+z out'. */
export function formatStepMove(step) {
  const move = Array.isArray(step?.move) ? step.move.map(Number) : [0, 0, 0];
  const axis = move.findIndex((value) => value !== 0);
  if (axis < 0) return 'no move';
  return `${move[axis] > 0 ? '+' : '-'}${'xyz'[axis]} ${step.out ? 'out' : Math.abs(move[axis])}`;
}

/** 'parts 2, 4  +x 1', 'part 3  +z out'. */
export function formatStep(step) {
  const parts = Array.isArray(step?.parts) ? step.parts : [];
  return `${parts.length === 1 ? 'part' : 'parts'} ${parts.join(', ')}  ${formatStepMove(step)}`;
}

/** BurrTools' notation: [98, 2, 5] -> '98.2.5'. */
export function formatLevel(level) {
  return Array.isArray(level) ? level.join('.') : '';
}

/**
 * Where every part is before each step of `steps` (the report's moves, in voxels; `boxes`: each
 * part's bounds as assembled, partId -> Box3). A move translates its parts by `move` times
 * `scale.step`. An `out` step moves its parts along its axis just far enough that their bounds
 * clear the rest of their sub-assembly, plus a cell; they then form a sub-assembly of their own.
 * A single part that goes out has left (the tray, or it runs out and fades). Nothing here decides
 * whether a move is possible: that is the core's plan. Returns { steps, before (N + 1 maps
 * partId -> offset), deltas, moving (Set per step), leaves (partId -> the step it leaves in),
 * framing (a Box3 around every position a visible part takes) }.
 */
function stepMotions(steps, boxes, scale) {
  const ids = [...boxes.keys()];
  let offsets = new Map(ids.map((id) => [id, new THREE.Vector3()]));
  const subAssembly = new Map(ids.map((id) => [id, 0]));
  let subAssemblies = 1;
  const before = [];
  const deltas = [];
  const moving = [];
  const leaves = new Map();
  const framing = new THREE.Box3();
  const include = (step) => {
    for (const id of ids) {
      const left = leaves.get(id);
      if (left === undefined || left >= step) framing.union(boxes.get(id).clone().translate(offsets.get(id)));
    }
  };
  include(0);
  steps.forEach((step, index) => {
    before.push(offsets);
    const parts = (Array.isArray(step?.parts) ? step.parts : []).filter((id) => boxes.has(id));
    const move = new THREE.Vector3(...(Array.isArray(step?.move) ? step.move : [0, 0, 0]).map((value) => Number(value) || 0));
    let delta = move.clone().multiplyScalar(scale.step);
    if (step?.out && parts.length > 0 && move.lengthSq() > 0) {
      const unit = move.clone().normalize();
      const group = new Set(parts);
      const from = subAssembly.get(parts[0]);
      const rest = ids.filter((id) => subAssembly.get(id) === from && !group.has(id) && !leaves.has(id));
      delta = unit.clone().multiplyScalar(clearingDistance(parts, rest, unit, boxes, offsets) + scale.cell);
      subAssemblies += 1;
      for (const id of parts) subAssembly.set(id, subAssemblies);
      if (parts.length === 1) leaves.set(parts[0], index);
    }
    deltas.push(delta);
    moving.push(new Set(parts));
    offsets = new Map(offsets);
    for (const id of parts) offsets.set(id, offsets.get(id).clone().add(delta));
    include(index);
  });
  before.push(offsets);
  return { steps, before, deltas, moving, leaves, framing };
}

/**
 * How far the parts `group` must move along `unit` (an axis) for their bounds to lie past the
 * bounds of `rest` (their size along it when `rest` is empty).
 */
function clearingDistance(group, rest, unit, boxes, offsets) {
  const span = (id) => {
    const box = boxes.get(id).clone().translate(offsets.get(id));
    const a = box.min.dot(unit);
    const b = box.max.dot(unit);
    return [Math.min(a, b), Math.max(a, b)];
  };
  const groupSpans = group.map(span);
  const low = Math.min(...groupSpans.map(([min]) => min));
  if (rest.length === 0) return Math.max(...groupSpans.map(([, max]) => max)) - low;
  const high = Math.max(...rest.map((id) => span(id)[1]));
  return Math.max(high - low, 0);
}

// ---------------------------------------------------------------------------------------------
// Plate plans: their removal directions as the disassembly to play.

/**
 * A direction vector as the report writes it: '-z' for an axis (up to rounding, such as
 * -0.9999999999999999), else '(0.707, 0, -0.707)'.
 */
export function formatDirection(vector) {
  if (!Array.isArray(vector) || vector.length !== 3) return 'none';
  const length = Math.hypot(...vector);
  if (!(length > 0)) return 'none';
  const unit = vector.map((value) => value / length);
  const axis = unit.findIndex((value) => Math.abs(Math.abs(value) - 1) < 1e-9);
  if (axis >= 0) return `${unit[axis] > 0 ? '+' : '-'}${'xyz'[axis]}`;
  const rounded = (value) => {
    const text = value.toFixed(3).replace(/\.?0+$/, '');
    return text === '-0' ? '0' : text;
  };
  return `(${unit.map(rounded).join(', ')})`;
}

/**
 * A plate plan's removal (document.removal: [{ part, direction }], the key first) as the
 * disassembly the view plays and the report lists: each plate moves along its planned
 * direction, in order; the last one stays. Null for documents without a removal.
 */
export function planDisassembly(document_) {
  const planned = document_?.kind === 'plate' || document_?.kind === 'frame';
  const removal = planned && Array.isArray(document_.removal) ? document_.removal : null;
  if (!removal?.length) return null;
  // A frame's beam leaves along an axis ('+y'), as far as the whole frame is wide (two steps),
  // so that the beam with its joint voxels is clear of the frame before it fades out.
  const steps = document_.kind === 'frame' ? 2 : 1;
  const order = removal.map((step) => step.part);
  const paths = removal.map((step) => {
    const vector = Array.isArray(step.direction) ? step.direction : axisVector(step.direction);
    return vector ? [{ dir: formatDirection(vector), vector, steps }] : [];
  });
  // A frame's removal lists the beams that leave; the last beam stays where it is.
  const beams = document_.kind === 'frame' && Array.isArray(document_.beams) ? document_.beams.map((beam) => beam.id) : [];
  for (const id of beams) {
    if (!order.includes(id)) {
      order.push(id);
      paths.push([]);
    }
  }
  return { order, paths };
}

/** '+y' -> [0, 1, 0]; anything else null. */
function axisVector(label) {
  const match = /^([+-])([xyz])$/.exec(String(label ?? '').trim());
  if (!match) return null;
  const vector = [0, 0, 0];
  vector['xyz'.indexOf(match[2])] = match[1] === '+' ? 1 : -1;
  return vector;
}

/** The report to show for `document_`: a plate plan's own removal replaces the check's disassembly. */
export function withPlannedRemoval(report, document_) {
  const disassembly = planDisassembly(document_);
  return disassembly ? { ...report, disassembly, disassemblyFailure: null } : report;
}

// ---------------------------------------------------------------------------------------------
// Playback: a clock that moves the disassembly step, and the controls that drive it.

/** Steps per second at speed 1: one part leaves per second... */
const STEPS_PER_SECOND = 1;
/** ...unless that would take longer than this: a 100-part bunny plays in 20 s, not 100. */
const MAX_PLAY_SECONDS = 20;
/** Previous / next step animate one removal at least this fast (steps per second). */
const MIN_STEP_RATE = 1.5;
/** A looping animation rests this long when fully assembled or fully taken apart. */
const LOOP_PAUSE_SECONDS = 0.9;
/** A frame after a long stall (hidden tab) does not jump the animation ahead. */
const MAX_FRAME_SECONDS = 0.1;

/**
 * Plays the disassembly step from 0 (assembled) to `length` (every part but the last removed).
 * Without `loop` it stops at the end; with `loop` it rests, plays back to assembled (the
 * assembly is the disassembly reversed), rests, and starts again. `onStep(step)` on every
 * change, `onPlayingChange(playing)` when it starts or stops.
 */
export class DisassemblyPlayer {
  #length = 0;
  #step = 0;
  #direction = 1;
  #restSeconds = 0;
  #playing = false;
  #frameRequest = 0;
  #lastTime = 0;
  #onStep;
  #onPlayingChange;
  /** Previous / next: the whole step to stop at, or null while playing freely. */
  #target = null;
  speed = 1;
  loop = false;

  constructor({ onStep = () => {}, onPlayingChange = () => {} } = {}) {
    this.#onStep = onStep;
    this.#onPlayingChange = onPlayingChange;
  }

  get length() {
    return this.#length;
  }

  get step() {
    return this.#step;
  }

  get playing() {
    return this.#playing;
  }

  /** Steps per second at speed 1: one a second, more for many parts (the whole within MAX_PLAY_SECONDS). */
  get stepsPerSecond() {
    return Math.max(STEPS_PER_SECOND, this.#length / MAX_PLAY_SECONDS);
  }

  /** A new disassembly of `length` steps: back to assembled, stopped. */
  setLength(length) {
    this.pause();
    this.#length = Math.max(Number(length) || 0, 0);
    this.#direction = 1;
    this.seek(0);
  }

  seek(step) {
    this.#step = Math.min(Math.max(Number(step) || 0, 0), this.#length);
    this.#onStep(this.#step);
  }

  /** Animates to the next whole step (one more part removed). */
  next() {
    this.stepTo(Math.floor(this.#step + 1e-6) + 1);
  }

  /** Animates back to the previous whole step (the last removed part put back). */
  previous() {
    this.stepTo(Math.ceil(this.#step - 1e-6) - 1);
  }

  /** Animates to whole step `target` and stops there (at once when motion is to be reduced). */
  stepTo(target) {
    const clamped = Math.min(Math.max(Math.round(Number(target) || 0), 0), this.#length);
    this.pause();
    if (clamped === this.#step) return;
    if (globalThis.matchMedia?.('(prefers-reduced-motion: reduce)').matches) {
      this.seek(clamped);
      return;
    }
    this.#target = clamped;
    this.#start();
  }

  play() {
    if (this.#playing || this.#length <= 0) return;
    // Play from the end means: start again (or, looping, go back the way it came).
    if (this.#step >= this.#length) {
      if (this.loop) this.#direction = -1;
      else this.seek(0);
    }
    if (this.#step <= 0) this.#direction = 1;
    this.#target = null;
    this.#start();
  }

  #start() {
    this.#playing = true;
    this.#restSeconds = 0;
    this.#lastTime = 0;
    this.#frameRequest = requestAnimationFrame((time) => this.#tick(time));
    this.#onPlayingChange(true);
  }

  pause() {
    if (!this.#playing) return;
    this.#playing = false;
    this.#target = null;
    cancelAnimationFrame(this.#frameRequest);
    this.#frameRequest = 0;
    this.#onPlayingChange(false);
  }

  toggle() {
    if (this.#playing) this.pause();
    else this.play();
  }

  dispose() {
    this.pause();
    this.#onStep = () => {};
    this.#onPlayingChange = () => {};
  }

  #tick(time) {
    if (!this.#playing) return;
    const seconds = this.#lastTime ? Math.min((time - this.#lastTime) / 1000, MAX_FRAME_SECONDS) : 0;
    this.#lastTime = time;
    if (this.#target !== null) {
      const rate = Math.max(this.stepsPerSecond * this.speed, MIN_STEP_RATE);
      const sign = this.#target > this.#step ? 1 : -1;
      const next = this.#step + sign * seconds * rate;
      const reached = sign > 0 ? next >= this.#target : next <= this.#target;
      this.seek(reached ? this.#target : next);
      if (reached) {
        this.pause();
        return;
      }
    } else if (this.#restSeconds > 0) {
      this.#restSeconds -= seconds;
    } else {
      const next = this.#step + this.#direction * seconds * this.stepsPerSecond * this.speed;
      const atEnd = this.#direction > 0 ? next >= this.#length : next <= 0;
      this.seek(next);
      if (atEnd) {
        if (!this.loop) {
          this.pause();
          return;
        }
        this.#direction = -this.#direction;
        this.#restSeconds = LOOP_PAUSE_SECONDS;
      }
    }
    this.#frameRequest = requestAnimationFrame((next) => this.#tick(next));
  }
}

/**
 * Where a partial plan (a disassemblyFailure with moves) stopped: 'parts 1, 2, 3 are stuck
 * together', or 'parts 1, 2, 3 are not separated (search limit)' when a search gave up.
 */
export function formatStuck(failure) {
  const groups = Array.isArray(failure?.unseparated) && failure.unseparated.length ? failure.unseparated : [failure?.stuck ?? []];
  const named = groups.map((group) => `${group.length === 1 ? 'part' : 'parts'} ${group.join(', ')}`).join(' and ');
  const plural = groups.length > 1 || groups[0]?.length > 1;
  if (failure?.searchLimitReached) return `${named} ${plural ? 'are' : 'is'} not separated (search limit${failure.limit ? `: ${failure.limit}` : ''})`;
  return `${named} ${plural ? 'are' : 'is'} stuck${groups.some((group) => group.length > 1) ? ' together' : ''}`;
}

/** '8 s', '1 min 20 s'. */
function formatSeconds(seconds) {
  const whole = Math.round(seconds);
  return whole < 60 ? `${whole} s` : `${Math.floor(whole / 60)} min ${whole % 60} s`;
}

/** '+z×1, then -x×2'; a plate plan's moves (with their own vector) have no step count: 'along -z'. */
export function formatMoves(path) {
  const moves = path ?? [];
  if (moves.length > 0 && moves.every((move) => Array.isArray(move.vector))) return `along ${moves.map((move) => move.dir).join(', then ')}`;
  return moves.map((move) => `${move.dir}×${move.steps}`).join(', then ');
}

/**
 * What the disassembly shows at `step`: `{ text, partId, index, moves }`, e.g. "removing part 3
 * (2 of 8)" with moves "+z×1, then -x×2"; "assembled" at 0 and "part 9 left" at the end.
 * A plan of moves (stepsToPlay) says "move 5 of 27" with moves "parts 2, 4  +x 1" (the move
 * under way, or just made at a whole step) and lists its `parts`; `index` is then the move's.
 * At the end of a partial plan (a disassemblyFailure) the moves text names the stuck parts.
 */
export function describeDisassemblyStep(disassembly, step) {
  const steps = stepsToPlay(disassembly);
  if (steps) {
    if (step <= 0) return { text: 'assembled', partId: null, index: -1, moves: '', parts: [] };
    const index = Math.min(Math.ceil(step - 1e-9), steps.length) - 1;
    let moves = formatStep(steps[index]);
    if (index === steps.length - 1 && step >= steps.length && Array.isArray(disassembly.unseparated)) {
      moves += `; then ${formatStuck(disassembly)}`;
    }
    return { text: `move ${index + 1} of ${steps.length}`, partId: null, index, moves, parts: [...(steps[index].parts ?? [])] };
  }
  const order = disassembly?.order ?? [];
  if (order.length < 2) return { text: '', partId: null, index: -1, moves: '' };
  if (step <= 0) return { text: 'assembled', partId: null, index: -1, moves: '' };
  const index = Math.min(Math.floor(step), order.length - 1);
  if (index >= order.length - 1) {
    return { text: `part ${order[order.length - 1]} left`, partId: order[order.length - 1], index, moves: '' };
  }
  return {
    text: `removing part ${order[index]} (${index + 1} of ${order.length - 1})`,
    partId: order[index],
    index,
    moves: formatMoves(disassembly.paths?.[index]),
  };
}

/**
 * Wires playback controls to `view`. `elements`: `range` (input[type=range], the step),
 * `label` (where describeDisassemblyStep's text goes), and optional `moves` (the moving part's
 * path), `playButton`, `speedSelect` (values are speed factors), `loopCheckbox`, `explodedRange`
 * (0..1), `previousButton` / `nextButton` (one removal back / on), `root` (gets data-playing).
 * `onStep({ step, index, partId, parts, moves })` is told about every change (e.g. to highlight
 * the current removal in a list; `moves` is true when a plan of moves is played, `index` then
 * being the move's). Returns { setDisassembly, play, pause, seek, setExploded, player, dispose }.
 * setDisassembly takes the report's disassembly, or a disassemblyFailure whose moves are played
 * up to where they stop.
 */
export function createPlaybackControls(view, elements, { onStep = () => {}, loop = false } = {}) {
  const { range, label, moves, playButton, speedSelect, loopCheckbox, explodedRange, previousButton, nextButton, root } = elements;
  let disassembly = null;

  /** Previous at the start and Next at the end have nothing to do. */
  function updateStepButtons(step) {
    if (previousButton) previousButton.disabled = !disassembly || step <= 0;
    if (nextButton) nextButton.disabled = !disassembly || step >= player.length;
  }

  const player = new DisassemblyPlayer({
    onStep(step) {
      view.setDisassemblyStep(step);
      if (range && Number(range.value) !== step) range.value = String(step);
      const described = describeDisassemblyStep(disassembly, step);
      if (label) label.textContent = described.text;
      if (moves) moves.textContent = described.moves;
      updateStepButtons(step);
      onStep({ step, index: described.index, partId: described.partId, parts: described.parts ?? [], moves: Boolean(stepsToPlay(disassembly)) });
    },
    onPlayingChange(playing) {
      if (playButton) {
        playButton.textContent = playing ? 'Pause' : 'Play';
        playButton.setAttribute('aria-pressed', String(playing));
      }
      if (root) root.dataset.playing = String(playing);
    },
  });
  player.loop = loopCheckbox ? loopCheckbox.checked : loop;
  if (speedSelect) player.speed = Number(speedSelect.value) || 1;

  const stepTitles = {
    previous: { removal: previousButton?.getAttribute('title') ?? null, move: 'Previous step: undo the last move' },
    next: { removal: nextButton?.getAttribute('title') ?? null, move: 'Next step: the next move of the plan' },
  };
  const listeners = [];
  const listen = (target, type, handler) => {
    if (!target) return;
    target.addEventListener(type, handler);
    listeners.push(() => target.removeEventListener(type, handler));
  };
  // Dragging the slider takes over from the clock.
  listen(range, 'input', () => {
    player.pause();
    player.seek(Number(range.value));
  });
  listen(playButton, 'click', () => player.toggle());
  listen(previousButton, 'click', () => player.previous());
  listen(nextButton, 'click', () => player.next());
  listen(speedSelect, 'change', () => { player.speed = Number(speedSelect.value) || 1; });
  listen(loopCheckbox, 'change', () => { player.loop = loopCheckbox.checked; });
  listen(explodedRange, 'input', () => view.setExploded(Number(explodedRange.value)));

  function setDisassembly(next) {
    // A plan of moves plays move by move; any other part by part (the last part stays).
    const steps = stepsToPlay(next);
    const removable = steps ? steps.length : (next?.order?.length ?? 0) - 1;
    disassembly = removable > 0 && view.available ? next : null;
    const length = disassembly ? removable : 0;
    if (range) {
      range.disabled = !disassembly;
      range.max = String(Math.max(length, 1));
    }
    if (playButton) playButton.disabled = !disassembly;
    // Previous / Next say what they do: a move, or a removal.
    for (const [button, titles] of [[previousButton, stepTitles.previous], [nextButton, stepTitles.next]]) {
      if (button && titles.removal !== null) button.title = steps ? titles.move : titles.removal;
    }
    if (explodedRange) {
      explodedRange.disabled = !view.available;
      view.setExploded(Number(explodedRange.value));
    }
    player.setLength(length);
    if (range) range.title = disassembly ? `${length} ${steps ? 'moves' : 'removals'}, ${formatSeconds(length / player.stepsPerSecond)} at 1×` : '';
  }

  return {
    player,
    setDisassembly,
    play: () => player.play(),
    pause: () => player.pause(),
    seek: (step) => {
      player.pause();
      player.seek(step);
    },
    setExploded(factor) {
      const clamped = Math.min(Math.max(Number(factor) || 0, 0), 1);
      if (explodedRange) explodedRange.value = String(clamped);
      view.setExploded(clamped);
    },
    dispose() {
      player.dispose();
      for (const remove of listeners) remove();
    },
  };
}
