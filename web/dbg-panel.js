// SPDX-License-Identifier: GPL-3.0-or-later
//
// Draws the base directional blocking graphs of a check report as SVG (Section 3.1 of the
// paper): one small graph G(d) per base direction, nodes = parts in their 3D colours with the
// key marked, an arrow a → b when part a is blocked by part b moving along d, and the strongly
// connected components as shaded arcs. All graph facts (edges, components, key) come from the
// core's report; this module only lays them out: nodes on a circle, each component's parts next
// to each other, so the drawing is the same every time for the same report.
//
// Large assemblies (issue 11: useful at 40-200 parts): above MAX_DRAWN_NODES parts a graph is
// drawn on a larger canvas (node spacing kept, so its labels stay readable when zoomed), up to
// MAX_PART_NODES parts; above that with its components as nodes (an interlocking assembly has at
// most two per graph: the key and the rest), and with too many components for that as well only
// a note is shown (the report panel keeps the table). Every drawing zooms (wheel, + / − buttons
// or keys) and pans (drag, arrow keys); Find part highlights a part's nodes and centres them; the
// Matrix view shows one graph at a time as an N x N adjacency matrix (row a, column b filled when
// a is blocked by b), scrollable, which stays readable where arrows no longer do.
//
// For tests: figure.dbg-graph[data-direction, data-nodes, data-edges, data-components,
// data-drawn = parts | components | none], circle.dbg-node[data-part, data-key],
// path.dbg-edge[data-from, data-to]; the container gets data-graphs and data-key.
// Zoom and pan: g.dbg-zoom[transform] in each drawing, figure[data-zoom] its scale;
// container[data-view = drawing | matrix]; the matrix: div.dbg-matrix[data-direction, data-size,
// data-cells, data-edges] with rect.dbg-cell[data-row, data-col, data-edge]; Find part:
// #dbg-find-status.
//
// Selection (the playground's part list, parts-panel.js): a click on a part's node dispatches a
// bubbling 'dbg-select' event ({ detail: { partId } }) from the container instead of zooming the
// graph, and highlightGraphPart(container, partId) marks that part's nodes
// (circle.dbg-node[data-selected="true"], container[data-selected]) and its matrix row and column;
// it survives a new drawing. findGraphPart(container, partId) does what Find part does: highlight,
// centre, and a 'dbg-select' event.

import { KEY_COLOR_CSS, partColorCss } from './view.js';

const SVG_NS = 'http://www.w3.org/2000/svg';
/** Above this many nodes a circle drawing stops being readable at the panel's size. */
export const MAX_DRAWN_NODES = 30;
/** Up to this many parts a graph is still drawn part by part, on a canvas that grows with them. */
export const MAX_PART_NODES = 200;
/** Zoom limits (scale of a drawing) and the step of one button press or key. */
const MIN_ZOOM = 1;
const MAX_ZOOM = 12;
const ZOOM_STEP = 1.5;
/** Find part zooms in at least this far on large drawings, so the node is told from its neighbours. */
const FIND_ZOOM = 3;

const VIEW_SIZE = 220;
const EDGE_COLOR = '#8d96a6';
const NODE_STROKE = '#101215';
const LABEL_COLOR = '#101215';
/** Translucent backgrounds of the strongly connected components, in turn. */
const COMPONENT_COLORS = ['#5b8bd0', '#b27ad6', '#4fb394', '#d68a5b', '#c2c24f', '#d86f98', '#63b6d8'];

/** Marker ids must be unique in the page (several drawings, several panels). */
let drawingSerial = 0;

function svg(tag, attributes = {}, text) {
  const node = document.createElementNS(SVG_NS, tag);
  for (const [name, value] of Object.entries(attributes)) node.setAttribute(name, String(value));
  if (text !== undefined) node.textContent = text;
  return node;
}

function html(tag, text, className) {
  const node = document.createElement(tag);
  if (text !== undefined) node.textContent = text;
  if (className) node.className = className;
  return node;
}

function round(value) {
  return Math.round(value * 100) / 100;
}

function plural(count, singular, pluralForm = `${singular}s`) {
  return `${count} ${count === 1 ? singular : pluralForm}`;
}

function describeComponent(component) {
  return component.length <= 4 ? `{${component.join(', ')}}` : `{${component.length} parts}`;
}

/**
 * The graph's nodes in drawing order: components ordered by their smallest part id, parts
 * ascending within each, so every component occupies one arc of the circle. Parts the report
 * lists but no component mentions (none, in a well-formed report) become components of one.
 */
function orderedComponents(graph, partIds) {
  const seen = new Set();
  const components = (graph.components ?? []).map((component) => {
    const sorted = [...component].sort((a, b) => a - b);
    for (const partId of sorted) seen.add(partId);
    return sorted;
  });
  for (const partId of partIds) if (!seen.has(partId)) components.push([partId]);
  return components.sort((a, b) => a[0] - b[0]);
}

