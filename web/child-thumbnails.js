// SPDX-License-Identifier: GPL-3.0-or-later
//
// Step by step: small pictures of the ranked children of the session's node, side by side. One
// small offscreen three.js renderer (a second WebGL context, made on first use) draws each child
// from the part surfaces the core returned into an image: the new part highlighted, the
// remainder ghosted, the placed parts as usual, all from the same three-quarter view so the
// children compare at a glance (the key, part 1, gold as in the main view). Clicking a picture previews that child; double-clicking chooses it.
//
// For tests: #session-children[data-count] (pictures shown), each button [data-index].

import * as THREE from 'three';
import { KEY_COLOR_CSS, partColor } from './view.js';

const SIZE = { width: 112, height: 84 };
const GHOST_OPACITY = 0.2;
const HIGHLIGHT_EDGE_COLOR = 0xffffff;
const EDGE_COLOR = 0x101215;

/**
 * `container`: the element the pictures go into. `onPreview(index)` / `onChoose(index)`: what a
 * click / double-click (or Enter) on a picture does.
 */
export function createChildThumbnails(container, { onPreview, onChoose }) {
  let painter = null; // made on first use; false when WebGL is unavailable

  function painterOrNull() {
    if (painter === null) painter = makePainter();
    return painter || null;
  }

  /**
   * Shows the children `[{ index, surfaces }]` of a node whose new part will be `newPart` and whose
   * remainder will be `remainder` (part ids). The selected child is marked.
   */
  function show(children, { newPart, remainder, selected = null }) {
    container.replaceChildren();
    const paint = painterOrNull();
    for (const { index, surfaces } of children) {
      const button = container.ownerDocument.createElement('button');
      button.type = 'button';
      button.className = 'child-thumbnail';
      button.dataset.index = String(index);
      button.setAttribute('aria-pressed', String(index === selected));
      button.title = `Child ${index}${index === 0 ? ' (best ranked)' : ''}: click to preview, double-click to choose`;
      if (paint) {
        const image = container.ownerDocument.createElement('img');
        image.alt = `child ${index}`;
        image.width = SIZE.width;
        image.height = SIZE.height;
        image.src = paint(surfaces, { newPart, remainder });
        button.append(image);
      }
      const caption = container.ownerDocument.createElement('span');
      caption.textContent = index === 0 ? '0 · best' : `${index}`;
      button.append(caption);
      button.addEventListener('click', () => onPreview(index));
      button.addEventListener('dblclick', () => onChoose(index));
      container.append(button);
    }
    container.dataset.count = String(children.length);
    container.hidden = children.length === 0;
  }

  function markSelected(index) {
    for (const button of container.querySelectorAll('.child-thumbnail')) {
      button.setAttribute('aria-pressed', String(Number(button.dataset.index) === index));
    }
  }

  function clear() {
    container.replaceChildren();
    container.dataset.count = '0';
    container.hidden = true;
  }

  function dispose() {
    clear();
    if (painter) painter.dispose();
    painter = false;
  }

  return { show, markSelected, clear, dispose };
}

/** A function (surfaces, emphasis) -> PNG data URL, or false without WebGL. */
function makePainter() {
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  } catch {
    return false;
  }
  renderer.setPixelRatio(1);
  renderer.setSize(SIZE.width, SIZE.height, false);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x1b1e24);
  scene.add(new THREE.HemisphereLight(0xf4f6ff, 0x3a3328, 1.6));
  const camera = new THREE.PerspectiveCamera(40, SIZE.width / SIZE.height, 0.1, 1000);
  const headLight = new THREE.DirectionalLight(0xffffff, 1.6);
  headLight.position.set(0.6, 1, 0.4);
  camera.add(headLight);
  scene.add(camera);
  const content = new THREE.Group();
  scene.add(content);

  function paint(surfaces, { newPart, remainder }) {
    for (const part of surfaces) content.add(partMesh(part, part.partId === newPart, part.partId === remainder));
    frame(camera, new THREE.Box3().setFromObject(content));
    renderer.render(scene, camera);
    const url = renderer.domElement.toDataURL('image/png');
    for (const mesh of [...content.children]) {
      mesh.geometry.dispose();
      mesh.material.dispose();
      mesh.children[0]?.geometry.dispose();
      mesh.children[0]?.material.dispose();
    }
    content.clear();
    return url;
  }
  paint.dispose = () => {
    renderer.dispose();
    renderer.forceContextLoss();
  };
  return paint;
}

function partMesh({ partId, positions, normals }, highlighted, ghosted) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  // Part 1 is the key of every voxel step: gold, as in the main view.
  const color = partId === 1 ? new THREE.Color(KEY_COLOR_CSS) : partColor(partId);
  const material = new THREE.MeshStandardMaterial({
    color,
    roughness: 0.7,
    transparent: ghosted,
    opacity: ghosted ? GHOST_OPACITY : 1,
    depthWrite: !ghosted,
    emissive: highlighted ? color.clone().multiplyScalar(0.45) : new THREE.Color(0),
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  const mesh = new THREE.Mesh(geometry, material);
  // Ghosted parts after the solid ones, so the solid parts show through them.
  mesh.renderOrder = ghosted ? 1 : 0;
  if (!ghosted) {
    mesh.add(new THREE.LineSegments(
      new THREE.EdgesGeometry(geometry, 30),
      new THREE.LineBasicMaterial({ color: highlighted ? HIGHLIGHT_EDGE_COLOR : EDGE_COLOR }),
    ));
  }
  return mesh;
}

/** The main view's three-quarter view direction, at a distance that fits `box`. */
function frame(camera, box) {
  const center = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1);
  const halfFov = THREE.MathUtils.degToRad(camera.fov / 2);
  const distance = (radius / Math.sin(Math.min(halfFov, Math.atan(Math.tan(halfFov) * camera.aspect)))) * 1.1;
  camera.position.copy(center).addScaledVector(new THREE.Vector3(1, 0.85, 1.5).normalize(), distance);
  camera.lookAt(center);
  camera.near = distance / 100;
  camera.far = distance * 50;
  camera.updateProjectionMatrix();
}
