// SPDX-License-Identifier: GPL-3.0-or-later
//
// The desia playground page: picks an assembly (bundled example, file picker or drag-and-drop),
// sends it to the WebAssembly core running in a module worker, draws the parts with three.js
// and lists the interlocking report; the Design panel (design-panel.js) turns the assembly's
// voxels into a new puzzle. The page itself never loads the WebAssembly module, so a slow check
// or design, or a crashed core, cannot freeze or break it.
//
// For tests the page exposes: body[data-status] = loading | ready | error, body[data-source] =
// the assembly last asked for (shown, or named by the error), body[data-shown] = the assembly in
// the 3D view and report (a file that fails to load leaves the previous one there),
// body[data-webgl] = on | off, body[data-core] = starting | ready (the worker), #verdict (text,
// data-verdict: the core's verdict, or 'shape' for a one-part voxel shape to design from;
// data-key), #still-showing (after a failed load: what the view still shows), #method-note (the graph test is not exact for this assembly) and #error;
// design-panel.js, mesh-input.js, export-panel.js, parts-panel.js and offline.js add their own.

import { byId, element, fitSelectToValue } from './dom.js';
import { AssemblyView, createPlaybackControls } from './view.js';
import { highlightMove, highlightRemovalStep, renderPlan, renderReport, resetReport, unjointedKind, withPlannedRemoval } from './report.js';
import { CoreWorker } from './worker-client.js';
import { createDesignPanel } from './design-panel.js';
import { readUrlState, writeUrlState } from './url-state.js';
import { createMeshInput, isMeshName } from './mesh-input.js';
import { createMeshAssemblyInput, isMeshAssemblyName } from './mesh-assembly.js';
import { createExportPanel } from './export-panel.js';
import { keepForOffline, registerServiceWorker } from './offline.js';
import { createPartsPanel } from './parts-panel.js';

// ---------------------------------------------------------------------------------------------
// Configuration

/**
 * Bundled voxel files (copies of the original authors' results and input shapes) and plate
 * designs (examples/plate/, in mm), served from this origin. Shapes are one-part assemblies to
 * design from; plate designs have no joints yet (Design plans them). `joints`: the Joints choice
 * a plate design needs ('milled', 'planned'; else the default 'auto'), set when it is loaded.
 */
