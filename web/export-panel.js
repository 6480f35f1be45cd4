// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Export panel: saves the assembly on screen as .puz, as the JSON document, as STL or OBJ
// meshes (3D printing; one part or all) or as a BurrTools .xmpuzzle. Every byte comes from the
// core in the worker (toPuz, parseDocument, exportAssembly); the panel only picks the format and
// part and hands the result to the browser as a download. SVG outlines are for plate structures
// (laser cutting) and come with the plate core: the option is shown, disabled, until then.
//
// For tests: #export-panel[data-state] = '' | working | done | error, #export-message (what was
// saved, or the core's message), #export-part (options: 0 = all parts, else a part id).

import { byId, element } from './dom.js';

/** What each format needs from the worker, its file extension and MIME type. */
const FORMATS = {
  puz: { op: 'to-puz', extension: 'puz', type: 'text/plain', perPart: false, voxelOnly: true },
  json: { op: 'document-json', extension: 'json', type: 'application/json', perPart: false, voxelOnly: false },
  // The core's mesh export writes voxel parts (plates and contact graphs are refused).
  stl: { op: 'export', extension: 'stl', type: 'model/stl', perPart: true, voxelOnly: true },
  'stl-ascii': { op: 'export', extension: 'stl', type: 'model/stl', perPart: true, voxelOnly: true },
  obj: { op: 'export', extension: 'obj', type: 'model/obj', perPart: true, voxelOnly: true },
  xmpuzzle: { op: 'export', extension: 'xmpuzzle', type: 'application/octet-stream', perPart: false, voxelOnly: true },
};
/** Object URLs of downloads are freed after this; the browser has read the blob by then. */
const DOWNLOAD_URL_LIFETIME_MS = 60_000;

/** 'Cube_4x4x4_N7_seed1.puz' -> 'Cube_4x4x4_N7_seed1', safe as a file name. */
function baseName(name) {
  return (name.replace(/\.[^.]*$/, '') || 'assembly').replace(/[\\/:*?"<>|]+/g, '_');
}

/** `<name>.ext` for the whole assembly, `<name>-part3.ext` for part 3. */
export function exportFileName(name, format, part) {
  const { extension } = FORMATS[format];
  return `${baseName(name)}${part > 0 ? `-part${part}` : ''}.${extension}`;
}

function saveBlob(fileName, blob) {
  const url = URL.createObjectURL(blob);
  const link = element('a');
  link.href = url;
  link.download = fileName;
  document.body.append(link);
  link.click();
  link.remove();
  // Revoking at once can abort the download in some browsers; a later revoke is harmless.
  setTimeout(() => URL.revokeObjectURL(url), DOWNLOAD_URL_LIFETIME_MS);
}

/** Wires the panel; `core` is the page's CoreWorker. */
export function createExportPanel({ core }) {
  const ui = {
    panel: byId('export-panel'),
    format: byId('export-format'),
    part: byId('export-part'),
    button: byId('export-button'),
    message: byId('export-message'),
  };
  /** { name, text, kind, partIds } of the assembly on screen, or null. */
  let assembly = null;
  let busy = false; // The worker designs for the Design panel.
  let exporting = false;

  function setMessage(state, text) {
    ui.panel.dataset.state = state;
    ui.message.textContent = text;
    ui.message.hidden = !text;
  }

  function refresh() {
    const format = FORMATS[ui.format.value];
    const voxel = assembly?.kind === 'voxel';
    for (const option of ui.format.options) {
      const known = FORMATS[option.value];
      // .puz, .xmpuzzle, STL and OBJ hold voxel parts only; SVG waits for plates (disabled in the HTML).
      if (known) option.disabled = known.voxelOnly && assembly !== null && !voxel;
    }
    // A plate design or plan is saved as its JSON document.
    if (assembly && !voxel && ui.format.selectedOptions[0]?.disabled) ui.format.value = 'json';
    ui.part.disabled = !assembly || !format?.perPart;
    ui.button.disabled = !assembly || busy || exporting || !format || ui.format.selectedOptions[0]?.disabled;
  }

  function fillParts(partIds, key) {
    const previous = ui.part.value;
    const all = element('option', 'All parts');
    all.value = '0';
    const parts = partIds.map((id) => {
      const option = element('option', id === key ? `Part ${id} (key)` : `Part ${id}`);
      option.value = String(id);
      return option;
    });
    ui.part.replaceChildren(all, ...parts);
    // Keep the chosen part while it exists (e.g. part 3 of one design, then of the next).
    if ([...ui.part.options].some((option) => option.value === previous)) ui.part.value = previous;
  }

  async function exportCurrent() {
    if (!assembly || exporting) return;
    const formatName = ui.format.value;
    const format = FORMATS[formatName];
    if (!format) return;
    const part = format.perPart ? Number(ui.part.value) : 0;
    const { name, text } = assembly;
    const fileName = exportFileName(name, formatName, part);
    exporting = true;
    setMessage('working', `Exporting ${fileName}…`);
    refresh();
    try {
      const options = format.op === 'export'
        ? { format: formatName, part, voxelSize: 1, source: name }
        : { source: name };
      const { value } = await core.run(format.op, text, options);
      // The assembly on screen may have changed meanwhile; the file is still the one asked for.
      saveBlob(fileName, new Blob([value], { type: format.type }));
      const size = typeof value === 'string' ? new TextEncoder().encode(value).length : value.byteLength;
      setMessage('done', `Saved ${fileName} (${size.toLocaleString('en')} bytes).`);
    } catch (error) {
      setMessage('error', error.cancelled ? 'Export cancelled.' : error.message);
    } finally {
      exporting = false;
      refresh();
    }
  }

  ui.format.addEventListener('change', refresh);
  ui.button.addEventListener('click', exportCurrent);
  fillParts([]);
  refresh();

  return {
    /**
     * The assembly on screen changed: `current` is `{ name, text }` or null, `report` its check
     * report (part ids and kind).
     */
    setAssembly(current, report) {
      assembly = current ? { ...current, kind: report?.kind ?? null, partIds: report?.partIds ?? [] } : null;
      fillParts(assembly?.partIds ?? [], report?.key ?? null);
      if (ui.panel.dataset.state !== 'working') setMessage('', '');
      refresh();
    },
    /** While the worker designs, an export would only wait behind the design. */
    setDisabled(disabled) {
      busy = disabled;
      refresh();
    },
  };
}
