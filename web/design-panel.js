// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Design panel: designs an N-part interlocking voxel puzzle from the assembly on screen
// (all its voxels are the shape), automatically (designVoxel, with live progress; with several
// Workers the package's portfolio of seeds, designVoxel's jobs, the winner naming the result) or step by
// step (a design session); for a plate design it plans the joints (designPlate: seed,
// candidates, time limit; N, ranking and mode do not apply), for a frame it designs the 3x3x3
// voxel joints (designFrame: seed, candidates, time limit); plates and frames also step by step
// (a session whose children are steps: the part taken, its direction, its joints). Everything runs in the worker; the panel only collects parameters,
// shows progress and hands finished assemblies to the page. Cancel terminates the worker (a
// busy WebAssembly worker cannot read a message), so the page keeps what it showed before.
//
// For tests: body[data-design] = '' | running | success | not-found | limit-reached |
// cancelled | cut-point | error (the last outcome), #design-panel[data-kind] = voxel | plate | frame (what
// Design will do), #design-message (the core's message),
// #design-progress-box[data-updates] (progress messages seen in the current run),
// #design-progress-box[data-seed] (with several Workers: the seed of the deepest search),
// #session-state[data-parts, data-children, data-complete] (the open session's node),
// #design-input[data-name] (what Design designs from: the assembly the user loaded, not a result
// designed from it), .field-help[data-invalid] under each field (its one-line explanation, or
// what is wrong with the value typed; the field gets aria-invalid).
// #design-joints holds the joints an example needs once it is loaded (main.js EXAMPLES).
// Live design: #design-progress-box[data-live-parts] (parts of the deepest node the view shows,
// '' when none), #design-progress-difficulty (voxels per part against what usually succeeds).

import { byId } from './dom.js';
import { readUrlState, writeUrlState } from './url-state.js';
import { formatDirection } from './view.js';
import { createChildThumbnails } from './child-thumbnails.js';
import { createPaceTracker, difficultyText } from './live-design.js';

/** The fields of the form, by URL key; their values go to the core as they are. */
const FIELDS = {
  parts: byId('design-parts'),
  seed: byId('design-seed'),
  candidates: byId('design-candidates'),
  timeLimit: byId('design-time-limit'),
  rank: byId('design-rank'),
  mode: byId('design-mode'),
  workers: byId('design-workers'),
  joints: byId('design-joints'),
  clearance: byId('design-clearance'),
};
const NUMBER_FIELDS = ['parts', 'seed', 'candidates', 'timeLimit'];
/** The text fields whose value the page checks and explains (Workers stays in the page). */
const CHECKED_FIELDS = [...NUMBER_FIELDS, 'workers'];
const FIELD_NAMES = { parts: 'Parts N', seed: 'Seed', candidates: 'Candidates m', timeLimit: 'Time limit', clearance: 'Clearance', workers: 'Workers' };
/**
 * Voxel designs run as a portfolio of seeds on this many workers at most (issue 10): one per core
 * up to 4 (each worker holds its own WebAssembly memory). The Workers field starts there.
 */
const MAX_WORKERS = Math.max(1, Math.min(Number(navigator.hardwareConcurrency) || 1, 4));
/** A number as typed: what the text fields accept before the core checks the value. */
const NUMBER_PATTERN = /^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$/;
/**
 * The fewest parts an interlocking puzzle has (key, a part it frees, the rest): the core refuses
 * 1 and 2 with these words, and 0 with its generic range, so the page says the same for all three.
 */
const MIN_PARTS = 3;
const MIN_PARTS_REASON = `an interlocking puzzle needs at least ${MIN_PARTS} parts`;

/** The fields designPlate takes; the others are voxel-only and disabled for plates. */
const PLATE_FIELDS = ['seed', 'candidates', 'timeLimit', 'clearance'];
/** The fields designFrame takes. */
const FRAME_FIELDS = ['seed', 'candidates', 'timeLimit'];
/** The designers' default m (the Candidates field follows the kind until the user edits it). */
const DEFAULT_CANDIDATES = { voxel: '30', plate: '30', frame: '2' };
/** Per kind of structure: the worker operation, what a run is called, what its parts are. */
const STRUCTURES = {
  plate: { op: 'design-plate', label: 'Planning joints…', noun: 'plates joined', parts: 'plates', suffix: 'plan' },
  frame: { op: 'design-frame', label: 'Designing frame joints…', noun: 'beams placed', parts: 'beams', suffix: 'frame' },
};

const ui = {
  panel: byId('design-panel'),
  voxelHint: byId('design-hint'),
  plateHint: byId('design-plate-hint'),
  plateNote: byId('design-plate-note'),
  frameHint: byId('design-frame-hint'),
  frameNote: byId('design-frame-note'),
  sessionPlateNote: byId('session-plate-note'),
  voxelOnlyFields: [byId('design-parts-field'), byId('design-rank-field'), byId('design-mode-field'), byId('design-workers-field')],
  plateOnlyFields: [byId('design-joints-field'), byId('design-clearance-field')],
  form: byId('design-form'),
  designButton: byId('design-button'),
  cancelButton: byId('design-cancel'),
  progressBox: byId('design-progress-box'),
  progress: byId('design-progress'),
  progressText: byId('design-progress-text'),
  message: byId('design-message'),
  sessionStart: byId('session-start'),
  sessionNext: byId('session-next'),
  sessionBack: byId('session-back'),
  sessionClose: byId('session-close'),
  sessionChild: byId('session-child'),
  sessionPreview: byId('session-preview'),
  sessionChoose: byId('session-choose'),
  sessionState: byId('session-state'),
  sessionFinish: byId('session-finish'),
  sessionChildren: byId('session-children'),
  input: byId('design-input'),
  difficulty: byId('design-difficulty'),
};