const EXAMPLES = [
  { file: 'Cube_4x4x4_K9.puz', label: 'Cube 4×4×4, 9 parts' },
  { file: 'Cube_4x4x4_K9_01.puz', label: 'Cube 4×4×4, 7 parts' },
  { file: 'Cube_Hollow_4x4x4_K7.puz', label: 'Hollow cube 4×4×4, 7 parts' },
  { file: 'cube_5x5x5_K16.puz', label: 'Cube 5×5×5, 16 parts' },
  { file: 'cartoon_dog.puz', label: 'Cartoon dog, 14 parts' },
  { file: 'bunny_15x14x11_K80.puz', label: 'Bunny, 80 parts' },
  { file: 'Cube_4x4x4_origin.puz', label: 'Cube 4×4×4', shape: true },
  { file: 'Cube_5x5x5_origin.puz', label: 'Cube 5×5×5', shape: true },
  { file: 'Cube_hollow_4x4x4_origin.puz', label: 'Hollow cube 4×4×4', shape: true },
  { file: 'bunny_origin.puz', label: 'Bunny', shape: true },
  { file: 'dog_origin.puz', label: 'Dog', shape: true },
  { file: 'table.json', label: 'Table, 6 plates', plate: true },
  { file: 'table_divider.json', label: 'Table with a divider, 7 plates (halved joint)', plate: true },
  { file: 'table_split_side.json', label: 'Table with a side in two halves, 7 plates (in-plane dovetail)', plate: true },
  { file: 'bench_2_bays.json', label: 'Table of 2 bays, 10 plates', plate: true },
  { file: 'long_table_102.json', label: 'Long table, 102 plates', plate: true },
  { file: 'chair_cut_point.json', label: 'Chair with a cut point, 8 plates', plate: true },
  // Boards whose joints need milling (Joints "milled") or that only the paper's plan joins ("planned only").
  { file: 'chair_repaired.json', label: 'Chair repaired, 10 plates (milled)', plate: true, joints: 'milled' },
  { file: 'cabinet.json', label: 'Cabinet under a gable roof, 7 plates (milled)', plate: true, joints: 'milled' },
  { file: 'table_slanted_crossing.json', label: 'Table with a tilted shelf and a divider crossing it at 60°, 7 plates (milled halved joint)', plate: true, joints: 'milled' },
  { file: 'mitred_box.json', label: 'Mitred box, 6 plates (milled mitre tenons)', plate: true, joints: 'milled' },
  { file: 'dodecahedron.json', label: 'Dodecahedron, 12 mitred plates (milled mitre tenons)', plate: true, joints: 'milled' },
  { file: 'icosahedron.json', label: 'Icosahedron, 20 mitred plates (milled step tenons; some seconds)', plate: true, joints: 'milled', timeLimit: 300 },
  { file: 'slanted_box.json', label: 'Slanted box, 6 mitred plates leaning out 55° (milled)', plate: true, joints: 'milled' },
  { file: 'lizard.json', label: 'Lizard, 38 mitred plates (milled mitre tenons and slides; a few seconds)', plate: true, joints: 'milled', timeLimit: 300 },
  // Flush boards that no mortise-and-tenon lets out: sliding dovetails, milled on a CNC.
  { file: 'bookshelf.json', label: 'Bookshelf, 12 plates (milled dovetails)', plate: true, joints: 'milled' },
  { file: 'bookcase_123.json', label: 'Bookcase, 123 plates (milled)', plate: true, joints: 'milled' },
  // Frames (examples/frame/, in mm): beams joined by 3x3x3 voxel joints; Design makes the joints.
  { file: 'frame_cube.json', label: 'Frame cube, 12 beams', frame: true },
  { file: 'frame_chair.json', label: 'Frame chair, 11 beams', frame: true },
  { file: 'flower.json', label: 'Flower, 23 curved beams', frame: true },
  { file: 'scaffold_92.json', label: 'Scaffold, 92 beams', frame: true },
  { file: 'scaffold_300.json', label: 'Scaffold 4×4×4 cells, 300 beams', frame: true },
  { file: 'scaffold_882.json', label: 'Scaffold 6×6×6 cells, 882 beams', frame: true },
  { file: 'cut_point.json', label: 'Two squares with a cut-point beam', frame: true },
  { file: 'frame_cube_result.json', label: 'Frame cube, designed', frame: true },
  { file: 'frame_chair_result.json', label: 'Frame chair, designed', frame: true },
  { file: 'flower_result.json', label: 'Flower, designed', frame: true },
  { file: 'scaffold_92_result.json', label: 'Scaffold of 92 beams, designed', frame: true },
];
/**
 * What a first visit opens: a shape Design makes sense on (a finished puzzle would only be split
 * again), so the three steps of the introduction (pick, design, play / export) follow in order.
 */
const DEFAULT_EXAMPLE = 'Cube_4x4x4_origin.puz';
const EXAMPLES_URL = new URL('../examples/voxel/', import.meta.url);
const PLATE_EXAMPLES_URL = new URL('../examples/plate/', import.meta.url);
const FRAME_EXAMPLES_URL = new URL('../examples/frame/', import.meta.url);

function exampleUrl(file) {
  const example = EXAMPLES.find((candidate) => candidate.file === file);
  return new URL(file, example?.plate ? PLATE_EXAMPLES_URL : example?.frame ? FRAME_EXAMPLES_URL : EXAMPLES_URL);
}
const USER_FILE_OPTION = '__user-file__';
/** The menu entry that names a designed result (or a design step) while it is on screen. */
const RESULT_OPTION = '__result__';

/** Larger inputs are refused before reading: a voxel file this big is surely a mistake. */
const MAX_FILE_BYTES = 32 * 1024 * 1024;
/** Object URLs of downloads are freed after this; the browser has read the blob by then. */
const DOWNLOAD_URL_LIFETIME_MS = 60_000;

// ---------------------------------------------------------------------------------------------
// Page elements and status

const ui = {
  exampleSelect: byId('example-select'),
  fileInput: byId('file-input'),
  methodSelect: byId('method-select'),
  downloadButton: byId('download-button'),
  statusText: byId('status-text'),
  viewport: byId('viewport'),
  viewerNotice: byId('viewer-notice'),
  disassemblyRange: byId('disassembly-range'),
  disassemblyStep: byId('disassembly-step'),
  viewerControls: byId('viewer-controls'),
  disassemblyPlay: byId('disassembly-play'),
  disassemblyPrev: byId('disassembly-prev'),
  disassemblyNext: byId('disassembly-next'),
  disassemblySpeed: byId('disassembly-speed'),
  disassemblyLoop: byId('disassembly-loop'),
  disassemblyMoves: byId('disassembly-moves'),
  explodedRange: byId('exploded-range'),
  error: byId('error'),
  stillShowing: byId('still-showing'),
  sourceName: byId('source-name'),
  methodNote: byId('method-note'),
  methodNoteLp: byId('method-note-lp'),
  coreVersion: byId('core-version'),
  dropOverlay: byId('drop-overlay'),
  intro: byId('intro'),
  introClose: byId('intro-close'),
  designSettings: byId('design-settings'),
};

