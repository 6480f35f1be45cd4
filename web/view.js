// SPDX-License-Identifier: GPL-3.0-or-later
//
// The shared three.js renderer of the playground and of the drop-in viewer (viewer.js): one
// merged surface per voxel part in its own colour, the key highlighted, the computed disassembly
// played back along the report's removal paths, and an exploded view. It only draws: every fact
// it shows (parts, key, order, paths) comes from the core's report, and the part surfaces from
// the core's partSurfaces (the triangles of the STL/OBJ export).
//
// Exports: AssemblyView (the 3D view inside a container element: the scene, its parts, the
// disassembly shown; the camera's framing is in view-camera.js, picking in view-picking.js),
// partColor / partColorCss, and, re-exported so that one import serves the playground and the
// drop-in viewer, the playback (view-playback.js: DisassemblyPlayer, createPlaybackControls,
// describeDisassemblyStep) and the motions and their words (view-motions.js: stepsToPlay,
// formatStep, formatLevel, formatDirection, and for plate plans planDisassembly and
// withPlannedRemoval).
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
import { RUN_OUT_VOXELS, layOutTray, pointAlong, removalMotions, stepMotions, stepsToPlay } from './view-motions.js';
import { fitCamera, fitDistance, reframeCamera, screenFill, setDepthRange } from './view-camera.js';
import { isClick, pickPart, screenPointOf } from './view-picking.js';
import { LiveDrawing, equalFloats } from './view-live.js';

