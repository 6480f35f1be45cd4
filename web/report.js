// SPDX-License-Identifier: GPL-3.0-or-later
//
// The report panel: verdict, key, directions, removal order and paths, blocking graphs (drawn
// by dbg-panel.js, and as a table). It formats the core's check report (the same fields as
// `desia check --json`) and nothing else.
//
// Plate designs add their cut points (#cut-points[data-plates]) and, for a joint plan, its joints
// (#joints li[data-mover, data-other, data-type, data-direction], #joints-details[data-count]).
//
// A one-part voxel assembly is a shape to design from, not a failed puzzle: #verdict says
// "Shape: 64 voxels, ready to design" (data-verdict="shape"). When the graph test ran on contacts
// that are not all along the axes (the core's base directions are more than +x, +y, +z), its
// "interlocking" or "deadlocked" is not exact (paper Section 3.2): #method-note says so and offers
// the LP test.
//
// A voxel plan's moves (issue 27): #disassembly-level says the level in BurrTools' notation and
// the number of moves ("level 98.2.5, 108 moves"; a partial plan: where it stopped), and #moves
// lists them ("move 3: parts 2, 4  +x 1", "move 5: part 3  +z out"), a long list shortened to its
// first and last moves (and the one played) until "show all".
//
// For tests: #verdict[data-verdict, data-key], #method-note[hidden, data-directions], #paths
// li[aria-current] (the removal shown by the disassembly animation), #disassembly-level[data-level,
// data-moves, data-partial], #moves li[data-parts, aria-current] (the move shown), #dbg-panel
// (see dbg-panel.js).

import { byId, element } from './dom.js';
import { clearBlockingGraphs, renderBlockingGraphs } from './dbg-panel.js';
import { formatDirection, formatLevel, formatStep, formatStuck, stepsToPlay } from './view.js';

// A plate plan's removal as a disassembly (view.js, shared with the drop-in viewer).
export { planDisassembly, withPlannedRemoval } from './view.js';

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
  cutPoints: byId('cut-points'),
  jointsDetails: byId('joints-details'),
  jointsSummary: byId('joints-summary'),
  joints: byId('joints'),
  methodNote: byId('method-note'),
  methodNoteText: byId('method-note-text'),
  level: byId('disassembly-level'),
  movesDetails: byId('moves-details'),
  movesSummary: byId('moves-summary'),
  moves: byId('moves'),
  graphsDetails: byId('graphs-details'),
  graphsSummary: byId('graphs-summary'),
};

/** Lists of more moves than this show the first MOVES_HEAD and the last MOVES_TAIL until "show all". */
const MOVES_SHORT_LIST = 12;
const MOVES_HEAD = 8;
const MOVES_TAIL = 2;

/** The base directions the core gives when every contact normal is along an axis. */
const AXIS_DIRECTIONS = new Set(['+x', '+y', '+z']);

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
  // A plan of moves names the parts left together, per sub-assembly.
  if (Array.isArray(failure.unseparated) && failure.unseparated.length) return `none: ${removed}${formatStuck(failure)}`;
  return `none: ${removed}parts ${formatList(failure.stuck)} are stuck`;
}

function formatWitness(witness, noun = 'part') {
  if (!witness) return 'none';
  const how = witness.direction ? `along ${witness.direction}` : 'in different directions';
  return `${witness.parts?.length === 1 ? noun : `${noun}s`} ${formatList(witness.parts)} can move ${how}`;
}

/**
 * What a part of this kind of assembly is called, everywhere the report names one (the verdict's
 * key, the Key line, the witness, the removal paths), as the part list does: plates, beams, parts.
 */
export function partNoun(kind) {
  return kind === 'plate' ? 'plate' : kind === 'frame' ? 'beam' : 'part';
}

/**
 * 'plate' or 'frame' when the document is a structure whose joints are not designed yet (a plate
 * design without joints, a frame without joint voxels), else null.
 */
