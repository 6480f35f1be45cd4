// SPDX-License-Identifier: GPL-3.0-or-later
//
// The motions the 3D view plays (view.js), computed from the core's report and nothing else:
// each part's removal path as waypoints (removalMotions), a plan of moves of several parts as
// offsets per move (stepMotions, issue 27), the tray beside the assembly where removed parts land
// (layOutTray), and a plate plan's removal as a disassembly (planDisassembly, withPlannedRemoval).
// Also the words for them shared with the report (formatDirection, formatStep, formatLevel).
// No scene, no DOM: three.js vectors and boxes only.

import * as THREE from 'three';

/** How far a part keeps going after its last move before it disappears, in voxels. */
export const RUN_OUT_VOXELS = 2;

/**
 * '+y' -> (0, 1, 0); a move's own `vector` (a plate plan's removal direction) first, then the
 * report's base directions, then the axis notation.
 */
export function directionVector(label, baseDirections = [], vector = null) {
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

/**
 * Places the removed parts (`parts`: { partId, box } in removal order, boxes in the content's
 * frame) on the floor beside the assembly (`assembly`: { min, max } arrays): rows running along
 * +x, starting past where the exploded assembly can reach, the next row behind (+z); the rows
 * are about as long as the tray is deep. Places snap to `cell` (voxels stay on the grid).
 * Returns { slots: Map(partId -> translation of the part), box: the tray's bounds }.
 */
export function layOutTray(parts, assembly, cell) {
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
export function removalMotions(report, scale = { step: 1, runOut: RUN_OUT_VOXELS }) {
  const motions = new Map();
  const disassembly = report.disassembly;
  if (!disassembly?.order?.length) return motions;
  disassembly.order.forEach((partId, index) => {
    const path = disassembly.paths?.[index] ?? [];
    const waypoints = [new THREE.Vector3()];
    for (const move of path) {
      // A mesh plan's finite move gives its `length` in mm, the unit its surfaces are drawn in.
      const distance = Number(move.length) > 0 ? Number(move.length) : (Number(move.steps) || 0) * scale.step;
      const step = directionVector(move.dir, report.baseDirections, move.vector).multiplyScalar(distance);
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
export function pointAlong(waypoints, fraction) {
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
export function stepMotions(steps, boxes, scale) {
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
    // A mesh plan's finite move is in mm already (its `length`), the unit its surfaces are drawn in.
    let delta = Number(step?.length) > 0 ? move.clone() : move.clone().multiplyScalar(scale.step);
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