// ---------------------------------------------------------------------------------------------
// Layout helpers

/**
 * The drawing's side in SVG units: the panel's size up to MAX_DRAWN_NODES nodes, beyond that grown
 * so that nodes keep about 9 units of circle each (the drawing is shrunk to the panel and zoomed).
 */
function viewSizeFor(count) {
  if (count <= MAX_DRAWN_NODES) return VIEW_SIZE;
  return Math.max(VIEW_SIZE, Math.round((count * 9) / Math.PI + 60));
}

function circleLayout(count, nodeRadius, outsideLabels, size = VIEW_SIZE) {
  const center = size / 2;
  const radius = center - nodeRadius - (outsideLabels ? 14 : 6);
  const angles = Array.from({ length: count }, (_, index) => -Math.PI / 2 + (2 * Math.PI * index) / count);
  // A single node (a strongly connected graph drawn by components) sits in the middle.
  const at = (angle) => (count === 1 ? { angle, x: center, y: center } : { angle, x: center + radius * Math.cos(angle), y: center + radius * Math.sin(angle) });
  return { center, radius, points: angles.map(at) };
}

/** Node radius for `count` nodes: large for a few parts, never overlapping for many. */
function nodeRadiusFor(count, size = VIEW_SIZE) {
  const spacing = (2 * Math.PI * (size / 2 - 20)) / Math.max(count, 1);
  return Math.max(3.5, Math.min(12, spacing * 0.4));
}

/**
 * A directed edge as a slightly bent curve from the boundary of one node to the boundary of the
 * other: bending every edge to its left keeps a pair a → b, b → a apart.
 */
function edgePath(from, to, fromRadius, toRadius) {
  const dx = to.x - from.x;
  const dy = to.y - from.y;
  const length = Math.hypot(dx, dy) || 1;
  const bend = 0.12 * length + 3;
  const control = { x: (from.x + to.x) / 2 + (dy / length) * bend, y: (from.y + to.y) / 2 - (dx / length) * bend };
  const trim = (point, radius) => {
    const ux = control.x - point.x;
    const uy = control.y - point.y;
    const norm = Math.hypot(ux, uy) || 1;
    return { x: point.x + (ux / norm) * radius, y: point.y + (uy / norm) * radius };
  };
  const start = trim(from, fromRadius + 1);
  const end = trim(to, toRadius + 1.5);
  return `M${round(start.x)},${round(start.y)} Q${round(control.x)},${round(control.y)} ${round(end.x)},${round(end.y)}`;
}

/** The arc band behind the nodes first..last (indices into the layout) of one component. */
function componentBand(layout, first, last, count, width, color) {
  if (last - first + 1 >= count) {
    return svg('circle', {
      cx: layout.center, cy: layout.center, r: round(layout.radius),
      fill: 'none', stroke: color, 'stroke-opacity': 0.3, 'stroke-width': round(width),
    });
  }
  const half = (Math.PI / count) * 0.8;
  const start = layout.points[first].angle - half;
  const end = layout.points[last].angle + half;
  const point = (angle) => `${round(layout.center + layout.radius * Math.cos(angle))},${round(layout.center + layout.radius * Math.sin(angle))}`;
  const largeArc = end - start > Math.PI ? 1 : 0;
  return svg('path', {
    d: `M${point(start)} A${round(layout.radius)},${round(layout.radius)} 0 ${largeArc} 1 ${point(end)}`,
    fill: 'none', stroke: color, 'stroke-opacity': 0.3, 'stroke-width': round(width), 'stroke-linecap': 'round',
  });
}

function arrowMarker(id, color) {
  const marker = svg('marker', {
    id, viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 5.5, markerHeight: 5.5,
    markerUnits: 'strokeWidth', orient: 'auto',
  });
  marker.append(svg('path', { d: 'M0,0 L10,5 L0,10 z', fill: color }));
  return marker;
}

// ---------------------------------------------------------------------------------------------
// One graph

/**
 * Draws `nodes` ({ id, label, title, fill, radiusScale, isKey, partId? }) on a circle with
 * `edges` ({ from, to, title }) between node ids and the component bands (`groups`: arrays of
 * consecutive node indices of components with two or more nodes).
 */
