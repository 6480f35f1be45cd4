// SPDX-License-Identifier: GPL-3.0-or-later
//
// The camera of the 3D view (view.js): framing a box from the usual three-quarter view, keeping
// the user's viewing direction and relative zoom when what is framed grows or shrinks (explode,
// a played disassembly), the depth range that goes with a distance, and how much of the view the
// visible parts cover (for tests: a finished result should fill the view, issue 28). Functions of
// a three.js PerspectiveCamera and its OrbitControls; the view keeps what was framed.

import * as THREE from 'three';

/** The direction the camera looks from, towards the framed box's centre. */
const VIEW_DIRECTION = new THREE.Vector3(1, 0.85, 1.5).normalize();
/** Room around the framed box's bounding sphere. */
const MARGIN = 1.25;

/** The distance at which `box`'s bounding sphere fits the narrower field of view, with a margin. */
export function fitDistance(camera, box) {
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1);
  // The narrower of the vertical and horizontal fields of view decides what fits.
  const verticalHalfFov = THREE.MathUtils.degToRad(camera.fov / 2);
  const horizontalHalfFov = Math.atan(Math.tan(verticalHalfFov) * camera.aspect);
  return (radius / Math.sin(Math.min(verticalHalfFov, horizontalHalfFov))) * MARGIN;
}

/** Near and far planes (and the farthest zoom) for a camera `distance` from its target. */
export function setDepthRange(camera, controls, distance) {
  camera.near = distance / 100;
  camera.far = distance * 50;
  camera.updateProjectionMatrix();
  controls.maxDistance = distance * 10;
}

/** Puts the camera in front of `box` from the usual three-quarter view; returns { center, distance }. */
export function fitCamera(camera, controls, box) {
  const center = box.getCenter(new THREE.Vector3());
  const distance = fitDistance(camera, box);
  camera.position.copy(center).addScaledVector(VIEW_DIRECTION, distance);
  controls.target.copy(center);
  setDepthRange(camera, controls, distance);
  controls.update();
  return { center, distance };
}

/**
 * Frames `box` keeping the user's viewing direction and zoom relative to what was framed before
 * (`framed`, fitCamera's result); returns the new { center, distance }.
 */
export function reframeCamera(camera, controls, box, framed) {
  const center = box.getCenter(new THREE.Vector3());
  const distance = fitDistance(camera, box);
  const ratio = distance / framed.distance;
  const offset = camera.position.clone().sub(controls.target).multiplyScalar(ratio);
  controls.target.copy(center);
  camera.position.copy(center).add(offset);
  setDepthRange(camera, controls, Math.max(distance, offset.length()));
  controls.update();
  return { center, distance };
}

/**
 * The share of the view's width and height the visible `meshes` cover on screen (0..1 each: the
 * box around their projected bounding-box corners, clipped to the view). World matrices must be
 * current.
 */
export function screenFill(camera, meshes) {
  const box = new THREE.Box3();
  const corner = new THREE.Vector3();
  let minX = Infinity; let maxX = -Infinity; let minY = Infinity; let maxY = -Infinity;
  for (const mesh of meshes) {
    if (!mesh.visible) continue;
    box.copy(mesh.geometry.boundingBox).applyMatrix4(mesh.matrixWorld);
    for (let k = 0; k < 8; k += 1) {
      corner.set(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z).project(camera);
      minX = Math.min(minX, corner.x); maxX = Math.max(maxX, corner.x);
      minY = Math.min(minY, corner.y); maxY = Math.max(maxY, corner.y);
    }
  }
  if (!Number.isFinite(minX)) return { fillWidth: 0, fillHeight: 0 };
  const clip = (value) => Math.min(Math.max(value, -1), 1);
  return { fillWidth: (clip(maxX) - clip(minX)) / 2, fillHeight: (clip(maxY) - clip(minY)) / 2 };
}