/** How often the elapsed time moves while the core is busy between progress messages. */
const CLOCK_INTERVAL_MS = 100;
/** Live design: the view draws the deepest node at most this often (the package's liveSurfaces sends as often). */
const LIVE_INTERVAL_MS = 250;
/**
 * ... and leaves the page at least this share of the time between two drawings (issue 28, item 8):
 * a drawing that took 200 ms (software WebGL with the workers on every core) waits 1 s for the
 * next; on a GPU a drawing takes a few ms and the interval above rules.
 */
const LIVE_FREE_SHARE = 0.8;
/**
 * ... but draws at least once a second: a design of a few seconds still shows its parts growing,
 * and one slow picture (the first compiles the live drawing's shader programs) does not stall it.
 */
const LIVE_MAX_INTERVAL_MS = 1000;

/**
 * A reasonable N for a shape of `voxels` voxels: about a dozen voxels per part (80 parts at
 * most, like the largest published puzzle), 7 for small shapes, never more than the core allows
 * (two voxels per part). Only a starting value: the user's N always wins.
 */
export function defaultParts(voxels) {
  let parts = Math.max(Math.round(voxels / 12), 7);
  parts = Math.min(parts, Math.floor(voxels / 2), 80);
  return Math.max(parts, 3);
}

/** 'Cube_4x4x4_origin.puz' -> 'Cube_4x4x4'; names of earlier designs lose their suffix too. */
function baseName(name) {
  return name.replace(/\.[^.]*$/, '').replace(/_N\d+_seed\d+$/, '').replace(/_(plan|frame)_seed\d+$/, '').replace(/_step\d+of\d+(_child\d+)?$/, '').replace(/_origin$/, '');
}

function seconds(ms) {
  return `${(ms / 1000).toFixed(1)} s`;
}

/**
 * Wires the panel. `core` is the page's CoreWorker; `getShape()` returns `{ name, text }` of the
 * assembly on screen or null; `showAssembly({ name, text, document, surfaces, report, elapsedMs,
 * timingLabel })` puts an assembly on screen; `setBusy(busy, label)` locks the page's other
 * inputs while the worker is busy for us. Live design: `showLive(snapshot, kind)` draws the deepest
 * node so far (the package's liveSurfaces, wasm/host.js) and `endLive()` puts back what was shown before, when a
 * run ends without a result to show.
 */
