// SPDX-License-Identifier: GPL-3.0-or-later
//
// Draws the base directional blocking graphs of a check report as SVG (Section 3.1 of the
// paper): one small graph G(d) per base direction, nodes = parts in their 3D colours with the
// key marked, an arrow a → b when part a is blocked by part b moving along d, and the strongly
// connected components as shaded arcs. All graph facts (edges, components, key) come from the
// core's report; this module only lays them out: nodes on a circle, each component's parts next
// to each other, so the drawing is the same every time for the same report.
//
// Large assemblies degrade in two steps: above MAX_DRAWN_NODES parts a graph is drawn with its
// components as nodes (an interlocking assembly has at most two per graph: the key and the
// rest); when there are too many components for that as well, only a note is shown (the report
// panel keeps the table).
//
// For tests: figure.dbg-graph[data-direction, data-nodes, data-edges, data-components,
// data-drawn = parts | components | none], circle.dbg-node[data-part, data-key],
// path.dbg-edge[data-from, data-to]; the container gets data-graphs and data-key.
//
// Selection (the playground's part list, parts-panel.js): a click on a part's node dispatches a
// bubbling 'dbg-select' event ({ detail: { partId } }) from the container instead of zooming the
// graph, and highlightGraphPart(container, partId) marks that part's nodes
// (circle.dbg-node[data-selected="true"], container[data-selected]); it survives a new drawing.

import { KEY_COLOR_CSS, partColorCss } from './view.js';

const SVG_NS = 'http://www.w3.org/2000/svg';
/** Above this many nodes a circle drawing stops being readable at the panel's size. */
export const MAX_DRAWN_NODES = 30;

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

function circleLayout(count, nodeRadius, outsideLabels) {
  const center = VIEW_SIZE / 2;
  const radius = center - nodeRadius - (outsideLabels ? 14 : 6);
  const angles = Array.from({ length: count }, (_, index) => -Math.PI / 2 + (2 * Math.PI * index) / count);
  // A single node (a strongly connected graph drawn by components) sits in the middle.
  const at = (angle) => (count === 1 ? { angle, x: center, y: center } : { angle, x: center + radius * Math.cos(angle), y: center + radius * Math.sin(angle) });
  return { center, radius, points: angles.map(at) };
}

/** Node radius for `count` nodes: large for a few parts, never overlapping for many. */
function nodeRadiusFor(count) {
  const spacing = (2 * Math.PI * (VIEW_SIZE / 2 - 20)) / Math.max(count, 1);
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
  const baseRadius = nodeRadiusFor(nodes.length);
  const insideLabels = baseRadius >= 7;
  const layout = circleLayout(nodes.length, baseRadius * Math.max(...nodes.map((node) => node.radiusScale ?? 1)), !insideLabels);
  const position = new Map(nodes.map((node, index) => [node.id, { ...layout.points[index], node, index }]));
  const radiusOf = (node) => baseRadius * (node.radiusScale ?? 1);

  const root = svg('svg', {
    viewBox: `0 0 ${VIEW_SIZE} ${VIEW_SIZE}`, role: 'img', 'aria-label': label, class: 'dbg-svg',
  });
  const defs = svg('defs');
  defs.append(arrowMarker(markerId, EDGE_COLOR), arrowMarker(keyMarkerId, KEY_COLOR_CSS));
  root.append(defs);

  const bands = svg('g', { class: 'dbg-components' });
  groups.forEach((group, index) => {
    const band = componentBand(layout, group[0], group[group.length - 1], nodes.length,
      2 * baseRadius + 8, COMPONENT_COLORS[index % COMPONENT_COLORS.length]);
    band.setAttribute('class', 'dbg-component');
    band.setAttribute('data-size', String(group.length));
    bands.append(band);
  });
  root.append(bands);

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
  root.append(edgeLayer);

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
  root.append(nodeLayer);
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
// The panel

/**
 * Replaces the content of `container` with one drawing per graph of `report` (or a short
 * message when there is none). `maxDrawnNodes` bounds the nodes drawn per graph.
 */
export function renderBlockingGraphs(container, report, { maxDrawnNodes = MAX_DRAWN_NODES } = {}) {
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
  const children = [legend];
  const partCount = partIds.length || (graphs[0].components ?? []).reduce((sum, component) => sum + component.length, 0);
  if (partCount > maxDrawnNodes) {
    children.push(html('p', `${partCount} parts are too many to draw one by one: each graph shows its strongly connected `
      + 'components as nodes ({n} = a component of n parts); the table lists them.', 'dbg-note'));
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
    } else if (components.length <= maxDrawnNodes) {
      figure.dataset.drawn = 'components';
      figure.append(drawGraph({ ...componentGraph(graph, components, keyId), label }));
    } else {
      figure.dataset.drawn = 'none';
      figure.append(html('p', `Not drawn: ${components.length} components of ${figure.dataset.nodes} parts.`, 'dbg-note'));
    }
    figure.append(caption(graph, components));
    figure.title = 'Click a part to select it, elsewhere to enlarge or shrink';
    figure.addEventListener('click', (event) => {
      const node = event.target.closest?.('.dbg-node-group')?.querySelector('circle.dbg-node[data-part]');
      if (node) container.dispatchEvent(new CustomEvent('dbg-select', { bubbles: true, detail: { partId: Number(node.dataset.part) } }));
      else figure.classList.toggle('dbg-wide');
    });
    grid.append(figure);
  }
  children.push(grid);
  container.replaceChildren(...children);
  highlightGraphPart(container, container.dataset.selected ? Number(container.dataset.selected) : null);
}

/** Marks part `partId`'s nodes in every graph of `container` as selected (null: none). */
export function highlightGraphPart(container, partId) {
  container.dataset.selected = partId === null || partId === undefined ? '' : String(partId);
  for (const node of container.querySelectorAll('circle.dbg-node[data-part]')) {
    const selected = Number(node.dataset.part) === partId;
    if (selected) node.setAttribute('data-selected', 'true');
    else node.removeAttribute('data-selected');
  }
}

export function clearBlockingGraphs(container) {
  container.replaceChildren();
  container.dataset.graphs = '0';
  container.dataset.key = '';
}