function drawGraph({ nodes, edges, groups, label }) {
  drawingSerial += 1;
  const markerId = `dbg-arrow-${drawingSerial}`;
  const keyMarkerId = `dbg-arrow-key-${drawingSerial}`;
  const size = viewSizeFor(nodes.length);
  const baseRadius = nodeRadiusFor(nodes.length, size);
  const insideLabels = baseRadius >= 7;
  const layout = circleLayout(nodes.length, baseRadius * Math.max(...nodes.map((node) => node.radiusScale ?? 1)), !insideLabels, size);
  const position = new Map(nodes.map((node, index) => [node.id, { ...layout.points[index], node, index }]));
  const radiusOf = (node) => baseRadius * (node.radiusScale ?? 1);

  const root = svg('svg', {
    viewBox: `0 0 ${size} ${size}`, role: 'img', 'aria-label': label, class: 'dbg-svg', tabindex: 0,
  });
  const defs = svg('defs');
  defs.append(arrowMarker(markerId, EDGE_COLOR), arrowMarker(keyMarkerId, KEY_COLOR_CSS));
  // Everything drawn sits in one group whose transform is the zoom and pan (zoomable below).
  const zoomed = svg('g', { class: 'dbg-zoom', transform: 'translate(0 0) scale(1)' });
  root.append(defs, zoomed);

  const bands = svg('g', { class: 'dbg-components' });
  groups.forEach((group, index) => {
    const band = componentBand(layout, group[0], group[group.length - 1], nodes.length,
      2 * baseRadius + 8, COMPONENT_COLORS[index % COMPONENT_COLORS.length]);
    band.setAttribute('class', 'dbg-component');
    band.setAttribute('data-size', String(group.length));
    bands.append(band);
  });
  zoomed.append(bands);

  const edgeLayer = svg('g', { class: 'dbg-edges', fill: 'none' });
  for (const edge of edges) {
    const from = position.get(edge.from);
    const to = position.get(edge.to);
    if (!from || !to) continue;
    const touchesKey = from.node.isKey || to.node.isKey;
    const path = svg('path', {
      class: 'dbg-edge',
      d: edgePath(from, to, radiusOf(from.node), radiusOf(to.node)),
      stroke: touchesKey ? KEY_COLOR_CSS : EDGE_COLOR,
      'stroke-width': nodes.length > 16 ? 1 : 1.3,
      'stroke-opacity': touchesKey ? 0.95 : 0.75,
      'marker-end': `url(#${touchesKey ? keyMarkerId : markerId})`,
      'data-from': edge.from,
      'data-to': edge.to,
    });
    path.append(svg('title', {}, edge.title));
    edgeLayer.append(path);
  }
  zoomed.append(edgeLayer);

  const nodeLayer = svg('g', { class: 'dbg-nodes' });
  for (const { x, y, angle, node } of position.values()) {
    const radius = radiusOf(node);
    const group = svg('g', { class: 'dbg-node-group' });
    if (node.isKey) {
      group.append(svg('circle', { cx: round(x), cy: round(y), r: round(radius + 3), fill: 'none', stroke: KEY_COLOR_CSS, 'stroke-width': 2 }));
    } else if (node.singleton) {
      // A part that is a component by itself: a dashed ring (in an interlocking assembly only the key is).
      group.append(svg('circle', { cx: round(x), cy: round(y), r: round(radius + 3), fill: 'none', stroke: EDGE_COLOR, 'stroke-width': 1, 'stroke-dasharray': '2 2' }));
    }
    const circle = svg('circle', {
      class: 'dbg-node', cx: round(x), cy: round(y), r: round(radius),
      fill: node.fill, stroke: NODE_STROKE, 'stroke-width': 1,
      'data-key': String(Boolean(node.isKey)),
    });
    if (node.partId !== undefined) circle.setAttribute('data-part', String(node.partId));
    if (node.size !== undefined) circle.setAttribute('data-size', String(node.size));
    group.append(circle);
    if (insideLabels) {
      group.append(svg('text', {
        x: round(x), y: round(y), 'text-anchor': 'middle', 'dominant-baseline': 'central',
        'font-size': round(Math.min(radius * (node.label.length > 2 ? 0.8 : 1.05), 12)), 'font-weight': 600, fill: LABEL_COLOR,
      }, node.label));
    } else {
      const labelRadius = layout.radius + radius + 7;
      group.append(svg('text', {
        x: round(layout.center + labelRadius * Math.cos(angle)), y: round(layout.center + labelRadius * Math.sin(angle)),
        'text-anchor': 'middle', 'dominant-baseline': 'central', 'font-size': 7, fill: node.isKey ? KEY_COLOR_CSS : '#c3c8d1',
      }, node.label));
    }
    group.append(svg('title', {}, node.title));
    nodeLayer.append(group);
  }
  zoomed.append(nodeLayer);
  return root;
}

/** Who blocks whom, for a node's tooltip. */
function neighbourLists(edges) {
  const blockedBy = new Map();
  const blocks = new Map();
  for (const [from, to] of edges) {
    if (!blockedBy.has(from)) blockedBy.set(from, []);
    if (!blocks.has(to)) blocks.set(to, []);
    blockedBy.get(from).push(to);
    blocks.get(to).push(from);
  }
  return { blockedBy, blocks };
}