export function createDesignPanel({ core, getShape, showAssembly, setBusy, showLive = () => {}, endLive = () => {} }) {
  let busy = false;
  let partsTouched = false;
  /** The open step-by-step session: { generation, base, snapshot }, or null. */
  let session = null;
  /** The latest run (design or session step): { started, latest, updates, clock, withProgress, noun }. */
  let run = null;
  /** The kind of assembly on screen: 'plate' and 'frame' design joints, anything else voxels. */
  let kind = 'voxel';
  /** True while the Joints choice is one an example set (not the user's): another file resets it. */
  let jointsFromExample = false;
  /** Voxels of the voxel shape on screen (for the difficulty line), or 0. */
  let inputVoxels = 0;

  // -------------------------------------------------------------------------------------------
  // Parameters

  function prefillFromUrl() {
    const state = readUrlState();
    for (const [key, field] of Object.entries(FIELDS)) {
      if (state[key] === undefined) continue;
      if (field instanceof HTMLSelectElement && ![...field.options].some((option) => option.value === state[key])) continue;
      field.value = state[key];
    }
    // A shared link's N is deliberate: do not replace it with the shape's default.
    if (state.parts !== undefined) partsTouched = true;
  }

  function syncUrl() {
    const changes = {};
    // Workers is this machine's setting, not the design's: links leave it out.
    for (const [key, field] of Object.entries(FIELDS)) if (key !== 'workers') changes[key] = field.value;
    writeUrlState(changes);
  }

  /**
   * The options for the core. Empty fields are left out (the core's defaults apply; a missing N
   * gets the core's message). Only what the browser cannot hand over is caught here: text in a
   * number field, which the field reports as empty.
   */
  function readOptions() {
    const options = {};
    const keys = kind === 'plate' ? PLATE_FIELDS : kind === 'frame' ? FRAME_FIELDS : NUMBER_FIELDS;
    for (const key of keys) {
      const field = FIELDS[key];
      if (field.validity.badInput) throw fieldError(key, `${FIELD_NAMES[key]}: not a number`);
      const problem = fieldProblem(key);
      if (problem) throw fieldError(key, problem);
      if (field.value.trim() !== '') options[key] = Number(field.value);
    }
    if (kind === 'frame') return options;
    if (kind === 'plate') {
      options.joints = FIELDS.joints.value;
      // A clearance is cut into the files to make; planned joints have none to cut.
      if (options.joints === 'planned' || options.clearance === 0) delete options.clearance;
      return options;
    }
    options.rank = FIELDS.rank.value;
    options.mode = FIELDS.mode.value;
    options.jobs = readWorkers();
    return options;
  }

  /** The Workers field: searches at once, at most MAX_WORKERS (an empty field: one). */
  function readWorkers() {
    const problem = fieldProblem('workers');
    if (problem) throw fieldError('workers', problem);
    const raw = FIELDS.workers.value.trim();
    return raw === '' ? 1 : Math.min(Number(raw), MAX_WORKERS);
  }

  /** What is wrong with the text of a number field ('' when nothing the page can tell). */
  function fieldProblem(key) {
    const raw = FIELDS[key].value.trim();
    if (raw === '' || FIELDS[key].type !== 'text') return '';
    if (!NUMBER_PATTERN.test(raw)) return `${FIELD_NAMES[key]}: "${raw}" is not a number`;
    const value = Number(raw);
    // The core's own words for 1 and 2 (it answers 0 with its generic range).
    if (key === 'parts' && Number.isInteger(value) && value < MIN_PARTS) return `parts = ${value}: ${MIN_PARTS_REASON}`;
    if (key === 'workers' && !(Number.isInteger(value) && value >= 1)) return `Workers: "${raw}" is not a whole number from 1`;
    return '';
  }

  function fieldError(key, message) {
    const error = new Error(message);
    error.field = key;
    return error;
  }

  /** The help line under a field: its explanation, or what is wrong with the value typed. */
  function helpOf(key) {
    return FIELDS[key].parentElement.querySelector('.field-help');
  }

  function explain(key) {
    const help = helpOf(key);
    if (!help) return;
    const raw = FIELDS[key].value.trim();
    let text = help.dataset.default ?? help.textContent;
    if (key === 'timeLimit') {
      // The core: seconds, 0 = no limit for voxels and frames; whole seconds from 1 for plates.
      if (kind === 'plate') text = 'whole seconds, 1 or more';
      else if (raw !== '' && NUMBER_PATTERN.test(raw) && Number(raw) === 0) text = '0 = no limit: runs until done or Cancel';
    }
    const problem = fieldProblem(key);
    markInvalid(key, problem !== '');
    help.textContent = problem ? problem.replace(/^[^:]*: /, '') : text;
  }

  function markInvalid(key, invalid) {
    const help = helpOf(key);
    if (invalid) FIELDS[key].setAttribute('aria-invalid', 'true');
    else FIELDS[key].removeAttribute('aria-invalid');
    if (help) help.dataset.invalid = String(invalid);
  }

  /** A message of the core about one option ("design option 'seed' ...", "parts = 40 ...") marks that field. */
  function markFieldOf(message) {
    for (const key of Object.keys(FIELDS)) {
      if (message.includes(`'${key}'`) || message.startsWith(`${key} =`)) {
        markInvalid(key, true);
        return;
      }
    }
  }

  function explainAll() {
    for (const key of CHECKED_FIELDS) explain(key);
  }

  // -------------------------------------------------------------------------------------------
  // Busy state, progress and messages

  function setOutcome(outcome, message) {
    document.body.dataset.design = outcome;
    ui.message.dataset.outcome = outcome;
    ui.message.textContent = message ?? '';
    ui.message.hidden = !message;
  }

  function begin(label, { withProgress, noun = 'parts placed' }) {
    busy = true;
    setBusy(true, label);
    document.body.dataset.design = 'running';
    ui.message.hidden = true;
    run = { started: performance.now(), latest: null, updates: 0, clock: 0, withProgress, noun, pace: createPaceTracker(), live: false };
    ui.progressBox.dataset.liveParts = '';
    if (withProgress) {
      ui.progressBox.hidden = false;
      ui.progressBox.dataset.updates = '0';
      ui.progress.max = 1;
      ui.progress.value = 0;
      run.clock = setInterval(renderProgress, CLOCK_INTERVAL_MS);
      renderProgress();
    }
    refreshControls();
  }

  /** Ends the run; returns its wall-clock time in ms. */
  function end() {
    const elapsed = performance.now() - run.started;
    clearInterval(run.clock);
    run.ended = true;
    // A run that failed before its first node has no progress worth keeping on screen.
    if (run.withProgress && run.latest) renderProgress();
    else ui.progressBox.hidden = true;
    busy = false;
    setBusy(false);
    refreshControls();
    return elapsed;
  }

  /** A run that drew live snapshots and has no result to show: the view goes back to its input. */
  function endLiveView() {
    if (!run?.live) return;
    run.live = false;
    ui.progressBox.dataset.liveParts = '';
    endLive();
  }

  function onProgress(value) {
    if (!run) return;
    run.latest = value;
    run.updates += 1;
    ui.progressBox.dataset.updates = String(run.updates);
    // A portfolio's progress is its deepest search's (nodes: all of them); which seed that is.
    ui.progressBox.dataset.seed = value.seed === undefined ? '' : String(value.seed);
    run.pace.observe(value);
    if (value.snapshot) offerLiveSnapshot(value.snapshot);
    else if (run.pendingLive) offerLiveSnapshot(run.pendingLive);
    renderProgress();
  }

  /**
   * Live design: draws a snapshot deeper than the one shown (with several Workers they come from
   * whichever search is deepest), at most every LIVE_INTERVAL_MS, and rarer (down to once a
   * second) when a drawing costs the page more than a fifth of that (LIVE_FREE_SHARE), so that
   * redraws leave the page responsive; one that comes sooner waits for the next progress.
   */
  function offerLiveSnapshot(snapshot) {
    const shownDepth = Number(ui.progressBox.dataset.liveParts || -1);
    if (!(snapshot.depth > shownDepth)) return;
    const interval = Math.min(LIVE_MAX_INTERVAL_MS, Math.max(LIVE_INTERVAL_MS, (run.liveCost ?? 0) / (1 - LIVE_FREE_SHARE)));
    if (performance.now() - (run.liveAt ?? -Infinity) < interval) {
      run.pendingLive = snapshot;
      return;
    }
    run.pendingLive = null;
    run.liveAt = performance.now();
    drawLiveOnNextFrame(snapshot);
  }

  /**
   * The view changes on an animation frame (issue 28, item 8): snapshots that arrive within one
   * frame (several workers) draw only the deepest, and a run that ended before draws nothing.
   */
  function drawLiveOnNextFrame(snapshot) {
    const current = run;
    if (current.liveSnapshot && !(snapshot.depth > current.liveSnapshot.depth)) return;
    current.liveSnapshot = snapshot;
    current.liveFrame ||= requestAnimationFrame(() => {
      current.liveFrame = 0;
      const latest = current.liveSnapshot;
      if (run !== current || current.ended || !latest) return;
      current.live = true;
      ui.progressBox.dataset.liveParts = String(latest.depth);
      const drawnAt = performance.now();
      showLive(latest, kind);
      // What the drawing cost the page: until the frame after the view's could start (the view
      // renders on the next frame, and the browser presents that before the one after).
      // The first picture of a run may still compile its shader programs: it does not count.
      const first = !current.pictures;
      current.pictures = (current.pictures ?? 0) + 1;
      requestAnimationFrame(() => requestAnimationFrame(() => {
        if (!first) current.liveCost = performance.now() - drawnAt;
        current.liveAt = performance.now();
      }));
    });
  }

  /**
   * Before Design: how hard the request is (voxels per part, live-design.js), for a voxel shape
   * and a whole N; the same line the progress shows while it runs. Hidden otherwise.
   */
  function renderDifficulty() {
    const parts = Number(FIELDS.parts.value.trim());
    const text = kind === 'voxel' && inputVoxels > 0 && Number.isInteger(parts) && parts >= MIN_PARTS
      ? difficultyText(inputVoxels, parts) : '';
    ui.difficulty.textContent = text ? `N = ${parts}: ${text}` : '';
    ui.difficulty.hidden = !text;
  }

  /** The line under the progress with the difficulty and the time left (made here: no markup to change). */
  function progressHint() {
    let hint = document.getElementById('design-progress-difficulty');
    if (!hint) {
      hint = document.createElement('p');
      hint.id = 'design-progress-difficulty';
      hint.className = 'progress-text';
      ui.progressText.after(hint);
    }
    return hint;
  }

  /** The difficulty of the request and the time left, when they can be told (live-design.js). */
  function progressDetails(latest) {
    const voxel = !STRUCTURES[kind];
    // bestDepth counts the parts of the deepest node, the remainder included: targetParts at the end.
    const estimate = run.ended ? '' : run.pace.estimate(latest);
    const difficulty = voxel && inputVoxels > 0 ? difficultyText(inputVoxels, latest.targetParts) : '';
    return [difficulty, estimate].filter(Boolean);
  }

  /** Parts placed (plates joined) of N (the deepest node so far), nodes, current depth, wall-clock time. */
  function renderProgress() {
    const elapsed = seconds(performance.now() - run.started);
    const latest = run.latest;
    if (!latest) {
      ui.progressText.textContent = `Starting… ${elapsed}`;
      return;
    }
    ui.progress.max = latest.targetParts;
    ui.progress.value = latest.bestDepth;
    ui.progressText.textContent = `${latest.bestDepth} of ${latest.targetParts} ${run.noun} · `
      + `${latest.nodesVisited} nodes visited · depth ${latest.depth} · ${elapsed}`;
    progressHint().textContent = progressDetails(latest).join(' · ');
  }

  function cancel() {
    if (!busy) return;
    // Rejects the pending request with a CancelledError, handled where it was sent.
    core.cancel();
  }

  // -------------------------------------------------------------------------------------------
  // Automatic design

  /** The current shape and the form's options, or null (with the reason on screen). */
  function readRequest() {
    const shape = getShape();
    if (!shape) {
      setOutcome('error', 'Load a voxel shape, a plate design or a frame first (an example, your own .puz / .json / .fpuz, or a mesh to voxelize).');
      return null;
    }
    try {
      return { shape, options: readOptions() };
    } catch (error) {
      setOutcome('error', error.message);
      if (error.field) {
        // A phone folds the settings: the field named by the message is shown before it is focused.
        const settings = FIELDS[error.field].closest('details');
        if (settings) settings.open = true;
        FIELDS[error.field].focus();
      }
      return null;
    }
  }

  /**
   * Runs one automatic design in the worker: the voxel designer, or for a plate design the joint
   * planner (designPlate), whose plan is shown with its plates (plate 1 the key), verification,
   * joints and planned removal. A cut point or a failed search shows the core's message.
   */
  async function design() {
    if (busy) return;
    const request = readRequest();
    if (!request) return;
    const { shape, options } = request;
    const structure = STRUCTURES[kind] ?? null;
    syncUrl();
    begin(structure ? structure.label : 'Designing…', { withProgress: true, ...(structure ? { noun: structure.noun } : {}) });
    try {
      const operation = structure ? structure.op : 'design';
      const coreOptions = { ...options, source: shape.name };
      // Several workers: the package's portfolio (designVoxel's jobs), the page's core left alone.
      const { value: result, elapsedMs } = await core.run(operation, shape.text, coreOptions, { onProgress });
      if (structure) {
        // The result's progress is the final count (a finished plan has every plate joined); a cut
        // point is found before any search, so there is no progress to show.
        if (result.progress) run.latest = { depth: 0, ...run.latest, ...result.progress };
        if (result.status === 'cut-point') run.latest = null;
      }
      end();
      if (!(result.status === 'success' && result.document)) endLiveView();
      if (result.status === 'success' && result.document) {
        showAssembly({
          name: structure
            ? `${baseName(shape.name)}_${structure.suffix}_seed${options.seed ?? 1}.json`
            : `${baseName(shape.name)}_N${result.progress.targetParts}_seed${result.seed ?? options.seed ?? 1}.puz`,
          text: structure ? `${JSON.stringify(result.document, null, 2)}\n` : result.puz,
          document: result.document,
          surfaces: result.surfaces,
          report: result.verification,
          elapsedMs,
          timingLabel: 'Design time',
        });
      }
      // The core's message says what was found, or how far the search got.
      setOutcome(result.status, result.message);
    } catch (error) {
      const elapsed = end();
      endLiveView();
      if (error.cancelled) setOutcome('cancelled', cancelledMessage(run.latest, elapsed, structure ? structure.parts : 'parts'));
      else {
        setOutcome('error', error.message);
        markFieldOf(error.message);
      }
    }
  }

  function cancelledMessage(latest, elapsed, noun = 'parts') {
    if (!latest) return `Cancelled after ${seconds(elapsed)}, before the first node.`;
    return `Cancelled after ${seconds(elapsed)}: the deepest node had ${latest.bestDepth} of `
      + `${latest.targetParts} ${noun} (${latest.nodesVisited} nodes visited).`;
  }

  // -------------------------------------------------------------------------------------------
  // Step by step
  //
  // The camera is framed once, when the session starts; every step, preview and finish after that
  // keeps the user's camera (double-click the view to frame again), so children compare at one
  // zoom. In the view the newest part glows and the remainder still to split is see-through.

  /** Thumbnails of the ranked children shown at most (each one is a preview in the worker). */
  const MAX_CHILD_THUMBNAILS = 6;
  const thumbnails = createChildThumbnails(ui.sessionChildren, {
    onPreview: (n) => { ui.sessionChild.value = String(n); preview(); },
    onChoose: (n) => step('session-choose', { n }),
  });
  /** Counts the nodes shown, so thumbnails of a node already left are dropped. */
  let nodeToken = 0;

  /** A session lives in one worker: after a crash or a cancel it is gone. */
  function sessionAlive() {
    if (session && session.generation !== core.generation) session = null;
    return session !== null;
  }

  /**
   * Sends one session operation; resolves with `{ value, elapsedMs }`, or null when it failed
   * (the message is on screen then).
   */
  async function sessionCall(op, text, options, label) {
    if (busy) return null;
    begin(label, { withProgress: false });
    try {
      const answer = await core.run(op, text, options);
      end();
      return answer;
    } catch (error) {
      end();
      if (error.cancelled) {
        session = null;
        setOutcome('cancelled', 'Cancelled; the step-by-step session ended with its worker.');
      } else {
        setOutcome('error', error.message);
      }
      refreshControls();
      return null;
    }
  }

  async function startSession() {
    if (kind !== 'voxel' && kind !== 'plate' && kind !== 'frame') return;
    const request = readRequest();
    if (!request) return;
    const { shape, options } = request;
    delete options.timeLimit; // A session makes one step per click: no search to limit.
    delete options.jobs; // One session, in the page's worker.
    syncUrl();
    const generation = core.generation;
    const answer = await sessionCall('session-open', shape.text, { ...options, source: shape.name }, 'Starting the session…');
    if (!answer) return;
    session = { generation, base: baseName(shape.name), snapshot: answer.value };
    showSnapshot(answer.elapsedMs, { keepCamera: false });
    setOutcome('', '');
  }

  async function step(op, options = {}) {
    if (!sessionAlive()) return refreshControls();
    const answer = await sessionCall(op, '', options, 'Working on the session…');
    if (!answer || !sessionAlive()) return;
    session.snapshot = answer.value;
    showSnapshot(answer.elapsedMs);
    if (answer.value.moved === false) {
      setOutcome('not-found', op === 'session-next'
        ? 'This step has no children: go back and choose another, or finish automatically (from the step before).'
        : 'Already at the first step.');
    } else {
      setOutcome('', '');
    }
  }

  async function preview() {
    if (!sessionAlive()) return refreshControls();
    const n = Number(ui.sessionChild.value);
    const answer = await sessionCall('session-preview', '', { n }, 'Previewing…');
    if (!answer) return;
    if (answer.value.step) {
      // A plate or frame session's child is a step (which plate or beam leaves, along what, with
      // which joints): the view keeps the design; the step is said in words.
      setOutcome('', `Child ${answer.value.index}: ${describeStep(answer.value.step)}. Choose it to continue from there.`);
      return;
    }
    const { index, document: document_, surfaces, report } = answer.value;
    const { partsPlaced, targetParts } = session.snapshot;
    // The child's new part is part partsPlaced; the remainder it leaves is the part after it.
    showSessionAssembly(`${session.base}_step${partsPlaced}of${targetParts}_child${index}`, document_, surfaces, report, answer.elapsedMs,
      { emphasis: stepEmphasis(partsPlaced + 1, targetParts), progress: { placed: partsPlaced + 1, target: targetParts } });
    thumbnails.markSelected(index);
    setOutcome('', `Preview of child ${index}: choose it to continue from there.`);
  }

  async function closeSession() {
    if (sessionAlive()) await sessionCall('session-close', '', {}, 'Closing the session…');
    session = null;
    refreshControls();
  }

  function showSnapshot(elapsedMs, { keepCamera = true } = {}) {
    const { partsPlaced, targetParts, document: document_, surfaces, report, steps } = session.snapshot;
    showSessionAssembly(`${session.base}_step${partsPlaced}of${targetParts}`, document_, surfaces, report, elapsedMs,
      { keepCamera, emphasis: steps ? null : stepEmphasis(partsPlaced, targetParts), progress: { placed: partsPlaced, target: targetParts } });
    ui.sessionChild.value = '0';
    refreshControls();
    loadThumbnails();
  }

  /**
   * A voxel assembly of `parts` parts on the way to `targetParts`: its newest part (parts - 1)
   * highlighted and its remainder (the last part) ghosted; nothing at the root (the whole shape is
   * the remainder) nor once complete (the last part is a part then).
   */
  function stepEmphasis(parts, targetParts) {
    if (parts < 2 || parts >= targetParts) return null;
    return { highlight: [parts - 1], ghost: [parts] };
  }

  /** Session assemblies have no .puz text from the core: the page keeps them as JSON documents. */
  function showSessionAssembly(name, document_, surfaces, report, elapsedMs, { keepCamera = true, emphasis = null, progress = null } = {}) {
    const plain = document_.voxel ? { ...document_, voxel: { ...document_.voxel, labels: Array.from(document_.voxel.labels) } } : document_;
    showAssembly({
      name: `${name}.json`, text: JSON.stringify(plain), document: document_, surfaces, report, elapsedMs, timingLabel: 'Step time', menuLabel: `Step by step: ${name}`,
      keepCamera, emphasis,
      // A step short of the target is a design in progress, not a failed puzzle (report.js).
      inProgress: progress && progress.placed < progress.target ? progress : null,
    });
  }

  /** Pictures of the current node's first ranked children (voxel sessions), made in the worker. */
  async function loadThumbnails() {
    const token = ++nodeToken;
    thumbnails.clear();
    if (!sessionAlive() || session.snapshot.steps || session.snapshot.childCount === 0) return;
    const { partsPlaced, targetParts } = session.snapshot;
    try {
      const { value: children } = await core.run('session-children', '', { count: MAX_CHILD_THUMBNAILS });
      if (token !== nodeToken || !sessionAlive()) return;
      const emphasis = stepEmphasis(partsPlaced + 1, targetParts);
      thumbnails.show(children, { newPart: partsPlaced, remainder: emphasis ? partsPlaced + 1 : null });
    } catch {
      // Pictures are a convenience: a failure (a cancelled worker) leaves the list and buttons.
    }
  }

  /**
   * "Finish automatically from here": the designer's search below the session's node, in the
   * worker with progress and Cancel (which ends the session with its worker). A success is the
   * verified puzzle, shown like any design; the session stays where it was.
   */
  async function finishFromHere() {
    if (busy || !sessionAlive()) return;
    const request = readRequest();
    if (!request) return;
    const timeLimit = request.options.timeLimit ?? 0;
    // A dead end has nothing below it to search: finish from the step before instead.
    if (session.snapshot.childCount === 0 && !session.snapshot.complete && session.snapshot.partsPlaced > 1) {
      await step('session-back');
      if (!sessionAlive()) return;
    }
    const { partsPlaced, targetParts } = session.snapshot;
    const base = session.base;
    begin('Finishing from here…', { withProgress: true });
    try {
      const { value: result, elapsedMs } = await core.run('session-finish', '', { timeLimit }, { onProgress });
      end();
      if (result.status === 'success' && result.puz) {
        showAssembly({
          name: `${base}_N${targetParts}_seed${result.seed}_from_step${partsPlaced}.puz`,
          text: result.puz, document: result.document, surfaces: result.surfaces, report: result.verification,
          elapsedMs, timingLabel: 'Design time', keepCamera: true,
        });
      } else if (result.status === 'success' && result.document) {
        // A plate or frame session: the verified design (designPlate's or designFrame's result),
        // the plates or beams taken so far first.
        showAssembly({
          name: `${base}_${STRUCTURES[kind]?.suffix ?? 'result'}_seed${request.options.seed ?? 1}_from_step${partsPlaced}.json`,
          text: `${JSON.stringify(result.document, null, 2)}\n`, document: result.document, surfaces: result.surfaces,
          report: result.verification, elapsedMs, timingLabel: 'Design time', keepCamera: true,
        });
      }
      setOutcome(result.status, result.message);
    } catch (error) {
      const elapsed = end();
      if (error.cancelled) {
        session = null;
        thumbnails.clear();
        setOutcome('cancelled', `${cancelledMessage(run.latest, elapsed)} The step-by-step session ended with its worker.`);
      } else {
        setOutcome('error', error.message);
      }
      refreshControls();
    }
  }

  /**
   * 'plate 3 leaves along +x (2 mortise-tenon joints, 1 empty)', or for a frame 'beam 4 leaves
   * along +y (free voxels taken: 2 at joint 1, 0 at joint 5)'
   */
  function describeStep(step) {
    if (typeof step.beam === 'number') {
      const voxels = step.joints.map((joint) => `${joint.voxels.length} at joint ${joint.joint}`).join(', ');
      return `beam ${step.beam} leaves along ${formatDirection(step.direction)} (free voxels taken: ${voxels})`;
    }
    const counts = new Map();
    for (const joint of step.joints) counts.set(joint.type, (counts.get(joint.type) ?? 0) + 1);
    const joints = [...counts].map(([type, count]) => `${count} ${type}`).join(', ');
    return `plate ${step.plate} leaves along ${formatDirection(step.direction)}${joints ? ` (${joints} joints)` : ''}`;
  }

  function describeSession() {
    if (!session) return 'No session.';
    const { partsPlaced, targetParts, complete, childCount, steps } = session.snapshot;
    const noun = !steps ? 'parts' : kind === 'frame' ? 'beams' : 'plates';
    if (complete) return `Complete: ${partsPlaced} of ${targetParts} ${noun}${steps ? ', verified' : ''}.`;
    const children = childCount === 0 ? (steps ? 'no children (go back)' : 'no children (go back, or finish automatically)') : `${childCount} children (0 = best ranked)`;
    const taken = steps?.length ? ` · taken: ${steps.map((step) => `${step.plate ?? step.beam} ${formatDirection(step.direction)}`).join(', ')}` : '';
    return `${partsPlaced} of ${targetParts} ${noun} (the last is the remainder)${taken} · ${children}.`;
  }

  // -------------------------------------------------------------------------------------------
  // Controls

  function refreshControls() {
    const alive = sessionAlive();
    const childCount = alive ? session.snapshot.childCount : 0;
    const plate = kind === 'plate';
    const frame = kind === 'frame';
    const structure = plate || frame;
    ui.panel.dataset.kind = kind;
    ui.panel.setAttribute('aria-label', plate ? 'Plan the joints of a plate design' : frame ? 'Design the joints of a frame' : 'Design a voxel puzzle');
    ui.voxelHint.hidden = structure;
    ui.plateHint.hidden = !plate;
    ui.plateNote.hidden = !plate;
    ui.frameHint.hidden = !frame;
    ui.frameNote.hidden = !frame;
    ui.sessionPlateNote.hidden = !frame;
    for (const field of ui.voxelOnlyFields) {
      field.hidden = structure;
      field.querySelector('input, select').disabled = structure;
    }
    for (const field of ui.plateOnlyFields) {
      field.hidden = !plate;
      field.querySelector('input, select').disabled = !plate;
    }
    ui.designButton.disabled = busy;
    ui.cancelButton.disabled = !busy;
    ui.sessionStart.disabled = busy;
    ui.sessionStart.textContent = alive ? 'Restart' : 'Start';
    ui.sessionNext.disabled = busy || !alive || childCount === 0;
    ui.sessionBack.disabled = busy || !alive || session.snapshot.partsPlaced <= 1;
    ui.sessionClose.disabled = busy || !alive;
    ui.sessionChild.disabled = busy || !alive || childCount === 0;
    ui.sessionChild.max = String(Math.max(childCount - 1, 0));
    ui.sessionPreview.disabled = ui.sessionChild.disabled;
    ui.sessionChoose.disabled = ui.sessionChild.disabled;
    ui.sessionFinish.disabled = busy || !alive || session.snapshot.complete;
    ui.sessionChildren.inert = busy;
    if (!alive && ui.sessionChildren.dataset.count !== '0') thumbnails.clear();
    ui.sessionState.textContent = describeSession();
    ui.sessionState.dataset.parts = alive ? String(session.snapshot.partsPlaced) : '';
    ui.sessionState.dataset.children = String(childCount);
    ui.sessionState.dataset.complete = String(alive && session.snapshot.complete);
    explain('timeLimit');
  }

  function wire() {
    ui.form.addEventListener('submit', (event) => {
      event.preventDefault();
      design();
    });
    ui.cancelButton.addEventListener('click', cancel);
    FIELDS.parts.addEventListener('input', () => { partsTouched = true; renderDifficulty(); });
    for (const key of CHECKED_FIELDS) FIELDS[key].addEventListener('input', () => explain(key));
    FIELDS.joints.addEventListener('change', () => { jointsFromExample = false; });
    ui.form.addEventListener('input', syncUrl);
    ui.form.addEventListener('change', syncUrl);
    ui.sessionStart.addEventListener('click', startSession);
    ui.sessionNext.addEventListener('click', () => step('session-next'));
    ui.sessionBack.addEventListener('click', () => step('session-back'));
    ui.sessionChoose.addEventListener('click', () => step('session-choose', { n: Number(ui.sessionChild.value) }));
    ui.sessionPreview.addEventListener('click', preview);
    ui.sessionClose.addEventListener('click', closeSession);
    ui.sessionFinish.addEventListener('click', finishFromHere);
  }

  FIELDS.workers.value = String(MAX_WORKERS);
  helpOf('workers').dataset.default = `seeds tried at once (at most ${MAX_WORKERS} here); the first puzzle wins`;
  prefillFromUrl();
  wire();
  refreshControls();
  explainAll();

  // Shown while a mesh assembly is on screen (setMeshAssembly), above the input line.
  const meshNote = document.createElement('p');
  meshNote.id = 'design-mesh-note';
  meshNote.className = 'design-input design-mesh-note';
  meshNote.setAttribute('role', 'note');
  meshNote.hidden = true;
  ui.input.before(meshNote);

  return {
    get busy() {
      return busy;
    },
    /**
     * The assembly on screen is of `kind` ('voxel', 'plate', 'frame', ...): plates get the joint
     * planner, frames the frame designer (neither has N, ranking, mode or step by step). A voxel
     * session stays open across plate and frame views. Candidates m follows the designer's
     * default while it holds the previous kind's default.
     */
    setKind(next) {
      const resolved = next === 'plate' || next === 'frame' ? next : 'voxel';
      if (resolved === kind) return;
      if (FIELDS.candidates.value === DEFAULT_CANDIDATES[kind]) FIELDS.candidates.value = DEFAULT_CANDIDATES[resolved];
      kind = resolved;
      refreshControls();
      renderDifficulty();
    },
    /**
     * An example that needs its own joints ('milled': the Bookshelf's dovetails; 'planned': the
     * mitred and flush designs) was loaded: Joints is set to them. null (an example without, or
     * the user's own file): Joints goes back to 'auto' if an example had set it; the user's own
     * choice stays. `timeLimit` (seconds): the least time limit the example needs.
     */
    setExampleJoints(joints, timeLimit = null) {
      // An example that needs longer than the default limit (the LIZARD's milled joints: about
      // 35 s in WebAssembly) raises it; a limit the user set higher stays.
      if (timeLimit && Number(FIELDS.timeLimit.value) < timeLimit) {
        FIELDS.timeLimit.value = String(timeLimit);
        syncUrl();
      }
      if (joints && [...FIELDS.joints.options].some((option) => option.value === joints)) {
        FIELDS.joints.value = joints;
        jointsFromExample = true;
      } else if (jointsFromExample) {
        FIELDS.joints.value = 'auto';
        jointsFromExample = false;
      } else {
        return;
      }
      syncUrl();
    },
    /** A new shape is on screen: N follows its size until the user sets N. */
    shapeLoaded(voxelCount) {
      inputVoxels = voxelCount > 0 ? voxelCount : 0;
      if (partsTouched || !(voxelCount > 0)) {
        renderDifficulty();
        return;
      }
      FIELDS.parts.value = String(defaultParts(voxelCount));
      explain('parts');
      syncUrl();
      renderDifficulty();
    },
    /**
     * The user chose another input (example, file, mesh): the last run's message and progress
     * are about the previous one, and N follows the new shape again (`keepParts`: a shared link's
     * first load keeps its N).
     */
    inputChanged({ keepParts = false } = {}) {
      if (busy) return;
      setOutcome('', '');
      ui.progressBox.hidden = true;
      ui.progressBox.dataset.updates = '0';
      ui.progress.value = 0;
      ui.progressText.textContent = '';
      progressHint().textContent = '';
      if (!keepParts) partsTouched = false;
      for (const key of Object.keys(FIELDS)) markInvalid(key, false);
      explainAll();
    },
    /**
     * A mesh assembly is on screen (`name`), or none (null): it is checked, not designed, so the
     * panel says so in plain words; Design still works from its input (the last one loaded).
     */
    setMeshAssembly(name) {
      meshNote.hidden = !name;
      meshNote.dataset.name = name ?? '';
      meshNote.textContent = !name ? ''
        : `${name} is a mesh assembly: desia checks it (verdict, key, disassembly) but does not design from it. `
          + (ui.input.hidden ? 'To design, load a voxel shape, a plate design or a frame (an example, a file, or one mesh to voxelize).'
            : 'Design below still works from the input it names.');
    },
    /** What Design designs from (`input` = { name }, or null), described as 'name · 64 voxels'. */
    setInput(input, description) {
      ui.input.hidden = !input;
      ui.input.dataset.name = input?.name ?? '';
      ui.input.textContent = input ? `Input: ${input.name} · ${description}` : '';
    },
    /** The worker was replaced (crash or cancel): forget what lived in the old one. */
    refresh: refreshControls,
  };
}
