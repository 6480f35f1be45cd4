// SPDX-License-Identifier: GPL-3.0-or-later
//
// Picking in the 3D view (view.js): which part is drawn at a point of the canvas (a click selects
// it, hovering names it), where a part is on the screen, and whether a press and release were a
// click or an orbit drag. Functions of the camera, the canvas and the part meshes.

import * as THREE from 'three';

/** A pointer that moves less than this between press and release is a click, not an orbit. */
export const CLICK_SLOP_PX = 5;

/** Whether a press at `down` ({ x, y }) and a release `event` (clientX, clientY) make a click. */
export function isClick(down, event) {
  return Boolean(down) && Math.hypot(event.clientX - down.x, event.clientY - down.y) <= CLICK_SLOP_PX;
}

/**
 * The part id of the nearest opaque visible mesh at client coordinates (x, y) of `canvas`, or
 * null. See-through parts (a witness's others, a session's remainder) let the pointer through.
 */
export function pickPart(raycaster, camera, canvas, meshes, clientX, clientY) {
  const bounds = canvas.getBoundingClientRect();
  if (!(bounds.width > 0 && bounds.height > 0)) return null;
  const pointer = new THREE.Vector2(
    ((clientX - bounds.left) / bounds.width) * 2 - 1,
    -((clientY - bounds.top) / bounds.height) * 2 + 1,
  );
  raycaster.setFromCamera(pointer, camera);
  const hit = raycaster
    .intersectObjects([...meshes], false)
    .find((candidate) => candidate.object.visible && (candidate.object.userData.baseOpacity ?? 1) === 1);
  return hit ? hit.object.userData.partId : null;
}

/** Where the centre of `mesh`'s bounding box is on the screen, in client coordinates. */
export function screenPointOf(mesh, camera, canvas) {
  mesh.updateWorldMatrix(true, false);
  const centre = mesh.geometry.boundingBox.getCenter(new THREE.Vector3()).applyMatrix4(mesh.matrixWorld).project(camera);
  const bounds = canvas.getBoundingClientRect();
  return { x: bounds.left + ((centre.x + 1) / 2) * bounds.width, y: bounds.top + ((1 - centre.y) / 2) * bounds.height };
}