/** The drawing of one graph with a node per part. */
function partGraph(graph, components, keyId) {
  const { blockedBy, blocks } = neighbourLists(graph.edges ?? []);
  const nodes = [];
  const groups = [];
  for (const component of components) {
    const first = nodes.length;
    for (const partId of component) {
      const isKey = partId === keyId;
      const list = (map) => (map.get(partId)?.length ? map.get(partId).join(', ') : 'none');
      nodes.push({
        id: partId,
        partId,
        label: String(partId),
        fill: partColorCss(partId, keyId),
        isKey,
        singleton: component.length === 1,
        title: `part ${partId}${isKey ? ' (key)' : ''}: blocked by ${list(blockedBy)} along ${graph.direction}; blocks ${list(blocks)}`,
      });
    }
    if (component.length > 1) groups.push(Array.from({ length: component.length }, (_, index) => first + index));
  }
  const edges = (graph.edges ?? []).map(([from, to]) => ({ from, to, title: `part ${from} is blocked by part ${to} along ${graph.direction}` }));
  return { nodes, edges, groups };
}

/**
 * The drawing of one graph with a node per component (the condensation): edges between parts of
 * different components are shown once per pair of components, with their count in the tooltip.
 */
function componentGraph(graph, components, keyId) {
  const componentOf = new Map();
  components.forEach((component, index) => {
    for (const partId of component) componentOf.set(partId, index);
  });
  const counts = new Map();
  for (const [from, to] of graph.edges ?? []) {
    const a = componentOf.get(from);
    const b = componentOf.get(to);
    if (a === undefined || b === undefined || a === b) continue;
    const id = `${a}>${b}`;
    counts.set(id, (counts.get(id) ?? 0) + 1);
  }
  let colorIndex = 0;
  const nodes = components.map((component, index) => {
    if (component.length === 1) {
      const partId = component[0];
      return {
        id: index, partId, label: String(partId), fill: partColorCss(partId, keyId), isKey: partId === keyId, singleton: true,
        title: `part ${partId}${partId === keyId ? ' (key)' : ''}: a component by itself`,
      };
    }
    const fill = COMPONENT_COLORS[colorIndex % COMPONENT_COLORS.length];
    colorIndex += 1;
    return {
      id: index, size: component.length, label: `{${component.length}}`, fill, isKey: false, radiusScale: 2,
      title: `a strongly connected component of ${component.length} parts: ${component.join(', ')}`,
    };
  });
  const edges = [...counts].map(([id, count]) => {
    const [from, to] = id.split('>').map(Number);
    return { from, to, title: `${plural(count, 'blocking relation')} from ${nodes[from].label} to ${nodes[to].label}` };
  });
  return { nodes, edges, groups: [] };
}

function caption(graph, components) {
  const edges = graph.edges?.length ?? 0;
  const summary = components.length === 1
    ? '1 SCC: strongly connected'
    : `${components.length} SCCs: ${components.slice(0, 4).map(describeComponent).join(' + ')}${components.length > 4 ? ' + …' : ''}`;
  const figcaption = html('figcaption');
  figcaption.append(html('strong', `G(${graph.direction})`), ` · ${plural(edges, 'edge')} · `, html('span', summary, 'dbg-scc-count'));
  return figcaption;
}

// ---------------------------------------------------------------------------------------------
// Zoom and pan

/** The zoom state of a drawing: scale and translation in its own SVG units. */
function zoomOf(root) {
  return root.__dbgZoom ?? (root.__dbgZoom = { scale: 1, x: 0, y: 0 });
}

function drawingSize(root) {
  return root.viewBox.baseVal.width || VIEW_SIZE;
}

/**
 * Applies `zoom` to a drawing, its canvas kept within half a frame of the frame's edges (so any
 * node, even one on the rim, can be centred, and the graph is never panned out of sight), and
 * records the scale on its figure.
 */
function applyZoom(root, zoom) {
  const size = drawingSize(root);
  zoom.scale = Math.min(MAX_ZOOM, Math.max(MIN_ZOOM, zoom.scale));
  const slack = size * (zoom.scale - 1);
  zoom.x = Math.min(size / 2, Math.max(-slack - size / 2, zoom.x));
  zoom.y = Math.min(size / 2, Math.max(-slack - size / 2, zoom.y));
  root.__dbgZoom = zoom;
  root.querySelector('g.dbg-zoom').setAttribute('transform', `translate(${round(zoom.x)} ${round(zoom.y)}) scale(${round(zoom.scale)})`);
  const figure = root.closest('figure');
  if (figure) figure.dataset.zoom = String(round(zoom.scale));
}

