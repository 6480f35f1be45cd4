// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Export panel: saves the assembly on screen as .puz, as the JSON document, as STL or OBJ
// meshes (3D printing; one part or all), print-ready (voxel size and clearance in mm: one STL per
// part in a ZIP, or every part laid flat on one build plate), as a BurrTools .xmpuzzle (with
// desia's disassembly as a saved solution), for plate structures as
// SVG or DXF cut sheets (one download per sheet; not for a result with milled joints, whose
// sliding dovetails are no 2D cuts: STL or OBJ for the CNC instead), for frames as .fpuz and a
// CSV cut list. Every byte comes from the core in the worker
// (toPuz, parseDocument, exportAssembly, cutSheets); the panel only picks the format, part, sheet
// size and kerf and hands the result to the browser as downloads, or shows the cut sheets' SVG
// in the panel (Preview sheets).
//
// For tests: #export-panel[data-state] = '' | working | done | error, #export-message (what was
// saved, or the core's message), #export-part (options: 0 = all parts, else a part id),
// #export-voxel-size and #export-clearance (mm; shown for the print-ready formats).

import { byId, element } from './dom.js';
import { partNoun, unjointedKind } from './report.js';

/**
 * How each format is saved: its file extension (and name suffix), MIME type, whether the Part
 * field applies and whether the print-ready fields (voxel size, clearance) show. Which kinds of
 * assembly a format takes, and whether it is cut sheets (one file per sheet), the core says: its
 * export-format registry (exportFormats, asked once through the worker).
 */
const FILES = {
  puz: { extension: 'puz', type: 'text/plain' },
  json: { extension: 'json', type: 'application/json' },
  stl: { extension: 'stl', type: 'model/stl', perPart: true },
  'stl-ascii': { extension: 'stl', suffix: '-ascii', type: 'model/stl', perPart: true },
  obj: { extension: 'obj', type: 'model/obj', perPart: true },
  fpuz: { extension: 'fpuz', type: 'text/plain' },
  csv: { extension: 'csv', type: 'text/csv' },
  'pieces-obj': { extension: 'obj', suffix: '-pieces', type: 'model/obj' },
  'joint-pieces-stl': { extension: 'stl', suffix: '-joint-pieces', type: 'model/stl' },
  'stl-zip': { extension: 'zip', type: 'application/zip', print: true },
  'build-plate-stl': { extension: 'stl', suffix: '-plate', type: 'model/stl', print: true },
  xmpuzzle: { extension: 'xmpuzzle', type: 'application/octet-stream' },
  svg: { extension: 'svg', type: 'image/svg+xml' },
  dxf: { extension: 'dxf', type: 'application/dxf' },
};
/**
 * The assembly itself rather than an export: a voxel assembly as its .puz text (toPuz), any
 * assembly as its JSON document. (The registry's own `puz` is a frame on a voxel grid, which the
 * panel does not offer.)
 */
const DOCUMENT_FORMATS = {
  puz: { op: 'to-puz', kinds: ['voxel'] },
  json: { op: 'document-json', kinds: null }, // every kind
};
/**
 * The sheet size the panel starts with: a large laser bed (CO2 lasers of 1300 x 900 mm are
 * common); the field says so and takes any other, or nothing for one sheet as large as needed.
 */
export const DEFAULT_SHEET = '1300x900';
/** Frame formats that need designed (and, for .fpuz, straight) joints: the core is asked whether it can write them. */
const PROBED_FRAME_FORMATS = ['fpuz', 'csv', 'xmpuzzle'];
/** Object URLs of downloads are freed after this; the browser has read the blob by then. */
const DOWNLOAD_URL_LIFETIME_MS = 60_000;