export function unjointedKind(document_) {
  if (document_?.kind === 'plate') return Array.isArray(document_.joints) && document_.joints.length > 0 ? null : 'plate';
  if (document_?.kind === 'frame') return Array.isArray(document_.parts) || Array.isArray(document_.jointVoxels) ? null : 'frame';
  return null;
}

/** With method 'both' the report carries each test's verdict; show them when they differ or agree. */
function formatMethods(methods) {
  if (!methods) return '';
  const name = (verdict) => VERDICT_TITLES[verdict?.verdict]?.toLowerCase() ?? 'unknown';
  return `Graph test: ${name(methods.dbg)}; LP test: ${name(methods.lp)}`;
}

function formatMoves(path) {
  if (!path?.length) return 'stays (last part)';
  // A plate plan's removal is a direction, not a number of steps (see planDisassembly).
  if (path.every((move) => Array.isArray(move.vector))) return `along ${path.map((move) => move.dir).join(', then ')}`;
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
export function renderReport(report, elapsedMs, timingLabel = 'Check time', { voxels = null, input = null, inProgress = null } = {}) {
  const verdict = report.verdict ?? (report.interlocking ? 'interlocking' : 'not-interlocking');
  const title = VERDICT_TITLES[verdict] ?? verdict;
  const hasKey = report.key !== null && report.key !== undefined;
  const noun = partNoun(report.kind);
  const count = report.parts ?? report.partIds?.length ?? 0;
  if (isShape(report)) {
    ui.verdict.textContent = `Shape: ${voxels ?? 'its'} voxels, ready to design`;
    ui.verdict.dataset.verdict = 'shape';
    ui.reason.textContent = 'One part: Design splits it into N interlocking parts.';
  } else if (inProgress && verdict !== 'interlocking') {
    // Step by step short of the target: the remainder is still one part, nothing to fail yet.
    ui.verdict.textContent = `Design in progress: ${inProgress.placed} of ${inProgress.target} ${noun}s placed`;
    ui.verdict.dataset.verdict = 'in-progress';
    ui.reason.textContent = `Next part, Choose or Finish automatically place the rest; the puzzle is checked once all ${inProgress.target} are placed.`;
  } else if (input && verdict !== 'interlocking') {
    // A plate or frame input has no joints yet: its boards or beams merely touch.
    const what = input === 'plate' ? 'Plate structure' : 'Frame';
    ui.verdict.textContent = `${what}: ${count} ${noun}s, ready to design joints`;
    ui.verdict.dataset.verdict = 'input';
    ui.reason.textContent = `No joints yet, so nothing holds it together: Design makes the joints so that only ${noun} 1, `
      + `the key, can move, and checks the result. Without joints: ${report.reason ?? 'not interlocking'}.`;
  } else {
    ui.verdict.textContent = verdict === 'interlocking' && hasKey ? `${title}, key: ${noun} ${report.key}` : title;
    ui.verdict.dataset.verdict = verdict;
    ui.reason.textContent = [report.reason, formatMethods(report.methods), formatShapeRemoval(report.shapeRemoval),
      formatCurvedContacts(report.mesh?.curvedContacts)]
      .filter(Boolean).join('. ');
  }
  ui.verdict.dataset.key = hasKey ? String(report.key) : '';
  renderMethodNote(report, verdict);
  ui.method.textContent = METHOD_NAMES[report.method] ?? report.method ?? '—';
  ui.partsCount.textContent = String(report.parts ?? report.partIds?.length ?? '—');
  ui.key.textContent = hasKey ? `${noun} ${report.key}` : 'none';
  ui.keyDirections.textContent = formatList(report.keyDirections);
  renderDirections(ui.baseDirections, report.baseDirections, report.baseDirectionCount);
  ui.order.textContent = report.disassembly
    ? formatOrder(report.disassembly.order)
    : formatDisassemblyFailure(report.disassemblyFailure);
  ui.witness.textContent = formatWitness(report.witness, noun);
  ui.timingLabel.textContent = timingLabel;
  ui.timing.textContent = Number.isFinite(elapsedMs) ? formatDuration(elapsedMs) : '—';
  renderPaths(report.disassembly, noun);
  foldGraphs(report.graphs);
  renderMoves(report.disassembly, report.disassemblyFailure);
  renderGraphs(report.graphs);
  renderBlockingGraphs(ui.dbgPanel, report);
  renderCutPoints(report.cutPoints, report.kind === 'frame' ? 'beam' : 'plate');
}

/** A voxel assembly of one part: the input of a design, not a puzzle that failed. */
function isShape(report) {
  return report.kind === 'voxel' && report.parts === 1;
}

/**
 * The graph test decides exactly only when every contact normal is along an axis (then the core's
 * base directions are +x, +y, +z). Otherwise parts moving at once in different directions escape
 * it: its "interlocking" or "deadlocked" needs the LP test. A "not interlocking" names a real motion.
 */
function renderMethodNote(report, verdict) {
  const labels = (report.baseDirections ?? []).map((direction) => direction.label);
  const count = report.baseDirectionCount ?? labels.length;
  const offAxis = count > AXIS_DIRECTIONS.size || labels.some((label) => !AXIS_DIRECTIONS.has(label));
  const inexact = report.method === 'dbg' && offAxis && verdict !== 'not-interlocking' && !isShape(report);
  ui.methodNote.hidden = !inexact;
  ui.methodNote.dataset.directions = inexact ? String(count) : '';
  ui.methodNoteText.textContent = inexact
    ? `The graph test is not exact here: some contacts are not along an axis (${count} base directions), and `
      + `parts moving at once in different directions escape it. The LP test decides exactly.`
    : '';
}

/** A plate or frame result's removal plan replayed on its real shapes by the core (checkDocument). */
function formatShapeRemoval(shapeRemoval) {
  if (!shapeRemoval) return '';
  return shapeRemoval.clear ? 'Removal plan replayed on the real shapes: every part leaves'
    : `Removal plan FAILS on the real shapes: ${shapeRemoval.failure}`;
}

/** A mesh assembly's curved contact regions (a pin in a hole): the core approximates them by their facets. */
function formatCurvedContacts(regions) {
  if (!Array.isArray(regions) || regions.length === 0) return '';
  const listed = regions.map(({ parts, facets }) => `parts ${parts.join(' and ')} (${facets} facets)`).join('; ');
  return `Curved contacts, approximated by their planar facets: ${listed}`;
}

/**
 * A plate (or beam) whose removal splits the parts-graph: no joints can make the design
 * interlocking. Frames: the same, from the core's check of the frame input (beams sharing a joint).
 */
function renderCutPoints(cutPoints, noun = 'plate') {
  const plates = Array.isArray(cutPoints) ? cutPoints : [];
  ui.cutPoints.hidden = plates.length === 0;
  ui.cutPoints.dataset.plates = plates.join(',');
  ui.cutPoints.textContent = plates.length === 0 ? ''
    : `${plates.length === 1 ? `Cut point: ${noun}` : `Cut points: ${noun}s`} ${plates.join(', ')} — no joints can make this `
      + `interlocking; add a part that bypasses ${plates.length === 1 ? 'it' : 'them'}.`;
}

const JOINT_TYPES = {
  halved: 'halved', 'mortise-tenon': 'mortise and tenon', dovetail: 'sliding dovetail', 'mitre-tenon': 'tenon across the mitre', 'mitre-slide': 'tongue sliding along the mitre', 'face-tenon': 'stub tenon on a lap', 'step-tenon': 'step tenons past the mitre', 'slanted-tenon': 'mortise and tenon at an angle', 'slanted-dovetail': 'sliding dovetail along a bevelled side', 'inplane-dovetail': 'dovetail key in the plane', 'through-slot': 'seated whole in a slot through the other',
  empty: 'no joint (empty)',
};

/**
 * The joints of a plate plan (document.joints: [{ mover, other, type, direction }]): which two
 * plates, the joint's type and the direction the mover slides out along. Hidden for documents
 * without joints.
 */
export function renderPlan(document_) {
  const joints = document_?.kind === 'plate' && Array.isArray(document_.joints) ? document_.joints : [];
  const names = new Map();
  for (const plate of Array.isArray(document_?.plates) ? document_.plates : []) {
    if (typeof plate?.name === 'string' && plate.name) names.set(plate.id, plate.name);
  }
  const plate = (id) => (names.has(id) ? `${id} (${names.get(id)})` : String(id));
  ui.jointsDetails.hidden = joints.length === 0;
  ui.jointsDetails.dataset.count = String(joints.length);
  ui.jointsSummary.textContent = `Joints (${joints.length})`;
  ui.joints.replaceChildren(...joints.map((joint) => {
    const direction = formatDirection(joint.direction);
    const item = element('li', `plates ${plate(joint.mover)} – ${plate(joint.other)}: ${JOINT_TYPES[joint.type] ?? joint.type}, `
      + `${joint.mover} slides along ${direction}`);
    Object.assign(item.dataset, { mover: String(joint.mover), other: String(joint.other), type: String(joint.type), direction });
    return item;
  }));
}

/** Lists of more base directions than this are folded behind their count and first entries. */
const DIRECTIONS_SHORT_LIST = 6;
/** More graphs than this: the Blocking graphs section starts folded, its summary says how many. */
const GRAPHS_SHORT_LIST = 12;

/**
 * Plates and contact graphs can have many base directions (the CABINET: 41): a short list is
 * written out; a long one is folded behind "41 directions: +x, +y, +z, … (show all)".
 */
function renderDirections(target, directions, count = directions?.length ?? 0) {
  const labels = directions?.map((direction) => direction.label) ?? [];
  // The core leaves very long lists out of the report (the LIZARD's 1,186): say how many.
  if (labels.length === 0 && count > 0) {
    target.textContent = `${count.toLocaleString('en')} directions (too many to list)`;
    return;
  }
  if (labels.length <= DIRECTIONS_SHORT_LIST) {
    target.textContent = formatList(labels);
    return;
  }
  const fold = element('details');
  fold.className = 'fold';
  fold.append(
    element('summary', `${labels.length} directions: ${labels.slice(0, 3).join(', ')}, … (show all)`),
    element('span', labels.join(', ')),
  );
  target.replaceChildren(fold);
}

/** The Blocking graphs section: its count in the summary; folded when there are many (41 for the CABINET). */
let graphsFoldedFor = -1;
function foldGraphs(graphs) {
  const count = Array.isArray(graphs) ? graphs.length : 0;
  ui.graphsSummary.textContent = count > 0 ? `Blocking graphs (${count})` : 'Blocking graphs';
  // Only when the count changes: a user's open or closed section stays as they left it.
  if (count === graphsFoldedFor) return;
  graphsFoldedFor = count;
  ui.graphsDetails.open = count <= GRAPHS_SHORT_LIST;
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

/**
 * A voxel plan's level and moves: "level 98.2.5, 108 moves" (with "not proven the fewest" and the
 * limit when the level was not found breadth-first) and the list of moves; for a partial plan
 * (disassemblyFailure with steps) the moves made and where they stopped. Hidden for plans without
 * moves (contacts, plates, frames).
 */
function renderMoves(disassembly, failure) {
  const partial = !disassembly && Array.isArray(failure?.steps) ? failure : null;
  const plan = disassembly ?? partial;
  const steps = Array.isArray(plan?.steps) ? plan.steps : [];
  const level = formatLevel(plan?.level);
  const count = Number.isInteger(plan?.moves) ? plan.moves : steps.length;
  const movesText = `${count} move${count === 1 ? '' : 's'}`;
  let text = '';
  if (partial) {
    text = `Partial plan: ${level ? `level ${level}, ` : ''}${movesText}, then ${formatStuck(partial)}`;
  } else if (level) {
    text = `level ${level}, ${movesText}`;
    if (plan.levelMinimal === false) text += ` (not proven the fewest${plan.limit ? `: ${plan.limit}` : ''})`;
  }
  ui.level.textContent = text;
  ui.level.hidden = !text;
  Object.assign(ui.level.dataset, { level, moves: text ? String(count) : '', partial: String(Boolean(partial)) });
  const items = steps.map((step, index) => {
    const item = element('li', `move ${index + 1}: ${formatStep(step)}`);
    item.dataset.parts = (step.parts ?? []).join(' ');
    if (step.out) item.dataset.out = 'true';
    return item;
  });
  ui.movesDetails.hidden = items.length === 0;
  // Whether the moves are what the view plays, or a plan beside the removal paths (as many moves).
  const played = Boolean(stepsToPlay(plan));
  ui.movesSummary.textContent = items.length === 0 ? 'Moves'
    : `Moves (${items.length})${played ? '' : '; Play follows the removal paths'}`;
  ui.moves.dataset.count = String(items.length);
  ui.moves.dataset.expanded = String(items.length <= MOVES_SHORT_LIST);
  if (items.length > MOVES_SHORT_LIST) {
    const more = element('li');
    more.className = 'moves-more';
    const button = element('button', `… ${items.length - MOVES_HEAD - MOVES_TAIL} more moves: show all`);
    button.type = 'button';
    button.className = 'link-button';
    button.addEventListener('click', () => {
      ui.moves.dataset.expanded = 'true';
      more.hidden = true;
      for (const item of items) item.hidden = false;
    });
    more.append(button);
    items.splice(MOVES_HEAD, 0, more);
  }
  ui.moves.replaceChildren(...items);
  markedMove = -1;
  shortenMoves();
}

/** A short list hides the middle moves, except the one played. */
function shortenMoves() {
  if (ui.moves.dataset.expanded === 'true') return;
  const moves = [...ui.moves.querySelectorAll('li:not(.moves-more)')];
  moves.forEach((item, index) => {
    item.hidden = index >= MOVES_HEAD && index < moves.length - MOVES_TAIL && item.getAttribute('aria-current') !== 'step';
  });
}

/** The move marked in the list (highlightMove is called on every animation frame). */
let markedMove = -1;

/** Marks the move the animation shows (`index` into the steps; -1 for none) in the list of moves. */
export function highlightMove(index) {
  if (index === markedMove) return;
  markedMove = index;
  [...ui.moves.querySelectorAll('li:not(.moves-more)')].forEach((item, position) => {
    if (position === index) item.setAttribute('aria-current', 'step');
    else item.removeAttribute('aria-current');
  });
  shortenMoves();
}

/** Milliseconds below ten seconds, seconds above: a design can take minutes. */
export function formatDuration(ms) {
  return ms < 10_000 ? `${ms.toFixed(1)} ms` : `${(ms / 1000).toFixed(1)} s`;
}

function renderPaths(disassembly, noun = 'part') {
  // A plan that moves parts together has no single-part paths: its moves are listed instead.
  if (disassembly && disassembly.paths === null) {
    ui.paths.replaceChildren(element('li', `no single-part paths: parts come free in the order ${formatOrder(disassembly.order ?? [])} by moving together (see Moves)`));
    return;
  }
  const items = (disassembly?.order ?? []).map((partId, index) => element(
    'li',
    `${noun} ${partId}: ${formatMoves(disassembly.paths?.[index])}`,
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
  ui.methodNote.hidden = true;
  ui.methodNote.dataset.directions = '';
  ui.verdict.textContent = message;
  ui.verdict.dataset.verdict = '';
  ui.verdict.dataset.key = '';
  ui.reason.textContent = '';
  ui.timingLabel.textContent = 'Check time';
  for (const field of [ui.method, ui.partsCount, ui.key, ui.keyDirections, ui.baseDirections, ui.order, ui.witness, ui.timing]) {
    field.textContent = '—';
  }
  ui.paths.replaceChildren();
  renderMoves(null, null);
  ui.graphs.replaceChildren();
  clearBlockingGraphs(ui.dbgPanel);
  renderCutPoints([]);
  renderPlan(null);
}