/** Zooms a drawing by `factor` about the point (px, py) in its SVG units (default: its centre). */
function zoomBy(root, factor, px = drawingSize(root) / 2, py = drawingSize(root) / 2) {
  const zoom = zoomOf(root);
  const scale = Math.min(MAX_ZOOM, Math.max(MIN_ZOOM, zoom.scale * factor));
  const ratio = scale / zoom.scale;
  applyZoom(root, { scale, x: px - (px - zoom.x) * ratio, y: py - (py - zoom.y) * ratio });
}

function panBy(root, dx, dy) {
  const zoom = zoomOf(root);
  applyZoom(root, { ...zoom, x: zoom.x + dx, y: zoom.y + dy });
}

/** Puts the drawing's point (cx, cy) (unzoomed SVG units) in the middle, at least at `scale`. */
function centreOn(root, cx, cy, scale) {
  const size = drawingSize(root);
  const zoomScale = Math.max(zoomOf(root).scale, scale);
  applyZoom(root, { scale: zoomScale, x: size / 2 - cx * zoomScale, y: size / 2 - cy * zoomScale });
}

/** A client point in the drawing's SVG units (the SVG is scaled to its box). */
function svgPoint(root, clientX, clientY) {
  const box = root.getBoundingClientRect();
  const size = drawingSize(root);
  return { x: ((clientX - box.left) / (box.width || 1)) * size, y: ((clientY - box.top) / (box.height || 1)) * size };
}

/**
 * Wheel zooms about the pointer, a drag pans (and the click that ends it does not select or
 * enlarge), keys for keyboard users: + and − zoom, 0 resets, arrows pan.
 */
function makeZoomable(root, figure) {
  let drag = null;
  root.addEventListener('wheel', (event) => {
    event.preventDefault();
    const point = svgPoint(root, event.clientX, event.clientY);
    zoomBy(root, Math.exp(-event.deltaY * 0.002), point.x, point.y);
  }, { passive: false });
  root.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    drag = { x: event.clientX, y: event.clientY, moved: false };
  });
  root.addEventListener('pointermove', (event) => {
    if (!drag) return;
    const size = drawingSize(root);
    const box = root.getBoundingClientRect();
    const dx = event.clientX - drag.x;
    const dy = event.clientY - drag.y;
    if (!drag.moved && Math.hypot(dx, dy) < 4) return;
    if (!drag.moved) root.setPointerCapture?.(event.pointerId);
    drag.moved = true;
    panBy(root, (dx / (box.width || 1)) * size, (dy / (box.height || 1)) * size);
    drag.x = event.clientX;
    drag.y = event.clientY;
  });
  const endDrag = () => {
    if (drag?.moved) figure.dataset.dragged = 'true';
    drag = null;
  };
  root.addEventListener('pointerup', endDrag);
  root.addEventListener('pointercancel', endDrag);
  root.addEventListener('keydown', (event) => {
    const step = drawingSize(root) / 10;
    const actions = {
      '+': () => zoomBy(root, ZOOM_STEP), '=': () => zoomBy(root, ZOOM_STEP), '-': () => zoomBy(root, 1 / ZOOM_STEP),
      0: () => applyZoom(root, { scale: 1, x: 0, y: 0 }),
      ArrowLeft: () => panBy(root, step, 0), ArrowRight: () => panBy(root, -step, 0),
      ArrowUp: () => panBy(root, 0, step), ArrowDown: () => panBy(root, 0, -step),
    };
    const action = actions[event.key];
    if (!action) return;
    event.preventDefault();
    action();
  });
  applyZoom(root, zoomOf(root));
}

/** The drawings of the panel (one per drawn graph). */
function drawings(container) {
  return [...container.querySelectorAll('figure.dbg-graph svg.dbg-svg')];
}

// ---------------------------------------------------------------------------------------------
// Adjacency matrix

/** Side of one matrix cell in px: large for a few parts, small enough for 200 to scroll. */
function cellSizeFor(count) {
  return Math.max(6, Math.min(16, Math.floor(480 / Math.max(count, 1))));
}

/**
 * Graph `graph` as an N x N matrix over `partIds` (sorted): row a, column b is filled when part a
 * is blocked by part b along the direction (an edge a → b), gold in the key's row and column.
 * Every cell is a rect (data-row, data-col, data-edge) so a click names its parts.
 */
