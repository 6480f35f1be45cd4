// SPDX-License-Identifier: GPL-3.0-or-later
//
// The report panel: verdict, key, directions, removal order and paths, blocking graphs (drawn
// by dbg-panel.js, and as a table). It formats the core's check report (the same fields as
// `desia check --json`) and nothing else.
//
// For tests: #verdict[data-verdict, data-key], #paths li[aria-current] (the removal shown by the
// disassembly animation), #dbg-panel (see dbg-panel.js).

import { byId, element } from './dom.js';
import { clearBlockingGraphs, renderBlockingGraphs } from './dbg-panel.js';

const VERDICT_TITLES = {
  interlocking: 'Interlocking',
  deadlocked: 'Deadlocked',
  'not-interlocking': 'Not interlocking',
};

const ui = {
  verdict: byId('verdict'),
  method: byId('method'),
  reason: byId('reason'),
  partsCount: byId('parts-count'),
  key: byId('key'),
  keyDirections: byId('key-directions'),
  baseDirections: byId('base-directions'),
  order: byId('order'),
  witness: byId('witness'),
  timing: byId('timing'),
  timingLabel: byId('timing-label'),
  paths: byId('paths'),
  graphs: byId('graphs'),
  dbgPanel: byId('dbg-panel'),
};

const METHOD_NAMES = { dbg: 'graphs (DBG)', lp: 'linear program (LP)', both: 'graphs and linear program' };

function formatList(values, empty = 'none') {
  return values?.length ? values.join(', ') : empty;
}

/** Long orders are shortened here; the full list is under "Removal paths". */
function formatOrder(order) {
  if (order.length <= 12) return order.join(' → ');
  return `${order.slice(0, 8).join(' → ')} → … → ${order.slice(-2).join(' → ')}`;
}

function formatDisassemblyFailure(failure) {
  if (!failure) return 'none found';
  const removed = failure.removed?.length ? `after removing ${formatList(failure.removed)}, ` : '';
  return `none: ${removed}parts ${formatList(failure.stuck)} are stuck`;
}

function formatWitness(witness) {
  if (!witness) return 'none';
  const how = witness.direction ? `along ${witness.direction}` : 'in different directions';
  const noun = witness.parts?.length === 1 ? 'part' : 'parts';
  return `${noun} ${formatList(witness.parts)} can move ${how}`;
}

/** With method 'both' the report carries each test's verdict; show them when they differ or agree. */
function formatMethods(methods) {
  if (!methods) return '';
  const name = (verdict) => VERDICT_TITLES[verdict?.verdict]?.toLowerCase() ?? 'unknown';
  return `Graph test: ${name(methods.dbg)}; LP test: ${name(methods.lp)}`;
}

function formatMoves(path) {
  if (!path?.length) return 'stays (last part)';
  return path.map((move) => `${move.dir}×${move.steps}`).join(', then ');
}

function formatComponents(components) {
  if (!components?.length) return '—';
  const describe = (component) => (component.length <= 4
    ? `{${component.join(', ')}}`
    : `{${component.length} parts}`);
  return `${components.length}: ${components.map(describe).join(' + ')}`;
}

/**
 * Shows `report`. `elapsedMs` is how long the core took; `timingLabel` says for what (a designed
 * puzzle reports its design time, which includes the verifying check).
 */
export function renderReport(report, elapsedMs, timingLabel = 'Check time') {
  const verdict = report.verdict ?? (report.interlocking ? 'interlocking' : 'not-interlocking');
  const title = VERDICT_TITLES[verdict] ?? verdict;
  const hasKey = report.key !== null && report.key !== undefined;
  ui.verdict.textContent = verdict === 'interlocking' && hasKey ? `${title}, key: part ${report.key}` : title;
  ui.verdict.dataset.verdict = verdict;
  ui.verdict.dataset.key = hasKey ? String(report.key) : '';
  ui.reason.textContent = [report.reason, formatMethods(report.methods)].filter(Boolean).join('. ');
  ui.method.textContent = METHOD_NAMES[report.method] ?? report.method ?? '—';
  ui.partsCount.textContent = String(report.parts ?? report.partIds?.length ?? '—');
  ui.key.textContent = hasKey ? `part ${report.key}` : 'none';
  ui.keyDirections.textContent = formatList(report.keyDirections);
  ui.baseDirections.textContent = formatDirections(report.baseDirections);
  ui.order.textContent = report.disassembly
    ? formatOrder(report.disassembly.order)
    : formatDisassemblyFailure(report.disassemblyFailure);
  ui.witness.textContent = formatWitness(report.witness);
  ui.timingLabel.textContent = timingLabel;
  ui.timing.textContent = Number.isFinite(elapsedMs) ? formatDuration(elapsedMs) : '—';
  renderPaths(report.disassembly);
  renderGraphs(report.graphs);
  renderBlockingGraphs(ui.dbgPanel, report);
}

/** Plates and contact graphs can have many base directions: say how many before listing them. */
function formatDirections(directions) {
  const labels = directions?.map((direction) => direction.label) ?? [];
  if (labels.length <= 6) return formatList(labels);
  return `${labels.length}: ${labels.join(', ')}`;
}

/**
 * Marks the removal the disassembly animation shows (`index` into the order; -1 for none) in
 * the list of removal paths.
 */
export function highlightRemovalStep(index) {
  [...ui.paths.children].forEach((item, position) => {
    if (position === index) item.setAttribute('aria-current', 'step');
    else item.removeAttribute('aria-current');
  });
}

/** Milliseconds below ten seconds, seconds above: a design can take minutes. */
export function formatDuration(ms) {
  return ms < 10_000 ? `${ms.toFixed(1)} ms` : `${(ms / 1000).toFixed(1)} s`;
}

function renderPaths(disassembly) {
  const items = (disassembly?.order ?? []).map((partId, index) => element(
    'li',
    `part ${partId}: ${formatMoves(disassembly.paths?.[index])}`,
  ));
  ui.paths.replaceChildren(...(items.length ? items : [element('li', 'no disassembly found')]));
}

function renderGraphs(graphs) {
  const rows = (graphs ?? []).map((graph) => {
    const row = document.createElement('tr');
    row.append(
      element('td', graph.direction),
      element('td', String(graph.edges?.length ?? 0)),
      element('td', formatComponents(graph.components)),
    );
    return row;
  });
  ui.graphs.replaceChildren(...rows);
}

export function resetReport(message) {
  ui.verdict.textContent = message;
  ui.verdict.dataset.verdict = '';
  ui.verdict.dataset.key = '';
  ui.reason.textContent = '';
  ui.timingLabel.textContent = 'Check time';
  for (const field of [ui.method, ui.partsCount, ui.key, ui.keyDirections, ui.baseDirections, ui.order, ui.witness, ui.timing]) {
    field.textContent = '—';
  }
  ui.paths.replaceChildren();
  ui.graphs.replaceChildren();
  clearBlockingGraphs(ui.dbgPanel);
}