/** 'Cube_4x4x4_N7_seed1.puz' -> 'Cube_4x4x4_N7_seed1', safe as a file name. */
function baseName(name) {
  return (name.replace(/\.[^.]*$/, '') || 'assembly').replace(/[\\/:*?"<>|]+/g, '_');
}

/** `<name>.ext` for the whole assembly, `<name>-part3.ext` for part 3, `<name>-sheet2.svg` for sheet 2 of several. */
export function exportFileName(name, format, part, sheet = 0) {
  const { extension, suffix = '' } = FILES[format];
  return `${baseName(name)}${suffix}${part > 0 ? `-part${part}` : ''}${sheet > 0 ? `-sheet${sheet}` : ''}.${extension}`;
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
    sheet: byId('export-sheet'),
    kerf: byId('export-kerf'),
    voxelSize: byId('export-voxel-size'),
    clearance: byId('export-clearance'),
    button: byId('export-button'),
    preview: byId('export-preview'),
    sheets: byId('sheet-preview'),
    message: byId('export-message'),
    warning: byId('export-warning'),
    unavailable: byId('export-unavailable'),
    sheetNote: byId('export-sheet-note'),
  };
  // Reset by the page's own value, whatever a browser restored.
  ui.sheet.value = DEFAULT_SHEET;

  /**
   * { name, text, kind, partIds, milled, verified, unjointed, reason, refused } of the assembly on
   * screen, or null. `refused`: format -> the core's reason it cannot write this one (frames).
   */
  let assembly = null;
  /** The core's export-format registry by name ({ name, kinds, options, perSheet, what }), once asked. */
  let registry = null;
  let registryAsked = false;
  let probeToken = 0;
  let busy = false; // The worker designs for the Design panel.
  let exporting = false;

  /**
   * Asks the core, in the worker, for its export formats: once, with the first assembly (the page
   * starts its worker after wiring the panels), again after a failure.
   */
  async function askRegistry() {
    if (registry || registryAsked) return;
    registryAsked = true;
    try {
      const { value } = await core.run('export-formats');
      registry = new Map(value.map((info) => [info.name, info]));
      refresh();
    } catch {
      registryAsked = false; // cancelled with the worker, or a broken core: asked at the next assembly
    }
  }

  /**
   * What the panel knows of a format: how it is saved (FILES) with what the core says of it (its
   * kinds, cut sheets or not), or null while the core has not answered or does not know it.
   */
  function formatOf(name) {
    const file = FILES[name];
    if (!file) return null;
    if (name in DOCUMENT_FORMATS) return { ...file, ...DOCUMENT_FORMATS[name], cut: false };
    const info = registry?.get(name);
    if (!info) return null;
    return { ...file, op: info.perSheet ? 'cut-sheets' : 'export', kinds: info.kinds, cut: info.perSheet };
  }

  function setMessage(state, text) {
    ui.panel.dataset.state = state;
    ui.message.textContent = text;
    ui.message.hidden = !text;
  }

  const MILLED_REASON = 'SVG and DXF cut sheets are greyed out: milled joints (sliding dovetails) are no 2D cuts; export STL or OBJ for the CNC.';
  // A mesh assembly (web/mesh-assembly.js) is shown from its own files: no document to convert.
  const MESH_REASON = 'Nothing to export for a mesh assembly: its own OBJ, STL or 3MF files are already the parts as meshes, '
    + 'and desia checks them without making a document of them (the formats here are for voxel puzzles, plates and frames).';

  function refresh() {
    const milled = Boolean(assembly?.milled);
    const mesh = assembly?.kind === 'mesh';
    const refused = assembly?.refused ?? {};
    for (const option of ui.format.options) {
      const known = formatOf(option.value);
      // Each format holds the kinds the core lists for it (SVG and DXF plates, .fpuz and CSV
      // frames, ...); cut sheets cannot hold milled dovetails (the core would say so too); a frame
      // format the core refused for this frame (a curved beam in .fpuz) says why. Until the core
      // has listed its formats, only the document's own (.puz, JSON) are offered.
      if (!known) {
        option.disabled = assembly !== null;
        option.title = '';
        continue;
      }
      option.disabled = assembly !== null && (mesh || (known.kinds !== null && !known.kinds.includes(assembly.kind)) || (known.cut === true && milled) || option.value in refused);
      option.title = known.cut && milled ? MILLED_REASON : (refused[option.value] ?? '');
    }
    if (assembly && !mesh && ui.format.selectedOptions[0]?.disabled) ui.format.value = assembly.kind === 'plate' ? (milled ? 'stl' : 'svg') : 'json';
    const format = formatOf(ui.format.value);
    ui.part.disabled = !assembly || !format?.perPart;
    ui.part.hidden = Boolean(format?.cut);
    for (const field of [ui.sheet, ui.kerf]) field.closest('label').hidden = !format?.cut;
    ui.preview.hidden = ui.sheetNote.hidden = !format?.cut;
    // Greyed formats, in words: a tooltip never shows on a touch screen.
    const reasons = [];
    if (assembly?.kind === 'plate' && milled) reasons.push(MILLED_REASON);
    if (mesh) reasons.push(MESH_REASON);
    for (const [name, reason] of Object.entries(refused)) reasons.push(`${name === 'csv' ? 'CSV' : `.${name}`} is greyed out: ${reason}`);
    ui.unavailable.textContent = reasons.join(' ');
    ui.unavailable.hidden = reasons.length === 0;
    renderWarning();
    // Voxel size and clearance are for voxel parts (a plate structure's ZIP is in mm already).
    for (const field of [ui.voxelSize, ui.clearance]) field.closest('label').hidden = !format?.print || (assembly !== null && assembly.kind !== 'voxel');
    ui.button.disabled = !assembly || busy || exporting || !format || ui.format.selectedOptions[0]?.disabled;
    ui.preview.disabled = ui.button.disabled;
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

  /**
   * Files of an assembly that is not a verified interlocking result (a plate or frame without
   * joints, after a failed design too; a voxel assembly that does not interlock) come with a
   * warning in plain sight: someone may cut wood from them.
   */
  function renderWarning() {
    const text = assembly && (!assembly.verified || assembly.planned) ? warningText(assembly) : '';
    ui.warning.textContent = text;
    ui.warning.hidden = !text;
    ui.panel.dataset.unverified = String(Boolean(text));
  }

  function warningText({ name, kind, unjointed, reason, parts, planned, verified }) {
    const noun = partNoun(kind);
    if (planned && verified) {
      // The paper's plan alone (Joints: planned): verified as a plan, but no joint is in the plates.
      return `Joints planned, not cut: ${name} says which joint goes where (the Joints list), but these files are `
        + 'the bare plates (plain outlines on the cut sheets). Design with Joints auto, cut or milled for plates with their joints.';
    }
    if (kind === 'voxel' && parts <= 1) return ''; // a shape to design from: one part, nothing to hold
    if (kind === 'contacts' || kind === 'mesh') return '';  // nothing is exported from a mesh assembly
    if (unjointed) {
      return `Not jointed, not verified: ${name} has no joints, so these files are its bare ${noun}s `
        + `(${kind === 'plate' ? 'plain outlines on the cut sheets' : 'beams without joint voxels'}); nothing holds them together. `
        + 'Design makes the joints and checks them (if Design found no plan, there is none to make).';
    }
    return `Not verified: ${name} is not interlocking${reason ? ` (${reason})` : ''}; files made from it will not hold together as a puzzle.`;
  }

  /** What a saved file's message adds when the assembly is not verified. */
  function unverifiedSuffix() {
    if (!assembly || !ui.warning.textContent) return '';
    return assembly.verified ? ' Joints not cut: see the warning above.' : ' Not jointed or verified: see the warning above.';
  }

  /**
   * Frames: asks the core, in the worker, whether it can write the formats that need designed,
   * straight joints (.fpuz, CSV) for this frame; a refusal greys the format with the core's reason.
   */
  async function probeFrameFormats(current) {
    const token = ++probeToken;
    const refused = {};
    for (const format of PROBED_FRAME_FORMATS) {
      try {
        await core.run('export', current.text, { format, part: 0, source: current.name });
      } catch (error) {
        if (error.cancelled) return;
        // The core's message names the file first: the reason is what follows it.
        refused[format] = error.message.startsWith(`${current.name}: `) ? error.message.slice(current.name.length + 2) : error.message;
      }
      if (token !== probeToken || assembly !== current) return;
    }
    current.refused = refused;
    refresh();
  }

  async function exportCurrent() {
    if (!assembly || exporting) return;
    const formatName = ui.format.value;
    const format = formatOf(formatName);
    if (!format) return;
    const part = format.perPart ? Number(ui.part.value) : 0;
    const { name, text } = assembly;
    const fileName = exportFileName(name, formatName, part);
    exporting = true;
    setMessage('working', `Exporting ${fileName}…`);
    refresh();
    try {
      if (format.cut) {
        await exportCutSheets(formatName, format, name, text);
        return;
      }
      const options = format.op === 'export'
        ? { format: formatName, part, voxelSize: 1, source: name, ...(format.print ? printOptions() : {}) }
        : { source: name };
      const { value } = await core.run(format.op, text, options);
      // The assembly on screen may have changed meanwhile; the file is still the one asked for.
      saveBlob(fileName, new Blob([value], { type: format.type }));
      const size = typeof value === 'string' ? new TextEncoder().encode(value).length : value.byteLength;
      setMessage('done', `Saved ${fileName} (${size.toLocaleString('en')} bytes).${unverifiedSuffix()}`);
    } catch (error) {
      setMessage('error', error.cancelled ? 'Export cancelled.' : withSheetHint(error.message));
    } finally {
      exporting = false;
      refresh();
    }
  }

  /** The core's "does not fit on a … sheet" gets the way out: a larger sheet, or none. */
  function withSheetHint(message) {
    return /does not fit on a/.test(message)
      ? `${message}. Type a larger sheet (e.g. 2440x1220, a plywood sheet) or empty the field for one sheet as large as needed.`
      : message;
  }

  /**
   * Voxel size and clearance (mm) of the print-ready formats; an empty field is its default (10 mm,
   * no clearance). The core checks the ranges (the clearance below half a voxel) and names the value.
   */
  function printOptions() {
    const number = (field, fallback, what) => {
      if (field.value.trim() === '') return fallback;
      const value = Number(field.value);
      if (!Number.isFinite(value)) throw new Error(`The ${what} must be a number of mm, got '${field.value}'.`);
      return value;
    };
    return { voxelSize: number(ui.voxelSize, 10, 'voxel size'), clearance: number(ui.clearance, 0, 'clearance') };
  }

  /** The cut-sheet options of the panel's fields. */
  function cutOptions(formatName, name) {
    const options = { format: formatName, source: name };
    if (ui.sheet.value.trim()) options.sheet = ui.sheet.value.trim();
    if (ui.kerf.value !== '') options.kerf = Number(ui.kerf.value);
    return options;
  }

  function clearPreview() {
    ui.sheets.replaceChildren();
    ui.sheets.hidden = true;
    delete ui.sheets.dataset.sheets;
  }

  /**
   * The cut sheets drawn in the panel, one image per sheet with its size in mm: the same SVG text
   * the download saves (the core writes it; the page only shows it).
   */
  async function previewCutSheets() {
    if (!assembly || exporting) return;
    const { name, text } = assembly;
    exporting = true;
    setMessage('working', 'Laying out the cut sheets…');
    refresh();
    try {
      const { value: sheets } = await core.run('cut-sheets', text, cutOptions('svg', name));
      clearPreview();
      const figures = sheets.map((svg, k) => {
        // Drawn inline so that the page's stylesheet can keep the cuts one pixel wide at any zoom
        // (the file's own 0.1 mm strokes vanish at this scale); its <style> is dropped before
        // parsing (the page's CSP allows none, and parsing it logged a violation per sheet), the
        // colours are in the paths' attributes too.
        const parsed = new DOMParser().parseFromString(svg.replace(/<style[^>]*>[\s\S]*?<\/style>/g, ''), 'image/svg+xml').documentElement;
        if (parsed.nodeName !== 'svg') throw new Error('the core returned a cut sheet that is not SVG');
        for (const style of parsed.querySelectorAll('style, script')) style.remove();
        const drawing = document.importNode(parsed, true);
        drawing.removeAttribute('width');
        drawing.removeAttribute('height');
        drawing.setAttribute('role', 'img');
        drawing.setAttribute('aria-label', `Cut sheet ${k + 1} of ${sheets.length}`);
        const size = /<svg[^>]*\bwidth="([0-9.]+)mm"[^>]*\bheight="([0-9.]+)mm"/.exec(svg);
        const figure = element('figure');
        figure.dataset.bytes = String(new TextEncoder().encode(svg).length);
        figure.append(drawing, element('figcaption',
          `Sheet ${k + 1} of ${sheets.length}${size ? ` · ${size[1]} × ${size[2]} mm` : ''}`
          + ' · red: outer cuts, blue: inner cuts, black: engraving'));
        return figure;
      });
      ui.sheets.append(...figures);
      ui.sheets.dataset.sheets = String(sheets.length);
      ui.sheets.hidden = false;
      setMessage('done', `${sheets.length} ${sheets.length === 1 ? 'sheet' : 'sheets'} shown below.${unverifiedSuffix()}`);
    } catch (error) {
      clearPreview();
      setMessage('error', error.cancelled ? 'Preview cancelled.' : withSheetHint(error.message));
    } finally {
      exporting = false;
      refresh();
    }
  }

  /** The cut sheets of a plate structure, one download per sheet. */
  async function exportCutSheets(formatName, format, name, text) {
    const options = cutOptions(formatName, name);
    const { value: sheets } = await core.run('cut-sheets', text, options);
    const names = sheets.map((_, k) => exportFileName(name, formatName, 0, sheets.length > 1 ? k + 1 : 0));
    sheets.forEach((sheet, k) => saveBlob(names[k], new Blob([sheet], { type: format.type })));
    setMessage('done', (sheets.length === 1
      ? `Saved ${names[0]} (1 sheet).`
      : `Saved ${sheets.length} sheets: ${names[0]} … ${names.at(-1)}.`) + unverifiedSuffix());
  }

  ui.format.addEventListener('change', refresh);
  ui.button.addEventListener('click', exportCurrent);
  ui.preview.addEventListener('click', previewCutSheets);
  fillParts([]);
  refresh();

  return {
    /**
     * The assembly on screen changed: `current` is `{ name, text }` or null, `report` its check
     * report (part ids and kind), `document_` its document (a plate result's jointGeometry).
     */
    setAssembly(current, report, document_ = null) {
      assembly = current ? {
        ...current,
        kind: report?.kind ?? null,
        partIds: report?.partIds ?? [],
        parts: report?.parts ?? report?.partIds?.length ?? 0,
        milled: report?.kind === 'plate' && document_?.jointGeometry === 'milled',
        planned: report?.kind === 'plate' && document_?.jointGeometry === 'planned',
        verified: report?.verdict === 'interlocking',
        unjointed: Boolean(unjointedKind(document_)),
        reason: report?.reason ?? '',
        refused: {},
      } : null;
      askRegistry();
      fillParts(assembly?.partIds ?? [], report?.key ?? null);
      clearPreview();  // the sheets of the assembly that was on screen
      if (ui.panel.dataset.state !== 'working') setMessage('', '');
      refresh();
      if (assembly?.kind === 'frame') probeFrameFormats(assembly);
    },
    /** While the worker designs, an export would only wait behind the design. */
    setDisabled(disabled) {
      busy = disabled;
      refresh();
    },
  };
}