function drawMatrix(graph, partIds, keyId) {
  const n = partIds.length;
  const cell = cellSizeFor(n);
  const margin = 26;
  const side = margin + n * cell;
  const index = new Map(partIds.map((partId, k) => [partId, k]));
  const edges = new Set((graph.edges ?? []).map(([from, to]) => `${from}>${to}`));
  const root = svg('svg', {
    width: side, height: side, viewBox: `0 0 ${side} ${side}`, role: 'img', class: 'dbg-matrix-svg',
    'aria-label': `Adjacency matrix of G(${graph.direction}): ${n} x ${n} cells, ${edges.size} blocking relations`,
  });
  const labelEvery = n <= 30 ? 1 : n <= 80 ? 5 : 10;
  const labels = svg('g', { class: 'dbg-matrix-labels', 'font-size': Math.min(10, cell + 2), fill: '#c3c8d1' });
  partIds.forEach((partId, k) => {
    if (k % labelEvery !== 0 && partId !== keyId) return;
    const at = margin + k * cell + cell / 2;
    const fill = partId === keyId ? KEY_COLOR_CSS : '#c3c8d1';
    labels.append(svg('text', { x: margin - 3, y: at, 'text-anchor': 'end', 'dominant-baseline': 'central', fill }, String(partId)));
    labels.append(svg('text', { x: at, y: margin - 4, 'text-anchor': 'middle', fill }, String(partId)));
  });
  const cells = svg('g', { class: 'dbg-cells' });
  for (const row of partIds) {
    for (const col of partIds) {
      const edge = edges.has(`${row}>${col}`);
      const touchesKey = row === keyId || col === keyId;
      const rect = svg('rect', {
        class: 'dbg-cell', x: margin + index.get(col) * cell, y: margin + index.get(row) * cell,
        width: cell - 1, height: cell - 1,
        fill: edge ? (touchesKey ? KEY_COLOR_CSS : partColorCss(row, keyId)) : row === col ? '#2a2f38' : '#1f232a',
        'data-row': row, 'data-col': col, 'data-edge': String(edge),
      });
      if (edge) rect.append(svg('title', {}, `part ${row} is blocked by part ${col} along ${graph.direction}`));
      cells.append(rect);
    }
  }
  // The selected part's row and column (highlightGraphPart moves them).
  const selection = svg('g', { class: 'dbg-matrix-selection', fill: 'none', stroke: '#4fd1ff', 'stroke-width': 1.5, visibility: 'hidden' });
  selection.append(svg('rect', { class: 'dbg-matrix-row', x: margin, width: n * cell, height: cell }));
  selection.append(svg('rect', { class: 'dbg-matrix-col', y: margin, height: n * cell, width: cell }));
  root.append(labels, cells, selection);
  root.__dbgMatrix = { index, cell, margin };
  return root;
}

/** The matrix view: a direction switch and the chosen graph's matrix in a scrolling box. */
function matrixView(container, graphs, partIds, keyId) {
  const chosen = graphs.find((graph) => graph.direction === container.dataset.matrixDirection) ?? graphs[0];
  container.dataset.matrixDirection = chosen.direction;
  const view = html('div', undefined, 'dbg-matrix');
  view.dataset.direction = chosen.direction;
  view.dataset.size = String(partIds.length);
  view.dataset.cells = String(partIds.length * partIds.length);
  view.dataset.edges = String(chosen.edges?.length ?? 0);
  const switcher = html('div', undefined, 'dbg-matrix-directions');
  switcher.setAttribute('role', 'group');
  switcher.setAttribute('aria-label', 'Direction of the matrix');
  for (const graph of graphs) {
    const button = html('button', `G(${graph.direction})`, 'button dbg-tool');
    button.type = 'button';
    button.setAttribute('aria-pressed', String(graph === chosen));
    button.addEventListener('click', () => {
      container.dataset.matrixDirection = graph.direction;
      rerender(container);
    });
    switcher.append(button);
  }
  const note = html('p', `Row a, column b filled: part a is blocked by part b moving along ${chosen.direction} `
    + `(${plural(chosen.edges?.length ?? 0, 'relation')}). Click a cell to select its row's part.`, 'dbg-note');
  const scroller = html('div', undefined, 'dbg-matrix-scroll');
  scroller.tabIndex = 0;
  const matrix = drawMatrix(chosen, partIds, keyId);
  matrix.addEventListener('click', (event) => {
    const cell = event.target.closest?.('rect.dbg-cell');
    if (cell) selectPart(container, Number(cell.dataset.row));
  });
  scroller.append(matrix);
  view.append(switcher, note, scroller);
  return view;
}

// ---------------------------------------------------------------------------------------------
// Toolbar: the view, zoom buttons, Find part

function toolButton(label, title, onClick) {
  const button = html('button', label, 'button dbg-tool');
  button.type = 'button';
  button.title = title;
  button.setAttribute('aria-label', title);
  button.addEventListener('click', onClick);
  return button;
}