const STATUS_LABELS = { loading: 'Working…', ready: 'Ready', error: 'Error' };

function setStatus(status, text = STATUS_LABELS[status]) {
  document.body.dataset.status = status;
  ui.statusText.textContent = text;
}

function showError(message) {
  ui.error.textContent = message;
  ui.error.hidden = false;
}

function hideError() {
  ui.error.textContent = '';
  ui.error.hidden = true;
  ui.stillShowing.textContent = '';
  ui.stillShowing.hidden = true;
}

// ---------------------------------------------------------------------------------------------
// The assembly on screen

const view = new AssemblyView(ui.viewport, {
  notice: ui.viewerNotice,
  onWebGL: (on) => { document.body.dataset.webgl = on ? 'on' : 'off'; },
  // A click on a part selects it in the part list (and the graphs); on empty space, nothing.
  onPartClick: (partId) => partsPanel.select(partId),
  // Removed parts lie in a tray beside the assembly; the leaving part's way out is drawn.
  tray: true,
  arrows: true,
});
// The part list: selection shared by the list, the view and the blocking graphs; hide, isolate.
const partsPanel = createPartsPanel({
  list: byId('part-list'),
  summary: byId('parts-summary'),
  isolateButton: byId('part-isolate'),
  hideButton: byId('part-hide'),
  showAllButton: byId('part-show-all'),
}, { view, graphs: byId('dbg-panel') });
// Play/pause, slider, speed, loop and explode (view.js); the removal shown is marked in the report.
const playback = createPlaybackControls(view, {
  range: ui.disassemblyRange,
  label: ui.disassemblyStep,
  moves: ui.disassemblyMoves,
  playButton: ui.disassemblyPlay,
  previousButton: ui.disassemblyPrev,
  nextButton: ui.disassemblyNext,
  speedSelect: ui.disassemblySpeed,
  loopCheckbox: ui.disassemblyLoop,
  explodedRange: ui.explodedRange,
  root: ui.viewerControls,
}, {
  // A plan of moves marks its move in the list of moves; a part-by-part plan its removal.
  onStep: ({ index, moves }) => {
    highlightMove(moves ? index : -1);
    highlightRemovalStep(moves ? -1 : index);
  },
});
// A small read-only handle for tests and debugging in the console.
window.__desiaView = {
  partPositions: () => view.partPositions(),
  trayPositions: () => view.trayPositions(),
  assemblyBounds: () => view.assemblyBounds(),
  partBounds: (partId) => view.partBounds(partId),
  get stepsPerSecond() { return playback.player.stepsPerSecond; },
  screenPoint: (partId) => view.screenPoint(partId),
  partAt: (x, y) => view.partAt(x, y),
  get selected() { return view.selectedPart; },
  framing: () => view.framing(),
  renderStats: () => view.renderStats(),
  get step() { return view.disassemblyStep; },
  get steps() { return playback.player.length; },
  /** Playing a plan of moves: the parts of the move shown (they glow). */
  get movingParts() { return view.movingParts; },
  get playing() { return playback.player.playing; },
  get exploded() { return view.exploded; },
};
let coreReady = false;
/** { name, text } of the assembly on screen: re-checked with another method, downloaded, exported. */
let current = null;
/**
 * Everything needed to put the last successfully shown assembly back on screen: a file that fails
 * to load leaves it there. { name, text, document, surfaces, report, elapsedMs, timingLabel, option, optionLabel }
 */
let shown = null;
/**
 * The input the Design panel designs from: the last assembly the user loaded (an example, a file,
 * a voxelized mesh), not a result designed from it, so Design on a result designs the same input
 * again. { name, text, kind }
 */
let designInput = null;
let loadGeneration = 0; // Only the newest load may touch the page.
let lastUserFile = null; // The user's last file, so its select entry can load it again.

/**
 * `assembly` = { name, text } (null: nothing on screen); it keeps the report's kind. `document_`
 * (its parsed document) tells the export panel how a plate result's joints were made.
 */