export {
  formatDirection, formatLevel, formatStep, formatStepMove, planDisassembly, stepsToPlay, withPlannedRemoval,
} from './view-motions.js';
export {
  DisassemblyPlayer, createPlaybackControls, describeDisassemblyStep, formatMoves, formatStuck,
} from './view-playback.js';

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
/** Step by step: the new part's edges and glow, and how see-through the remainder is. */
const HIGHLIGHT_EDGE_COLOR = 0xffffff;
const HIGHLIGHT_GLOW = 0.45;
const GHOST_OPACITY = 0.22;
const GHOST_EDGE_OPACITY = 0.2;
/** At explode factor 1 every part sits this many times farther from the centre than assembled. */
const EXPLODE_SCALE = 1.2;
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
  /** Frames drawn so far (renderStats). */
  #framesRendered = 0;
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
  /**
   * Materials of parts no longer drawn, { surface, edges } pairs kept for the next parts (issue
   * 28, item 8): a disposed material frees its shader program once no other material uses it, so
   * the next assembly compiled the same programs again (hundreds of ms in software WebGL, at every
   * live-design update). Reused, the programs stay; #takeMaterials resets their state.
   */
  #spareMaterials = [];
  /** Live design's merged drawing (view-live.js), made on first use. */
  #liveDrawing = null;
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
    // A part whose surface is unchanged keeps its geometry and edges (a live design redraws the
    // placed parts at every update; their edges are the costly part to make again).
    const previous = this.#detachParts();
    try {
      this.clear();
      if (!this.available) return;
      this.#build(document_, surfaces, previous, kept);
    } finally {
      this.#releaseParts(previous);
    }
  }

  /**
   * Live design (issue 28, item 8): the deepest node of a running design, a picture only: its
   * parts merged into a few meshes (view-live.js), those in `ghost` see-through, the camera where
   * it is. No picking, playback or emphasis until the next show(). The container's data-parts
   * and data-ghost say what is drawn, as for show() and setEmphasis.
   */
  showLive(document_, surfaces, { ghost = [] } = {}) {
    const kept = this.#framed;
    this.clear();
    if (!this.available) return;
    this.#build(document_, surfaces, new Map(), kept, new Set(ghost));
  }

  /**
   * show()'s drawing, once the view is empty: `previous` parts may lend their geometry; with
   * `liveGhost` (a Set of part ids) the parts are merged as showLive draws them.
   */
  #build(document_, surfaces, previous, kept, liveGhost = null) {
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
    // A mesh assembly's parts keep the names of their objects, groups, solids or files.
    for (const part of document_?.kind === 'mesh' && Array.isArray(document_.parts) ? document_.parts : []) {
      if (Number.isInteger(part?.id) && typeof part.name === 'string' && part.name) this.#partNames.set(part.id, part.name);
    }
    // Whole-cell offsets keep voxel boundaries (and round plate coordinates) on the grid lines.
    const cell = this.#scale.cell;
    const snap = (value) => Math.floor(value / cell) * cell;
    const offset = new THREE.Vector3(-snap((min[0] + max[0]) / 2), -min[1], -snap((min[2] + max[2]) / 2));
    this.#content.position.copy(offset);
    this.#floorY = min[1] + offset.y;
    if (liveGhost) this.#addLiveParts(surfaces, centroids, liveGhost);
    else this.#addParts(surfaces, centroids, min, max, previous);
    this.#content.add(this.#arrow);
    this.#bounds = { min, max, offset };
    this.#addGrid(min, max, offset);
    if (!liveGhost) this.#container.dataset.parts = String(this.#meshes.size);
    this.#updatePositions();
    // The explode factor outlives the assembly: frame what is actually shown.
    if (kept) this.#framed = kept;
    else if (!liveGhost) this.#fitCamera(this.#framingBox()); // a live picture keeps the camera
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

  /** `previous`: the parts drawn before (#detachParts); those reused are taken out of it. */
  #addParts(surfaces, centroids, min, max, previous) {
    const center = new THREE.Vector3(...min).add(new THREE.Vector3(...max)).multiplyScalar(0.5);
    for (const surface of [...surfaces].sort((a, b) => a.partId - b.partId)) {
      const { partId } = surface;
      const sums = centroids.get(partId);
      if (!sums) continue;
      const old = previous.get(partId);
      const reused = old && sameSurface(old.geometry, surface);
      if (reused) previous.delete(partId);
      const geometry = reused ? old.geometry : surfaceGeometry(surface);
      const edgesGeometry = reused ? old.children[0].geometry : new THREE.EdgesGeometry(geometry, 30);
      if (reused) this.#spareMaterials.push({ surface: old.material, edges: old.children[0].material });
      const materials = this.#takeMaterials(partId);
      const mesh = new THREE.Mesh(geometry, materials.surface);
      mesh.name = `part ${partId}`;
      mesh.userData.partId = partId;
      mesh.userData.edgeColor = EDGE_COLOR;
      mesh.add(new THREE.LineSegments(edgesGeometry, materials.edges));
      this.#content.add(mesh);
      this.#meshes.set(partId, mesh);
      // Exploded view: every part moves away from the assembly's centre along the line through
      // its centroid, proportionally to its distance (the usual exploded drawing).
      const centroid = new THREE.Vector3(...sums.voxelSum).divideScalar(sums.voxelCount);
      this.#explodeOffsets.set(partId, centroid.sub(center).multiplyScalar(EXPLODE_SCALE));
    }
  }

  #removeGrid() {
    const grid = this.#scene?.getObjectByName('grid');
    if (!grid) return;
    grid.geometry.dispose();
    grid.material.dispose();
    this.#scene.remove(grid);
  }

  #liveDrawingOnce() {
    this.#liveDrawing ??= new LiveDrawing({
      partColor, edgeColor: EDGE_COLOR, edgeOpacity: 0.55, ghostOpacity: GHOST_OPACITY, ghostEdgeOpacity: GHOST_EDGE_OPACITY,
    });
    return this.#liveDrawing;
  }

  /**
   * Compiles live design's shader programs ahead (in parallel where the browser can), so that a
   * design's first picture does not wait for them (a second in software WebGL on a busy
   * machine). Call when the page is idle; resolves when they are ready.
   */
  async prepareLive() {
    if (!this.available) return;
    const sample = this.#liveDrawingOnce().sample();
    try {
      await this.#renderer.compileAsync(sample, this.#camera, this.#scene);
    } finally {
      LiveDrawing.disposeSample(sample);
    }
  }

  #addLiveParts(surfaces, centroids, ghost) {
    const drawn = surfaces.filter((surface) => centroids.has(surface.partId));
    this.#content.add(this.#liveDrawingOnce().update(drawn, ghost));
    this.#container.dataset.parts = String(drawn.length);
    this.#container.dataset.ghost = drawn.filter((surface) => ghost.has(surface.partId)).map((surface) => surface.partId).join(' ');
  }

  /** A part's materials, as a fresh pair would be: from the spare ones when there are any. */
  #takeMaterials(partId) {
    const spare = this.#spareMaterials.pop();
    const surface = spare?.surface ?? new THREE.MeshStandardMaterial({
      roughness: 0.7,
      metalness: 0.0,
      // Push the faces back a little so the outline edges win the depth test.
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    const edges = spare?.edges ?? new THREE.LineBasicMaterial({ transparent: true });
    surface.color.copy(partColor(partId));
    surface.emissive.copy(NO_GLOW);
    surface.opacity = 1;
    surface.depthWrite = true;
    // Back to opaque: a program the material has compiled before (three.js keeps it per material).
    if (surface.transparent) surface.needsUpdate = true;
    surface.transparent = false;
    edges.color.set(EDGE_COLOR);
    edges.opacity = 0.55;
    return { surface, edges };
  }

  /** Takes the drawn parts out of the view (partId -> mesh); #releaseParts frees what is not reused. */
  #detachParts() {
    const parts = new Map(this.#meshes);
    this.#meshes.clear();
    return parts;
  }

  /** Frees the geometry of `parts` (partId -> mesh) and keeps their materials for the next parts. */
  #releaseParts(parts) {
    for (const mesh of parts.values()) {
      mesh.children[0].geometry.dispose();
      mesh.geometry.dispose();
      this.#spareMaterials.push({ surface: mesh.material, edges: mesh.children[0].material });
    }
    parts.clear();
  }

  /**
   * The floor grid under the assembly (and under the tray, `trayBox` in the content's frame). The
   * same grid is kept while its size does not change (live design draws many nodes of one shape).
   */
  #addGrid(min, max, offset, trayBox = null) {
    const { cell } = this.#scale;
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
    const size = `${divisions} x ${cell}`;
    let grid = this.#scene.getObjectByName('grid');
    if (grid && grid.userData.size !== size) {
      this.#removeGrid();
      grid = null;
    }
    if (!grid) {
      grid = new THREE.GridHelper(divisions * cell, divisions, 0x59606e, 0x353a44);
      grid.name = 'grid';
      grid.userData.size = size;
      this.#scene.add(grid);
    }
    grid.visible = true;
    grid.position.set(0, min[1] + offset.y - 0.001 * cell, 0);
  }

  /** Puts the camera in front of `box` from the usual three-quarter view (view-camera.js). */
  #fitCamera(box) {
    this.#framed = fitCamera(this.#camera, this.#controls, box);
  }

  /** What the camera was last fitted to, so explode changes can keep the same framing. */
  #framed = null;

  /**
   * Whether the framing takes in the removal paths and the tray: not until the disassembly is
   * played (a step past 0), so that a result first fills the view; playing widens it once.
   */
  #widened = false;

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
    // Cut points: a plate's or a frame's, from the core's check of the input.
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
    this.#framed = reframeCamera(this.#camera, this.#controls, this.#framingBox(), this.#framed);
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
    return screenFill(this.#camera, this.#meshes.values());
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
    return pickPart(this.#raycaster, this.#camera, this.#renderer.domElement, this.#meshes.values(), clientX, clientY);
  }

  /** Where the centre of part `partId`'s bounding box is on the screen, in client coordinates (or null). */
  screenPoint(partId) {
    const mesh = this.#meshes.get(partId);
    if (!this.available || !mesh?.visible) return null;
    return screenPointOf(mesh, this.#camera, this.#renderer.domElement);
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
    this.#releaseParts(this.#detachParts());
    this.#liveDrawing?.clear();
    this.#content.clear();
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
    // Hidden, not freed: the next assembly of the same size shows it again (#addGrid).
    const grid = this.#scene.getObjectByName('grid');
    if (grid) grid.visible = false;
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
    this.#removeGrid();
    for (const { surface, edges } of this.#spareMaterials) {
      surface.dispose();
      edges.dispose();
    }
    this.#spareMaterials = [];
    this.#liveDrawing?.dispose();
    this.#liveDrawing = null;
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

  /**
   * What the renderer holds (three.js renderer.info): shader programs, geometries and textures
   * on the GPU, the calls and triangles of the last frame, and the frames drawn so far. Live design keeps `programs`
   * flat (issue 28, item 8): materials are reused, not made per update.
   */
  renderStats() {
    if (!this.available) return { programs: 0, geometries: 0, textures: 0, calls: 0, triangles: 0, framesRendered: 0 };
    const { programs, memory, render } = this.#renderer.info;
    return {
      programs: programs?.length ?? 0, ...memory, calls: render.calls, triangles: render.triangles, framesRendered: this.#framesRendered,
    };
  }

  /** Renders on demand (at most once per frame) instead of spinning a render loop. */
  requestRender() {
    if (!this.available || this.#frameRequest) return;
    this.#frameRequest = requestAnimationFrame(() => {
      this.#frameRequest = 0;
      if (!this.available) return;
      this.#renderer.render(this.#scene, this.#camera);
      this.#framesRendered += 1;
    });
  }

  #resize() {
    const width = Math.max(this.#container.clientWidth, 1);
    const height = Math.max(this.#container.clientHeight, 1);
    this.#renderer.setSize(width, height, false);
    const aspect = width / height;
    if (aspect !== this.#camera.aspect && this.#framed && this.#meshes.size > 0) {
      // A narrower or wider view: the camera moves in or out along its line of sight so that
      // what was framed still fits as it did (direction, target and relative zoom kept).
      const box = this.#framingBox();
      const before = fitDistance(this.#camera, box);
      this.#camera.aspect = aspect;
      const ratio = fitDistance(this.#camera, box) / before;
      const offset = this.#camera.position.clone().sub(this.#controls.target).multiplyScalar(ratio);
      this.#camera.position.copy(this.#controls.target).add(offset);
      this.#framed = { ...this.#framed, distance: this.#framed.distance * ratio };
      setDepthRange(this.#camera, this.#controls, Math.max(this.#framed.distance, offset.length()));
      this.#controls.update();
    }
    this.#camera.aspect = aspect;
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
    if (!this.#onPartClick || this.#meshes.size === 0 || !isClick(down, event)) return;
    this.#onPartClick(this.partAt(event.clientX, event.clientY));
  }
}

/** Whether a drawn geometry has exactly the triangles of a core part surface. */
function sameSurface(geometry, { positions }) {
  const drawn = geometry.getAttribute('position')?.array;
  return Boolean(drawn) && equalFloats(drawn, positions);
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