function toolbar(container, partIds) {
  const bar = html('div', undefined, 'dbg-toolbar');
  const mode = container.dataset.view === 'matrix' ? 'matrix' : 'drawing';
  const views = html('div', undefined, 'dbg-tool-group');
  views.setAttribute('role', 'group');
  views.setAttribute('aria-label', 'Blocking graphs as');
  for (const [value, label] of [['drawing', 'Graphs'], ['matrix', 'Matrix']]) {
    const button = toolButton(label, value === 'drawing' ? 'Show the graphs as drawings' : 'Show a graph as an adjacency matrix', () => {
      container.dataset.view = value;
      rerender(container);
    });
    button.setAttribute('aria-pressed', String(mode === value));
    button.dataset.view = value;
    views.append(button);
  }
  bar.append(views);
  if (mode === 'drawing') {
    const zoom = html('div', undefined, 'dbg-tool-group');
    zoom.append(
      toolButton('+', 'Zoom in', () => drawings(container).forEach((root) => zoomBy(root, ZOOM_STEP))),
      toolButton('−', 'Zoom out', () => drawings(container).forEach((root) => zoomBy(root, 1 / ZOOM_STEP))),
      toolButton('Fit', 'Show the whole graphs', () => drawings(container).forEach((root) => applyZoom(root, { scale: 1, x: 0, y: 0 }))),
    );
    bar.append(zoom);
  }
  const find = html('form', undefined, 'dbg-find');
  const input = html('input');
  input.id = 'dbg-find';
  input.type = 'text';
  input.inputMode = 'numeric';
  input.autocomplete = 'off';
  input.placeholder = 'part';
  input.setAttribute('aria-label', 'Find part by id');
  const status = html('span', '', 'dbg-find-status');
  status.id = 'dbg-find-status';
  status.setAttribute('aria-live', 'polite');
  find.append(input, toolButton('Find', 'Find the part: highlight and centre it', () => find.requestSubmit()), status);
  find.addEventListener('submit', (event) => {
    event.preventDefault();
    const partId = Number(input.value.trim());
    if (!Number.isInteger(partId) || !partIds.includes(partId)) {
      status.textContent = input.value.trim() === '' ? 'type a part id' : `no part ${input.value.trim()} (parts ${partIds[0]}–${partIds.at(-1)})`;
      return;
    }
    status.textContent = '';
    findGraphPart(container, partId);
  });
  bar.append(find);
  return bar;
}

/** A part chosen in the panel: highlighted here, and announced to the page's selection. */
function selectPart(container, partId) {
  highlightGraphPart(container, partId);
  container.dispatchEvent(new CustomEvent('dbg-select', { bubbles: true, detail: { partId } }));
}

/** Draws the last report again (a switch of view or of the matrix's direction). */
function rerender(container) {
  if (container.__dbgLast) renderBlockingGraphs(container, container.__dbgLast.report, container.__dbgLast.options);
}

// ---------------------------------------------------------------------------------------------
// The panel

/**
 * Replaces the content of `container` with one drawing per graph of `report` (or a short
 * message when there is none). `maxDrawnNodes` bounds the nodes drawn per graph.
 */
