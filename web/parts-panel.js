// SPDX-License-Identifier: GPL-3.0-or-later
//
// The part list of the playground (issue 11): one entry per part (id, what it is: its voxel
// count, a plate's name, a beam's input beam; its colour as drawn, the key in gold). A part is
// selected from the list, from a click in the 3D view (AssemblyView's onPartClick) or from a
// click on its node in the blocking graphs (dbg-panel.js 'dbg-select'); the selection glows in
// the view, is marked in the graphs and in the list. Hide and Isolate act on the selected part,
// Show all brings every part back. Every fact listed comes from the core's document and report.
//
// Keyboard: the entries are focusable (Tab, or the arrow keys within the list); Enter or Space
// selects, H hides, I isolates, A shows all, Escape clears the selection.
//
// For tests: #part-list[data-selected, data-count, data-hidden], li.part-item[data-part,
// aria-selected, data-hidden]; the view's container repeats the selection (data-selected).

import { highlightGraphPart } from './dbg-panel.js';
import { partColorCss } from './view.js';

/** Counts each label's voxels: Map(partId -> voxels). */
function voxelCounts(document_) {
  const counts = new Map();
  for (const label of document_?.voxel?.labels ?? []) {
    if (label > 0) counts.set(label, (counts.get(label) ?? 0) + 1);
  }
  return counts;
}

/**
 * The entries of the list: [{ id, title, detail, color }] in id order, for every part the report
 * names and every part the view draws (a frame without joints draws its joint cubes as part 0).
 */
export function describeParts(document_, report, drawnIds = []) {
  const kind = report?.kind ?? document_?.kind;
  const key = report?.key ?? null;
  const noun = kind === 'plate' ? 'plate' : kind === 'frame' ? 'beam' : 'part';
  const voxels = kind === 'voxel' ? voxelCounts(document_) : new Map();
  const plates = new Map((Array.isArray(document_?.plates) ? document_.plates : []).map((plate) => [plate.id, plate]));
  const beams = new Map((Array.isArray(document_?.beams) ? document_.beams : []).map((beam) => [beam.id, beam]));
  const meshParts = new Map((kind === 'mesh' && Array.isArray(document_?.parts) ? document_.parts : []).map((part) => [part.id, part]));
  const ids = new Set([...(report?.partIds ?? []), ...voxels.keys(), ...drawnIds]);
  return [...ids].filter(Number.isInteger).sort((a, b) => a - b).map((id) => {
    let detail = '';
    if (kind === 'voxel') detail = `${voxels.get(id) ?? 0} voxels`;
    else if (kind === 'plate') detail = plates.get(id)?.name ?? '';
    else if (kind === 'mesh') detail = meshParts.get(id)?.name ?? ''; // its object, group, solid or file
    else if (kind === 'frame' && id === 0) detail = 'joint cubes (no joints designed yet)';
    else if (kind === 'frame' && Number.isInteger(beams.get(id)?.inputId)) detail = `input beam ${beams.get(id).inputId}`;
    const title = id === 0 && kind === 'frame' ? 'joints' : `${noun} ${id}${id === key ? ' (key)' : ''}`;
    return { id, title, detail, color: partColorCss(id, key) };
  });
}

/**
 * Wires the list. `elements`: list (ul), summary (the details' summary, gets the count),
 * isolateButton, hideButton, showAllButton; `view` (AssemblyView), `graphs` (the blocking-graph
 * container). Returns { setAssembly(name, document, report), select(partId), clear() }.
 */