function setCurrent(assembly, report = null, document_ = null) {
  exportPanel.setAssembly(assembly, report, document_);
  current = assembly ? { ...assembly, kind: report?.kind ?? null } : null;
  // A mesh assembly is checked, not designed: the panel keeps its input's kind and says so.
  if (current && current.kind !== 'mesh') designPanel.setKind(current.kind);
  designPanel.setMeshAssembly(current?.kind === 'mesh' ? current.name : null);
  ui.downloadButton.disabled = !current?.text; // a mesh assembly has files, not a text
  ui.downloadButton.textContent = `Download .${/\.(json|fpuz)$/i.exec(current?.name ?? '')?.[1]?.toLowerCase() ?? 'puz'}`;
}

function isJsonName(name) {
  return /\.json$/i.test(name ?? '');
}

/** Puts the menu on the entry for what is on screen (`option`: a value; `label` for the user's file and results). */
function selectMenuEntry(option, label) {
  for (const value of [USER_FILE_OPTION, RESULT_OPTION]) {
    const entry = ui.exampleSelect.querySelector(`option[value="${value}"]`);
    if (value === option) {
      if (label) entry.textContent = label;
      entry.hidden = false;
    } else if (value === RESULT_OPTION) {
      entry.hidden = true; // a result is only listed while it is on screen
    }
  }
  ui.exampleSelect.value = option;
  fitSelectToValue(ui.exampleSelect);
}

function menuLabel(option) {
  return ui.exampleSelect.querySelector(`option[value="${option}"]`)?.textContent ?? '';
}

function voxelCount(document_) {
  const labels = document_?.voxel?.labels ?? [];
  let count = 0;
  for (const label of labels) if (label > 0) count += 1;
  return count;
}

/**
 * Puts an assembly on screen whose document, part surfaces and report are already known (a
 * designed puzzle, a design step). It supersedes any load still in flight. Step by step passes
 * `keepCamera` (the user's camera stays) and `emphasis` ({ highlight, ghost } part ids, view.js).
 */
function showAssembly({ name, text, document: document_, surfaces, report, elapsedMs, timingLabel, menuLabel: label = `Designed: ${name}`, keepCamera = false, emphasis = null, inProgress = null }) {
  loadGeneration += 1;
  document.body.dataset.source = name;
  hideError();
  selectMenuEntry(RESULT_OPTION, label);
  present({ name, text, document: document_, surfaces, report, elapsedMs, timingLabel, option: RESULT_OPTION, optionLabel: label, keepCamera, emphasis, inProgress });
  setStatus('ready');
  // Voxel designs are verified with the graph test; another chosen test runs on the result as
  // well (plate plans are verified with both tests already).
  if (report.method && report.method !== 'both' && report.method !== ui.methodSelect.value) loadAssembly(name, async () => text, { asInput: false });
}

/**
 * Draws an assembly whose document, surfaces and report are known, fills the report and makes it
 * the current one (the 3D view, the report panel, the download and export).
 */
function present(assembly) {
  const { name, text, document: document_, surfaces, report, elapsedMs, timingLabel = 'Check time', keepCamera = false, emphasis = null, inProgress = null } = assembly;
  shown = assembly;
  document.body.dataset.shown = name;
  ui.sourceName.textContent = name;
  view.show(document_, surfaces, { keepCamera });
  setCurrent({ name, text }, report, document_);
  // A plate plan is played along its own planned removal directions.
  const played = withPlannedRemoval(report, document_);
  renderReport(played, elapsedMs, timingLabel, {
    voxels: document_.kind === 'voxel' ? voxelCount(document_) : null,
    // A plate or frame without joints, or a design step short of its target, is an input to
    // design from: said neutrally, not as a failed puzzle.
    input: inProgress ? null : unjointedKind(document_),
    inProgress,
  });
  renderPlan(document_);
  view.applyReport(played, { keepCamera });
  if (emphasis) view.setEmphasis(emphasis);
  partsPanel.setAssembly(name, document_, played);
  markNextStep(report);
  // A partial plan of moves (a disassemblyFailure with steps) plays up to where it stops.
  setUpDisassemblySlider(view.available ? (played.disassembly ?? played.disassemblyFailure ?? null) : null);
}

/**
 * Shows one assembly: `readText` yields its text (a fetch or a file read, so that their errors
 * land in the same error box as the core's).
 */