export function renderBlockingGraphs(container, report, options = {}) {
  const { maxDrawnNodes = MAX_PART_NODES } = options;
  container.__dbgLast = { report, options };
  const graphs = report?.graphs ?? [];
  const keyId = report?.key ?? null;
  const partIds = [...(report?.partIds ?? [])].sort((a, b) => a - b);
  container.dataset.graphs = String(graphs.length);
  container.dataset.key = keyId === null ? '' : String(keyId);
  if (graphs.length === 0) {
    container.replaceChildren(html('p', 'No blocking graphs in this report.', 'dbg-note'));
    return;
  }

  const legend = html('p', '', 'dbg-legend');
  legend.append(
    'One graph per base direction d: an arrow a → b means part a is blocked by part b when moving along d ',
    '(G(−d) is the same graph with the arrows reversed). Shaded arcs: strongly connected components (SCCs). ',
    html('span', keyId === null ? 'No key.' : `Gold: the key, part ${keyId}.`, 'dbg-key-note'),
  );
  const partCount = partIds.length || (graphs[0].components ?? []).reduce((sum, component) => sum + component.length, 0);
  const allPartIds = partIds.length ? partIds : orderedComponents(graphs[0], []).flat().sort((a, b) => a - b);
  const children = [legend, toolbar(container, allPartIds)];
  if (container.dataset.view === 'matrix') {
    children.push(matrixView(container, graphs, allPartIds, keyId));
    container.replaceChildren(...children);
    highlightGraphPart(container, container.dataset.selected ? Number(container.dataset.selected) : null);
    return;
  }
  container.dataset.view = 'drawing';
  if (partCount > maxDrawnNodes) {
    children.push(html('p', `${partCount} parts are too many to draw one by one: each graph shows its strongly connected `
      + 'components as nodes ({n} = a component of n parts); the Matrix shows every part.', 'dbg-note'));
  } else if (partCount > MAX_DRAWN_NODES) {
    children.push(html('p', `${partCount} parts: zoom with the wheel or + / −, drag to pan, Find a part by its id, `
      + 'or switch to the Matrix.', 'dbg-note'));
  }

  const grid = html('div', undefined, 'dbg-grid');
  for (const graph of graphs) {
    const components = orderedComponents(graph, partIds);
    const figure = html('figure', undefined, 'dbg-graph');
    figure.dataset.direction = graph.direction;
    figure.dataset.nodes = String(components.reduce((sum, component) => sum + component.length, 0));
    figure.dataset.edges = String(graph.edges?.length ?? 0);
    figure.dataset.components = String(components.length);
    const label = `Directional blocking graph along ${graph.direction}: ${figure.dataset.nodes} parts, `
      + `${figure.dataset.edges} edges, ${components.length} strongly connected components`;
    if (Number(figure.dataset.nodes) <= maxDrawnNodes) {
      figure.dataset.drawn = 'parts';
      figure.append(drawGraph({ ...partGraph(graph, components, keyId), label }));
    } else if (components.length <= MAX_DRAWN_NODES) {
      figure.dataset.drawn = 'components';
      figure.append(drawGraph({ ...componentGraph(graph, components, keyId), label }));
    } else {
      figure.dataset.drawn = 'none';
      figure.append(html('p', `Not drawn: ${components.length} components of ${figure.dataset.nodes} parts.`, 'dbg-note'));
    }
    figure.append(caption(graph, components));
    figure.title = 'Click a part to select it, elsewhere to enlarge or shrink; wheel or + / − to zoom, drag to pan';
    const drawing = figure.querySelector('svg.dbg-svg');
    if (drawing) makeZoomable(drawing, figure);
    figure.addEventListener('click', (event) => {
      // The click that ends a drag is part of the pan.
      if (figure.dataset.dragged === 'true') {
        delete figure.dataset.dragged;
        return;
      }
      const node = event.target.closest?.('.dbg-node-group')?.querySelector('circle.dbg-node[data-part]');
      if (node) selectPart(container, Number(node.dataset.part));
      else figure.classList.toggle('dbg-wide');
    });
    grid.append(figure);
  }
  children.push(grid);
  container.replaceChildren(...children);
  highlightGraphPart(container, container.dataset.selected ? Number(container.dataset.selected) : null);
}

/**
 * Marks part `partId`'s nodes in every graph of `container` as selected, and its row and column
 * in the matrix (null: none). The page's part list calls it when its selection changes.
 */
export function highlightGraphPart(container, partId) {
  container.dataset.selected = partId === null || partId === undefined ? '' : String(partId);
  for (const node of container.querySelectorAll('circle.dbg-node[data-part]')) {
    const selected = Number(node.dataset.part) === partId;
    if (selected) node.setAttribute('data-selected', 'true');
    else node.removeAttribute('data-selected');
  }
  const matrix = container.querySelector('svg.dbg-matrix-svg');
  const layout = matrix?.__dbgMatrix;
  if (!layout) return;
  const selection = matrix.querySelector('.dbg-matrix-selection');
  const k = layout.index.get(partId);
  selection.setAttribute('visibility', k === undefined ? 'hidden' : 'visible');
  if (k === undefined) return;
  const at = layout.margin + k * layout.cell;
  selection.querySelector('.dbg-matrix-row').setAttribute('y', String(at));
  selection.querySelector('.dbg-matrix-col').setAttribute('x', String(at));
}

/**
 * Find part: highlights `partId`, centres its node in every drawing that has one (zooming in on
 * large drawings so it stands out) or scrolls the matrix to its row, and announces it with a
 * 'dbg-select' event (the page's selection follows). Returns whether the part is in the graphs.
 */
export function findGraphPart(container, partId) {
  selectPart(container, partId);
  let found = false;
  for (const root of drawings(container)) {
    const node = root.querySelector(`circle.dbg-node[data-part="${partId}"]`);
    if (!node) continue;
    found = true;
    const large = drawingSize(root) > VIEW_SIZE;
    centreOn(root, Number(node.getAttribute('cx')), Number(node.getAttribute('cy')), large ? FIND_ZOOM : 1);
  }
  const matrix = container.querySelector('svg.dbg-matrix-svg');
  const layout = matrix?.__dbgMatrix;
  if (layout?.index.has(partId)) {
    found = true;
    const scroller = matrix.parentElement;
    const at = layout.margin + layout.index.get(partId) * layout.cell;
    scroller.scrollTo({ left: Math.max(0, at - scroller.clientWidth / 2), top: Math.max(0, at - scroller.clientHeight / 2) });
  }
  return found;
}

export function clearBlockingGraphs(container) {
  container.__dbgLast = null;
  container.replaceChildren();
  container.dataset.graphs = '0';
  container.dataset.key = '';
}
