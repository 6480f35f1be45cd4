// SPDX-License-Identifier: GPL-3.0-or-later
//
// The playground's three.js view of a voxel assembly: one merged surface per part, the key
// highlighted, and the computed disassembly played back along the report's removal paths.
// It only draws: every fact it shows (parts, key, paths) comes from the core's report.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { element } from './dom.js';

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

export class AssemblyView {
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