async function loadAssembly(name, readText, { origin = name, asInput = true } = {}) {
  const generation = ++loadGeneration;
  const isCurrent = () => generation === loadGeneration;
  // The menu entry asked for; on failure the menu goes back to the one on screen.
  const option = ui.exampleSelect.value;
  const optionLabel = menuLabel(option);
  setStatus('loading', coreReady ? 'Checking…' : 'Starting the core…');
  document.body.dataset.source = name;
  ui.sourceName.textContent = name;
  setCurrent(null);
  hideError();
  // The view keeps the previous assembly until this one is parsed and checked.
  resetReport('Checking…');
  try {
    const loaded = await readText();
    if (!isCurrent()) return;
    // A mesh assembly comes checked and drawn already (web/mesh-assembly.js); text is parsed here.
    const { text, document: document_, surfaces, report, elapsedMs } = typeof loaded === 'string' ? await parseAndCheck(name, loaded) : loaded;
    if (!isCurrent()) return;
    // A plate plan opened from a file plays its own removal, as it did when it was designed.
    present({ name, text, document: document_, surfaces, report, elapsedMs, option, optionLabel });
    if (asInput) {
      designInput = { name, text, kind: report.kind ?? document_.kind };
      designPanel.setInput(designInput, describeInput(document_, report));
      if (document_.kind === 'voxel') designPanel.shapeLoaded(voxelCount(document_));
    }
    setStatus('ready');
  } catch (error) {
    if (!isCurrent()) return;
    // The core's messages start with the source name already; others (fetch, worker) get it here.
    // `origin` is the file the text came from when it is not `name` (a mesh and its voxels).
    const message = error.message.startsWith(name) || error.message.startsWith(origin) ? error.message : `${name}: ${error.message}`;
    if (shown) {
      // The previous assembly stays until a valid one replaces it.
      present(shown);
      selectMenuEntry(shown.option, shown.optionLabel);
      showError(message);
      ui.stillShowing.textContent = `Still showing ${shown.name}: the view and the report below are about it.`;
      ui.stillShowing.hidden = false;
    } else {
      setCurrent(null);
      view.clear();
      partsPanel.clear();
      setUpDisassemblySlider(null);
      resetReport('No result');
      showError(message);
    }
    setStatus('error');
  }
}

/** The document, part surfaces and check report of an assembly's text. */
async function parseAndCheck(name, text) {
  // `source` makes the core's error messages name the file (and line) they are about.
  const { value: { document: document_, surfaces } } = await core.run('parse', text, { source: name });
  const { value: report, elapsedMs } = await core.run('check', text, { method: ui.methodSelect.value, source: name });
  return { text, document: document_, surfaces, report, elapsedMs };
}

/** 'Cube_4x4x4_origin.puz · 64 voxels' ('· 6 plates', '· 12 beams'): what Design starts from. */
function describeInput(document_, report) {
  const kind = report.kind ?? document_.kind;
  if (kind === 'voxel') {
    const parts = report.parts > 1 ? `, ${report.parts} parts` : '';
    return `${voxelCount(document_)} voxels${parts}`;
  }
  const noun = kind === 'plate' ? 'plates' : kind === 'frame' ? 'beams' : 'parts';
  return `${report.parts} ${noun}`;
}

async function fetchExampleText(file) {
  const url = exampleUrl(file);
  const response = await fetch(url);
  if (!response.ok) throw new Error(`cannot fetch example ${url.pathname} (HTTP ${response.status})`);
  return response.text();
}

/**
 * Loads a bundled example; it brings the Joints choice it needs (`joints` in EXAMPLES), unless
 * `keepJoints` (the first load of a shared link that says which joints).
 */
function loadExample(file, { keepJoints = false, first = false } = {}) {
  if (!keepJoints) {
    const example = EXAMPLES.find((entry) => entry.file === file);
    designPanel.setExampleJoints(example?.joints ?? null, example?.timeLimit ?? null);
  }
  // Another input: the last run's message, progress and N belong to the previous one (a shared
  // link's N is kept for its first load).
  designPanel.inputChanged({ keepParts: first });
  selectMenuEntry(file);
  meshAssemblies.forget();
  if (meshInput.isExample(file)) return meshInput.openExample(file);
  meshInput.forget();
  return loadAssembly(file, () => fetchExampleText(file));
}

/**
 * Files dropped or picked: several (all OBJ, STL or 3MF), or one 3MF, are a mesh assembly; one file
 * is loaded as before (an OBJ or STL of several parts becomes a mesh assembly there).
 */
function loadUserFiles(files) {
  if (files.length === 1 && !/\.3mf$/i.test(files[0].name)) return loadUserFile(files[0]);
  const names = files.map((file) => file.name);
  lastUserFile = files;
  designPanel.setExampleJoints(null);
  designPanel.inputChanged();
  meshInput.forget();
  selectMenuEntry(USER_FILE_OPTION, `Your files: ${names.join(', ')}`);
  if (!files.every((file) => isMeshAssemblyName(file.name))) {
    meshAssemblies.forget();
    showError(`${names.join(', ')}: several files are one assembly only when each is a mesh (.obj, .stl or .3mf); open other files one at a time`);
    return Promise.resolve();
  }
  return meshAssemblies.open(files);
}