export function createPartsPanel({ list, summary, isolateButton, hideButton, showAllButton }, { view, graphs }) {
  let parts = [];
  let assemblyName = null;
  let selected = null;
  let hidden = new Set();

  function item(part) {
    const entry = document.createElement('li');
    entry.className = 'part-item';
    entry.dataset.part = String(part.id);
    entry.tabIndex = 0;
    entry.setAttribute('role', 'option');
    const swatch = document.createElement('span');
    swatch.className = 'part-swatch';
    swatch.style.background = part.color;
    const title = document.createElement('span');
    title.className = 'part-title';
    title.textContent = part.title;
    const detail = document.createElement('span');
    detail.className = 'part-detail';
    detail.textContent = part.detail;
    entry.append(swatch, title, detail);
    entry.title = `${part.title}${part.detail ? `: ${part.detail}` : ''}`;
    return entry;
  }

  function entries() {
    return [...list.querySelectorAll('li.part-item')];
  }

  /** Shows the state everywhere: the list, the view and the graphs. */
  function apply() {
    view.setSelection(selected);
    view.setHiddenParts(hidden);
    if (graphs) highlightGraphPart(graphs, selected);
    for (const entry of entries()) {
      const id = Number(entry.dataset.part);
      entry.setAttribute('aria-selected', String(id === selected));
      entry.dataset.hidden = String(hidden.has(id));
    }
    list.dataset.selected = selected === null ? '' : String(selected);
    list.dataset.hidden = [...hidden].sort((a, b) => a - b).join(' ');
    isolateButton.disabled = selected === null;
    hideButton.disabled = selected === null;
    hideButton.textContent = selected !== null && hidden.has(selected) ? 'Show' : 'Hide';
    showAllButton.disabled = hidden.size === 0;
  }

  /** Scrolls the list itself (never the page: a click in the view must not jump the page). */
  function revealInList(partId) {
    const entry = entries().find((candidate) => Number(candidate.dataset.part) === partId);
    if (!entry) return;
    const top = entry.offsetTop - list.offsetTop;
    if (top < list.scrollTop) list.scrollTop = top;
    else if (top + entry.offsetHeight > list.scrollTop + list.clientHeight) list.scrollTop = top + entry.offsetHeight - list.clientHeight;
  }

  function select(partId) {
    selected = parts.some((part) => part.id === partId) ? partId : null;
    apply();
    if (selected !== null) revealInList(selected);
  }

  /** Hide (or show again) the selected part. */
  function toggleHidden() {
    if (selected === null) return;
    if (hidden.has(selected)) hidden.delete(selected);
    else hidden.add(selected);
    apply();
  }

  /** Only the selected part is shown. */
  function isolate() {
    if (selected === null) return;
    hidden = new Set(parts.map((part) => part.id).filter((id) => id !== selected));
    apply();
  }

  function showAll() {
    hidden = new Set();
    apply();
  }

  list.addEventListener('click', (event) => {
    const entry = event.target.closest('li.part-item');
    if (entry) select(Number(entry.dataset.part));
  });
  list.addEventListener('keydown', (event) => {
    const entry = event.target.closest('li.part-item');
    if (!entry || event.ctrlKey || event.metaKey || event.altKey) return;
    const id = Number(entry.dataset.part);
    const all = entries();
    const index = all.indexOf(entry);
    const key = event.key.length === 1 ? event.key.toLowerCase() : event.key;
    const actions = {
      Enter: () => select(id),
      ' ': () => select(id),
      h: () => { if (selected !== id) select(id); toggleHidden(); },
      i: () => { if (selected !== id) select(id); isolate(); },
      a: showAll,
      Escape: () => select(null),
      ArrowDown: () => all[Math.min(index + 1, all.length - 1)].focus(),
      ArrowUp: () => all[Math.max(index - 1, 0)].focus(),
      Home: () => all[0].focus(),
      End: () => all[all.length - 1].focus(),
    };
    if (!actions[key]) return;
    event.preventDefault();
    actions[key]();
  });
  isolateButton.addEventListener('click', isolate);
  hideButton.addEventListener('click', toggleHidden);
  showAllButton.addEventListener('click', showAll);
  graphs?.addEventListener('dbg-select', (event) => select(event.detail.partId));

  return {
    /**
     * A new assembly on screen. The same assembly again (checked with another test, say) keeps
     * the selection and the hidden parts; another one starts with every part shown.
     */
    setAssembly(name, document_, report) {
      parts = describeParts(document_, report, view.partIds ?? []);
      const ids = new Set(parts.map((part) => part.id));
      if (name !== assemblyName) {
        selected = null;
        hidden = new Set();
      }
      assemblyName = name;
      if (!ids.has(selected)) selected = null;
      hidden = new Set([...hidden].filter((id) => ids.has(id)));
      list.replaceChildren(...parts.map(item));
      list.dataset.count = String(parts.length);
      summary.textContent = parts.length ? `Parts (${parts.length})` : 'Parts';
      apply();
    },
    select,
    clear() {
      parts = [];
      assemblyName = null;
      selected = null;
      hidden = new Set();
      list.replaceChildren();
      list.dataset.count = '0';
      summary.textContent = 'Parts';
      apply();
    },
  };
}
