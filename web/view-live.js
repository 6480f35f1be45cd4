// SPDX-License-Identifier: GPL-3.0-or-later
//
// Live design's picture (issue 28, item 8): the deepest node of a running design drawn as a few
// merged meshes (the placed parts in their colours, the remainder see-through, and their
// outlines) instead of two meshes per part: a voxel node's surfaces, or a plate or frame input's
// own surfaces with the parts its plan has not placed yet see-through (web/main.js). Every mesh is a draw call, and a live design redraws
// many times a second: 140 parts were 280 draw calls a frame, 170-300 ms of the page's main
// thread per frame in software WebGL, where four merged meshes take about a third of that. The
// materials are made once and kept (a new material compiles its shader program again), and the
// outline of a part whose surface did not change since the last node is kept too.
//
// Exports: LiveDrawing (used by AssemblyView.showLive in view.js), equalFloats.

import * as THREE from 'three';

/** Outline edges: faces meeting at more than this angle (degrees), as the per-part view draws them. */
const EDGE_THRESHOLD_DEGREES = 30;

export class LiveDrawing {
  #group = new THREE.Group();
  #materials;
  #partColor;
  /** partId -> { positions, edges }: the part's surface positions and its outline segments. */
  #outlines = new Map();

  /**
   * `partColor(partId)` gives a part's THREE.Color; `edgeColor` the outline colour;
   * `edgeOpacity`, `ghostOpacity` and `ghostEdgeOpacity` how opaque the outlines and the remainder are.
   */
  constructor({ partColor, edgeColor, edgeOpacity, ghostOpacity, ghostEdgeOpacity }) {
    this.#partColor = partColor;
    const surface = (opacity) => new THREE.MeshStandardMaterial({
      vertexColors: true,
      roughness: 0.7,
      metalness: 0.0,
      transparent: opacity < 1,
      opacity,
      depthWrite: opacity >= 1,
      // Push the faces back a little so the outline edges win the depth test (as view.js does).
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    });
    const lines = (opacity) => new THREE.LineBasicMaterial({ color: edgeColor, transparent: true, opacity });
    this.#materials = {
      placed: surface(1), ghost: surface(ghostOpacity), placedEdges: lines(edgeOpacity), ghostEdges: lines(ghostEdgeOpacity),
    };
    this.#group.name = 'live design';
  }

  /**
   * The group to add to the scene, drawing `surfaces` (the core's part surfaces) with the parts in
   * `ghost` (a Set of part ids) see-through. Replaces what the last call drew.
   */
  update(surfaces, ghost) {
    this.clear();
    const placed = surfaces.filter((surface) => !ghost.has(surface.partId));
    const ghosted = surfaces.filter((surface) => ghost.has(surface.partId));
    this.#add(mergedSurface(placed, this.#partColor), this.#materials.placed, THREE.Mesh);
    this.#add(mergedSurface(ghosted, this.#partColor), this.#materials.ghost, THREE.Mesh);
    this.#add(this.#mergedOutlines(placed), this.#materials.placedEdges, THREE.LineSegments);
    this.#add(this.#mergedOutlines(ghosted), this.#materials.ghostEdges, THREE.LineSegments);
    // Outlines of parts no longer drawn are forgotten.
    const drawn = new Set(surfaces.map((surface) => surface.partId));
    for (const partId of this.#outlines.keys()) if (!drawn.has(partId)) this.#outlines.delete(partId);
    return this.#group;
  }

  /**
   * One small object per material, to compile their shader programs before the first picture
   * (AssemblyView.prepareLive); free it with disposeSample.
   */
  sample() {
    const geometry = new THREE.BufferGeometry();
    const triangle = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]);
    geometry.setAttribute('position', new THREE.BufferAttribute(triangle, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]), 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(9).fill(1), 3));
    const group = new THREE.Group();
    const { placed, ghost, placedEdges, ghostEdges } = this.#materials;
    group.add(new THREE.Mesh(geometry, placed), new THREE.Mesh(geometry, ghost),
      new THREE.LineSegments(geometry, placedEdges), new THREE.LineSegments(geometry, ghostEdges));
    return group;
  }

  /** Frees what sample() made (its materials are the drawing's own and stay). */
  static disposeSample(group) {
    group.children[0]?.geometry.dispose();
    group.clear();
  }

  /** Frees the merged geometries (the materials stay for the next update). */
  clear() {
    for (const child of this.#group.children) child.geometry.dispose();
    this.#group.clear();
    this.#group.removeFromParent();
  }

  /** Frees everything; the drawing cannot be used afterwards. */
  dispose() {
    this.clear();
    this.#outlines.clear();
    for (const material of Object.values(this.#materials)) material.dispose();
  }

  #add(geometry, material, Kind) {
    if (!geometry) return;
    this.#group.add(new Kind(geometry, material));
  }

  /** The outline segments of `surfaces`, one geometry; a part's outline is made once per surface. */
  #mergedOutlines(surfaces) {
    const parts = surfaces.map((surface) => this.#outline(surface));
    const length = parts.reduce((sum, edges) => sum + edges.length, 0);
    if (length === 0) return null;
    const positions = new Float32Array(length);
    let at = 0;
    for (const edges of parts) {
      positions.set(edges, at);
      at += edges.length;
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    return geometry;
  }

  #outline({ partId, positions }) {
    const known = this.#outlines.get(partId);
    if (known && equalFloats(known.positions, positions)) return known.edges;
    const surface = new THREE.BufferGeometry();
    surface.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    const outline = new THREE.EdgesGeometry(surface, EDGE_THRESHOLD_DEGREES);
    const edges = outline.getAttribute('position').array;
    surface.dispose();
    outline.dispose();
    this.#outlines.set(partId, { positions, edges });
    return edges;
  }
}

/** The triangles of `surfaces` as one geometry, each vertex in its part's colour; null if none. */
function mergedSurface(surfaces, partColor) {
  const length = surfaces.reduce((sum, surface) => sum + surface.positions.length, 0);
  if (length === 0) return null;
  const positions = new Float32Array(length);
  const normals = new Float32Array(length);
  const colors = new Float32Array(length);
  let at = 0;
  for (const surface of surfaces) {
    positions.set(surface.positions, at);
    normals.set(surface.normals, at);
    const { r, g, b } = partColor(surface.partId);
    for (let k = at; k < at + surface.positions.length; k += 3) {
      colors[k] = r;
      colors[k + 1] = g;
      colors[k + 2] = b;
    }
    at += surface.positions.length;
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(colors, 3));
  geometry.computeBoundingSphere();
  return geometry;
}

/** Whether two float arrays hold the same numbers (a part surface that did not change). */
export function equalFloats(a, b) {
  if (a === b) return true;
  if (a.length !== b.length) return false;
  for (let k = 0; k < a.length; k += 1) if (a[k] !== b[k]) return false;
  return true;
}