function loadUserFile(file) {
  meshAssemblies.forget();
  lastUserFile = file;
  designPanel.setExampleJoints(null); // the user's own design: 'auto' unless the user chose otherwise
  designPanel.inputChanged();
  selectMenuEntry(USER_FILE_OPTION, `Your file: ${file.name}`);
  if (isMeshName(file.name)) return openMeshOrFrame(file);
  meshInput.forget();
  return loadAssembly(file.name, async () => {
    if (file.size > MAX_FILE_BYTES) {
      throw new Error(`the file is ${(file.size / 1048576).toFixed(1)} MiB; the playground accepts up to ${MAX_FILE_BYTES / 1048576} MiB`);
    }
    return decodeText(file.name, await file.arrayBuffer());
  });
}

/** An OBJ with line elements (`l`) is a frame (its lines and face edges are beams); others are meshes to voxelize. */
async function openMeshOrFrame(file) {
  if (!/\.obj$/i.test(file.name) || file.size > MAX_FILE_BYTES) return openMesh(file);
  let text;
  try {
    text = decodeText(file.name, await file.arrayBuffer());
  } catch {
    return openMesh(file); // the voxelizer names what is wrong with it
  }
  if (!/^\s*l\s/m.test(text)) return openMesh(file);
  meshInput.forget();
  // The core reads the OBJ as a frame and gives its JSON document, which the page then shows.
  return loadAssembly(`${file.name.replace(/\.obj$/i, '')}.json`, async () => {
    const { value } = await core.run('frame-document', text, { source: file.name });
    return value;
  }, { origin: file.name });
}

/** A mesh of several parts is a mesh assembly; one solid is a shape to voxelize. */
async function openMesh(file) {
  if (await meshAssemblies.openIfSeveralParts(file)) return;
  meshInput.openFile(file);
}

/**
 * Strict UTF-8 decoding: a lenient decoder would turn a binary file into U+FFFD characters and
 * the core would then report bytes the user's file never contained.
 */
function decodeText(name, buffer) {
  try {
    return new TextDecoder('utf-8', { fatal: true }).decode(buffer);
  } catch {
    throw new Error(`${name}: not a text file (it is not valid UTF-8); expected a .puz, desia .json or .fpuz file`);
  }
}

// ---------------------------------------------------------------------------------------------
// The disassembly slider: 0 = assembled, i..i+1 = the (i+1)-th part of the order moving out, or,
// for a plan of moves (the report's steps), the (i+1)-th move under way.

function setUpDisassemblySlider(disassembly) {
  playback.setDisassembly(disassembly);
}


// ---------------------------------------------------------------------------------------------
// Download: the text of the assembly on screen, unchanged (a loaded file keeps its own text).

function downloadCurrent() {
  if (!current) return;
  const type = isJsonName(current.name) ? 'application/json' : 'text/plain';
  const url = URL.createObjectURL(new Blob([current.text], { type }));
  const link = element('a');
  link.href = url;
  link.download = current.name.replace(/[\\/:*?"<>|]+/g, '_');
  document.body.append(link);
  link.click();
  link.remove();
  // Revoking at once can abort the download in some browsers; a later revoke is harmless.
  setTimeout(() => URL.revokeObjectURL(url), DOWNLOAD_URL_LIFETIME_MS);
}

// ---------------------------------------------------------------------------------------------
// The worker and the design panel

const core = new CoreWorker({
  onStart() {
    coreReady = false;
    document.body.dataset.core = 'starting';
  },
  onReady(version) {
    coreReady = true;
    document.body.dataset.core = 'ready';
    ui.coreVersion.textContent = version;
    // A fresh worker has no design session: let the panel notice.
    designPanel?.refresh();
  },
  onCrash(text) {
    coreReady = false;
    showError(text);
    setStatus('error');
  },
});

let statusBeforeBusy = null;

/**
 * While the worker designs, loading another assembly would only queue behind the design: the
 * inputs that load are locked (Cancel is the way out) and the page keeps what it shows.
 */
function setBusy(busy, label) {
  for (const control of [ui.exampleSelect, ui.fileInput, ui.methodSelect]) control.disabled = busy;
  meshInput.setDisabled(busy);
  exportPanel.setDisabled(busy);
  if (busy) {
    statusBeforeBusy = { status: document.body.dataset.status, text: ui.statusText.textContent };
    setStatus('loading', label);
  } else if (statusBeforeBusy) {
    setStatus(statusBeforeBusy.status, statusBeforeBusy.text);
    statusBeforeBusy = null;
  }
}

const meshInput = createMeshInput({ core, loadAssembly });
const meshAssemblies = createMeshAssemblyInput({ core, loadAssembly, method: () => ui.methodSelect.value });
const exportPanel = createExportPanel({ core });

/**
 * Live design (issue 11): the deepest node of a running design, drawn over what is shown with the
 * user's camera kept. A voxel snapshot brings its labels and surfaces (parts 1..depth placed, the
 * remainder see-through); a plate or frame snapshot lists the input indices placed, and the input
 * on screen is recoloured: the rest see-through. The report stays the input's until the result.
 */
function showLiveDesign(snapshot) {
  if (!shown) return;
  if (snapshot.labels) {
    // The shape on screen with the node's labels, its surfaces made in the worker (the package's
    // liveSurfaces), merged into a few meshes (issue 28, item 8): a picture redrawn several times a second.
    const voxel = shown.document?.voxel;
    if (!voxel || !Array.isArray(snapshot.surfaces)) return;
    view.showLive({ ...shown.document, voxel: { ...voxel, labels: snapshot.labels } }, snapshot.surfaces, { ghost: [snapshot.depth + 1] });
    return;
  }
  if (!Array.isArray(snapshot.placed)) return;
  const items = shown.document?.plates ?? shown.document?.beams ?? [];
  const placed = new Set(snapshot.placed.map((index) => items[index]?.id));
  // The input's part surfaces merged as a voxel node's are (issue 28, item 8): one mesh per part,
  // recoloured at every picture, drew 882 beams with 882 draw calls, about a second of the page
  // per picture in software WebGL; merged, a picture is four draw calls.
  const ghost = items.map((item) => item.id).filter((id) => !placed.has(id));
  view.showLive(shown.document, shown.surfaces, { ghost });
}

/** A design that ended without a result: the assembly shown before it, as it was. */
function endLiveDesign() {
  if (shown) present({ ...shown, keepCamera: true });
}

const designPanel = createDesignPanel({
  core,
  getShape: () => designInput,
  showAssembly,
  setBusy,
  showLive: showLiveDesign,
  endLive: endLiveDesign,
});

// ---------------------------------------------------------------------------------------------
// Wiring

/** The label alone (the report names the file); the file name is the option's tooltip. */
function exampleOption({ file, label }) {
  const option = element('option', label);
  option.value = file;
  option.title = file;
  return option;
}

function fillExampleSelect() {
  const userOption = element('option', 'Your file');
  userOption.value = USER_FILE_OPTION;
  userOption.hidden = true;
  const resultOption = element('option', 'Designed');
  resultOption.value = RESULT_OPTION;
  resultOption.hidden = true;
  const puzzles = document.createElement('optgroup');
  puzzles.label = 'Puzzles';
  puzzles.append(...EXAMPLES.filter((example) => !example.shape && !example.plate && !example.frame).map(exampleOption));
  const shapes = document.createElement('optgroup');
  shapes.label = 'Shapes to design from';
  shapes.append(...EXAMPLES.filter((example) => example.shape).map(exampleOption));
  const meshes = document.createElement('optgroup');
  meshes.label = 'Meshes to voxelize';
  meshes.append(...meshInput.examples.map(exampleOption));
  const plates = document.createElement('optgroup');
  plates.label = 'Plate structures';
  plates.append(...EXAMPLES.filter((example) => example.plate).map(exampleOption));
  const frames = document.createElement('optgroup');
  frames.label = 'Frame structures';
  frames.append(...EXAMPLES.filter((example) => example.frame).map(exampleOption));
  ui.exampleSelect.replaceChildren(userOption, resultOption, puzzles, shapes, meshes, plates, frames);
}

function initialExample() {
  const requested = readUrlState().example;
  const known = EXAMPLES.some((example) => example.file === requested) || meshInput.isExample(requested);
  return known ? requested : DEFAULT_EXAMPLE;
}

function wireDragAndDrop() {
  let depth = 0; // dragenter/dragleave fire for every child element crossed.
  const carriesFiles = (event) => [...(event.dataTransfer?.types ?? [])].includes('Files');
  document.addEventListener('dragenter', (event) => {
    if (!carriesFiles(event) || designPanel.busy) return;
    event.preventDefault();
    depth += 1;
    ui.dropOverlay.hidden = false;
  });
  document.addEventListener('dragover', (event) => {
    if (carriesFiles(event)) event.preventDefault();
  });
  document.addEventListener('dragleave', () => {
    depth = Math.max(depth - 1, 0);
    if (depth === 0) ui.dropOverlay.hidden = true;
  });
  document.addEventListener('drop', (event) => {
    event.preventDefault();
    depth = 0;
    ui.dropOverlay.hidden = true;
    const files = [...(event.dataTransfer?.files ?? [])];
    if (files.length > 0 && !designPanel.busy) loadUserFiles(files);
  });
}

/** Checks the assembly on screen again with the chosen test (the design input stays what it was). */
function recheck() {
  if (!current) return;
  const { name, text } = current;
  if (meshAssemblies.shows(name)) return meshAssemblies.recheck();
  loadAssembly(name, async () => text, { asInput: designInput?.name === name && designInput?.text === text });
}

function wireControls() {
  ui.exampleSelect.addEventListener('change', () => {
    fitSelectToValue(ui.exampleSelect);
    if (ui.exampleSelect.value === RESULT_OPTION) {
      // Only listed while the result is on screen: nothing to load.
    } else if (ui.exampleSelect.value !== USER_FILE_OPTION) {
      writeUrlState({ example: ui.exampleSelect.value });
      loadExample(ui.exampleSelect.value);
    } else if (lastUserFile) {
      loadUserFiles([lastUserFile].flat());
    }
  });
  ui.fileInput.addEventListener('change', () => {
    const files = [...(ui.fileInput.files ?? [])];
    // Clear the input so picking the same file again still fires `change`.
    ui.fileInput.value = '';
    if (files.length > 0) loadUserFiles(files);
  });
  ui.methodSelect.addEventListener('change', recheck);
  // The graph test is not exact for this assembly (report.js says why): run the LP test on it.
  ui.methodNoteLp.addEventListener('click', () => {
    ui.methodSelect.value = 'lp';
    recheck();
  });
  ui.downloadButton.addEventListener('click', downloadCurrent);
}

// ---------------------------------------------------------------------------------------------
// The introduction (the first screen): what desia is and three steps, the next one marked.

const INTRO_HIDDEN_KEY = 'desia.intro.hidden';
/** Phones (the one-column layout of style.css) fold the Design settings: the verdict comes first. */
const PHONE_QUERY = '(max-width: 760px)';

/** An interlocking result is played or exported next; anything else (a shape, an input) designed. */
function markNextStep(report) {
  ui.intro.dataset.next = report?.verdict === 'interlocking' || report?.interlocking === true ? 'play' : 'design';
}

function wireIntro() {
  let hidden = false;
  try { hidden = localStorage.getItem(INTRO_HIDDEN_KEY) === '1'; } catch { /* storage refused: show it */ }
  ui.intro.hidden = hidden;
  ui.introClose.addEventListener('click', () => {
    ui.intro.hidden = true;
    try { localStorage.setItem(INTRO_HIDDEN_KEY, '1'); } catch { /* it shows again next time */ }
  });
  for (const step of ui.intro.querySelectorAll('.intro-step')) {
    step.addEventListener('click', () => {
      let target = byId(step.dataset.target);
      // Nothing to play yet (a shape, a design input): Design first; Play disabled: Export.
      if (target.disabled) target = step.dataset.target === 'disassembly-play' ? byId('export-link') : target;
      target.scrollIntoView({ block: 'center', behavior: 'smooth' });
      target.focus({ preventScroll: true });
      if (target.id === 'example-select') target.showPicker?.();
    });
  }
  if (window.matchMedia(PHONE_QUERY).matches) ui.designSettings.open = false;
}

function main() {
  wireIntro();
  fillExampleSelect();
  wireControls();
  wireDragAndDrop();
  setStatus('loading', 'Starting the core…');
  core.start().catch(() => {}); // failures are on screen (onCrash)
  const file = initialExample();
  ui.exampleSelect.value = file;
  registerServiceWorker();
  // Once the first assembly is on screen, keep the playground's files for offline use.
  loadExample(file, { keepJoints: readUrlState().joints !== undefined, first: true }).finally(() => {
    // Live design's shader programs, compiled while nothing else happens (issue 28, item 8).
    const whenIdle = window.requestIdleCallback ?? ((callback) => setTimeout(callback, 0));
    whenIdle(() => view.prepareLive().catch(() => {}));
  }).finally(() => keepForOffline([
    ...EXAMPLES.map((example) => exampleUrl(example.file).href),
    ...meshInput.exampleUrls,
  ]));
}

main();
