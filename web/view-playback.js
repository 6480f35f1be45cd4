// SPDX-License-Identifier: GPL-3.0-or-later
//
// Playback of the disassembly in the 3D view (view.js): DisassemblyPlayer (the play/pause clock
// of the disassembly step), describeDisassemblyStep (what the step shown is, in words), and
// createPlaybackControls (wires a slider, a play button, previous / next, a speed select, a loop
// checkbox and an explode slider to an AssemblyView). Shared by the playground and the drop-in
// viewer (viewer.js).

import { formatStep, stepsToPlay } from './view-motions.js';

/** Steps per second at speed 1: one part leaves per second... */
const STEPS_PER_SECOND = 1;
/** ...unless that would take longer than this: a 100-part bunny plays in 20 s, not 100. */
const MAX_PLAY_SECONDS = 20;
/** Previous / next step animate one removal at least this fast (steps per second). */
const MIN_STEP_RATE = 1.5;
/** A looping animation rests this long when fully assembled or fully taken apart. */
const LOOP_PAUSE_SECONDS = 0.9;
/** A frame after a long stall (hidden tab) does not jump the animation ahead. */
const MAX_FRAME_SECONDS = 0.1;

/**
 * Plays the disassembly step from 0 (assembled) to `length` (every part but the last removed).
 * Without `loop` it stops at the end; with `loop` it rests, plays back to assembled (the
 * assembly is the disassembly reversed), rests, and starts again. `onStep(step)` on every
 * change, `onPlayingChange(playing)` when it starts or stops.
 */
export class DisassemblyPlayer {
  #length = 0;
  #step = 0;
  #direction = 1;
  #restSeconds = 0;
  #playing = false;
  #frameRequest = 0;
  #lastTime = 0;
  #onStep;
  #onPlayingChange;
  /** Previous / next: the whole step to stop at, or null while playing freely. */
  #target = null;
  speed = 1;
  loop = false;

  constructor({ onStep = () => {}, onPlayingChange = () => {} } = {}) {
    this.#onStep = onStep;
    this.#onPlayingChange = onPlayingChange;
  }

  get length() {
    return this.#length;
  }

  get step() {
    return this.#step;
  }

  get playing() {
    return this.#playing;
  }

  /** Steps per second at speed 1: one a second, more for many parts (the whole within MAX_PLAY_SECONDS). */
  get stepsPerSecond() {
    return Math.max(STEPS_PER_SECOND, this.#length / MAX_PLAY_SECONDS);
  }

  /** A new disassembly of `length` steps: back to assembled, stopped. */
  setLength(length) {
    this.pause();
    this.#length = Math.max(Number(length) || 0, 0);
    this.#direction = 1;
    this.seek(0);
  }

  seek(step) {
    this.#step = Math.min(Math.max(Number(step) || 0, 0), this.#length);
    this.#onStep(this.#step);
  }

  /** Animates to the next whole step (one more part removed). */
  next() {
    this.stepTo(Math.floor(this.#step + 1e-6) + 1);
  }

  /** Animates back to the previous whole step (the last removed part put back). */
  previous() {
    this.stepTo(Math.ceil(this.#step - 1e-6) - 1);
  }

  /** Animates to whole step `target` and stops there (at once when motion is to be reduced). */
  stepTo(target) {
    const clamped = Math.min(Math.max(Math.round(Number(target) || 0), 0), this.#length);
    this.pause();
    if (clamped === this.#step) return;
    if (globalThis.matchMedia?.('(prefers-reduced-motion: reduce)').matches) {
      this.seek(clamped);
      return;
    }
    this.#target = clamped;
    this.#start();
  }

  play() {
    if (this.#playing || this.#length <= 0) return;
    // Play from the end means: start again (or, looping, go back the way it came).
    if (this.#step >= this.#length) {
      if (this.loop) this.#direction = -1;
      else this.seek(0);
    }
    if (this.#step <= 0) this.#direction = 1;
    this.#target = null;
    this.#start();
  }

  #start() {
    this.#playing = true;
    this.#restSeconds = 0;
    this.#lastTime = 0;
    this.#frameRequest = requestAnimationFrame((time) => this.#tick(time));
    this.#onPlayingChange(true);
  }

  pause() {
    if (!this.#playing) return;
    this.#playing = false;
    this.#target = null;
    cancelAnimationFrame(this.#frameRequest);
    this.#frameRequest = 0;
    this.#onPlayingChange(false);
  }

  toggle() {
    if (this.#playing) this.pause();
    else this.play();
  }

  dispose() {
    this.pause();
    this.#onStep = () => {};
    this.#onPlayingChange = () => {};
  }

  #tick(time) {
    if (!this.#playing) return;
    const seconds = this.#lastTime ? Math.min((time - this.#lastTime) / 1000, MAX_FRAME_SECONDS) : 0;
    this.#lastTime = time;
    if (this.#target !== null) {
      const rate = Math.max(this.stepsPerSecond * this.speed, MIN_STEP_RATE);
      const sign = this.#target > this.#step ? 1 : -1;
      const next = this.#step + sign * seconds * rate;
      const reached = sign > 0 ? next >= this.#target : next <= this.#target;
      this.seek(reached ? this.#target : next);
      if (reached) {
        this.pause();
        return;
      }
    } else if (this.#restSeconds > 0) {
      this.#restSeconds -= seconds;
    } else {
      const next = this.#step + this.#direction * seconds * this.stepsPerSecond * this.speed;
      const atEnd = this.#direction > 0 ? next >= this.#length : next <= 0;
      this.seek(next);
      if (atEnd) {
        if (!this.loop) {
          this.pause();
          return;
        }
        this.#direction = -this.#direction;
        this.#restSeconds = LOOP_PAUSE_SECONDS;
      }
    }
    this.#frameRequest = requestAnimationFrame((next) => this.#tick(next));
  }
}

/**
 * Where a partial plan (a disassemblyFailure with moves) stopped: 'parts 1, 2, 3 are stuck
 * together', or 'parts 1, 2, 3 are not separated (search limit)' when a search gave up.
 */
export function formatStuck(failure) {
  const groups = Array.isArray(failure?.unseparated) && failure.unseparated.length ? failure.unseparated : [failure?.stuck ?? []];
  const named = groups.map((group) => `${group.length === 1 ? 'part' : 'parts'} ${group.join(', ')}`).join(' and ');
  const plural = groups.length > 1 || groups[0]?.length > 1;
  if (failure?.searchLimitReached) return `${named} ${plural ? 'are' : 'is'} not separated (search limit${failure.limit ? `: ${failure.limit}` : ''})`;
  return `${named} ${plural ? 'are' : 'is'} stuck${groups.some((group) => group.length > 1) ? ' together' : ''}`;
}

/** '8 s', '1 min 20 s'. */
function formatSeconds(seconds) {
  const whole = Math.round(seconds);
  return whole < 60 ? `${whole} s` : `${Math.floor(whole / 60)} min ${whole % 60} s`;
}

/** '+z×1, then -x×2'; a plate plan's moves (with their own vector) have no step count: 'along -z'. */
export function formatMoves(path) {
  const moves = path ?? [];
  if (moves.length > 0 && moves.every((move) => Array.isArray(move.vector))) return `along ${moves.map((move) => move.dir).join(', then ')}`;
  return moves.map((move) => `${move.dir}×${move.steps}`).join(', then ');
}

/**
 * What the disassembly shows at `step`: `{ text, partId, index, moves }`, e.g. "removing part 3
 * (2 of 8)" with moves "+z×1, then -x×2"; "assembled" at 0 and "part 9 left" at the end.
 * A plan of moves (stepsToPlay) says "move 5 of 27" with moves "parts 2, 4  +x 1" (the move
 * under way, or just made at a whole step) and lists its `parts`; `index` is then the move's.
 * At the end of a partial plan (a disassemblyFailure) the moves text names the stuck parts.
 */
export function describeDisassemblyStep(disassembly, step) {
  const steps = stepsToPlay(disassembly);
  if (steps) {
    if (step <= 0) return { text: 'assembled', partId: null, index: -1, moves: '', parts: [] };
    const index = Math.min(Math.ceil(step - 1e-9), steps.length) - 1;
    let moves = formatStep(steps[index]);
    if (index === steps.length - 1 && step >= steps.length && Array.isArray(disassembly.unseparated)) {
      moves += `; then ${formatStuck(disassembly)}`;
    }
    return { text: `move ${index + 1} of ${steps.length}`, partId: null, index, moves, parts: [...(steps[index].parts ?? [])] };
  }
  const order = disassembly?.order ?? [];
  if (order.length < 2) return { text: '', partId: null, index: -1, moves: '' };
  if (step <= 0) return { text: 'assembled', partId: null, index: -1, moves: '' };
  const index = Math.min(Math.floor(step), order.length - 1);
  if (index >= order.length - 1) {
    return { text: `part ${order[order.length - 1]} left`, partId: order[order.length - 1], index, moves: '' };
  }
  return {
    text: `removing part ${order[index]} (${index + 1} of ${order.length - 1})`,
    partId: order[index],
    index,
    moves: formatMoves(disassembly.paths?.[index]),
  };
}

/**
 * Wires playback controls to `view`. `elements`: `range` (input[type=range], the step),
 * `label` (where describeDisassemblyStep's text goes), and optional `moves` (the moving part's
 * path), `playButton`, `speedSelect` (values are speed factors), `loopCheckbox`, `explodedRange`
 * (0..1), `previousButton` / `nextButton` (one removal back / on), `root` (gets data-playing).
 * `onStep({ step, index, partId, parts, moves })` is told about every change (e.g. to highlight
 * the current removal in a list; `moves` is true when a plan of moves is played, `index` then
 * being the move's). Returns { setDisassembly, play, pause, seek, setExploded, player, dispose }.
 * setDisassembly takes the report's disassembly, or a disassemblyFailure whose moves are played
 * up to where they stop.
 */
export function createPlaybackControls(view, elements, { onStep = () => {}, loop = false } = {}) {
  const { range, label, moves, playButton, speedSelect, loopCheckbox, explodedRange, previousButton, nextButton, root } = elements;
  let disassembly = null;

  /** Previous at the start and Next at the end have nothing to do. */
  function updateStepButtons(step) {
    if (previousButton) previousButton.disabled = !disassembly || step <= 0;
    if (nextButton) nextButton.disabled = !disassembly || step >= player.length;
  }

  const player = new DisassemblyPlayer({
    onStep(step) {
      view.setDisassemblyStep(step);
      if (range && Number(range.value) !== step) range.value = String(step);
      const described = describeDisassemblyStep(disassembly, step);
      if (label) label.textContent = described.text;
      if (moves) moves.textContent = described.moves;
      updateStepButtons(step);
      onStep({ step, index: described.index, partId: described.partId, parts: described.parts ?? [], moves: Boolean(stepsToPlay(disassembly)) });
    },
    onPlayingChange(playing) {
      if (playButton) {
        playButton.textContent = playing ? 'Pause' : 'Play';
        playButton.setAttribute('aria-pressed', String(playing));
      }
      if (root) root.dataset.playing = String(playing);
    },
  });
  player.loop = loopCheckbox ? loopCheckbox.checked : loop;
  if (speedSelect) player.speed = Number(speedSelect.value) || 1;

  const stepTitles = {
    previous: { removal: previousButton?.getAttribute('title') ?? null, move: 'Previous step: undo the last move' },
    next: { removal: nextButton?.getAttribute('title') ?? null, move: 'Next step: the next move of the plan' },
  };
  const listeners = [];
  const listen = (target, type, handler) => {
    if (!target) return;
    target.addEventListener(type, handler);
    listeners.push(() => target.removeEventListener(type, handler));
  };
  // Dragging the slider takes over from the clock.
  listen(range, 'input', () => {
    player.pause();
    player.seek(Number(range.value));
  });
  listen(playButton, 'click', () => player.toggle());
  listen(previousButton, 'click', () => player.previous());
  listen(nextButton, 'click', () => player.next());
  listen(speedSelect, 'change', () => { player.speed = Number(speedSelect.value) || 1; });
  listen(loopCheckbox, 'change', () => { player.loop = loopCheckbox.checked; });
  listen(explodedRange, 'input', () => view.setExploded(Number(explodedRange.value)));

  function setDisassembly(next) {
    // A plan of moves plays move by move; any other part by part (the last part stays).
    const steps = stepsToPlay(next);
    const removable = steps ? steps.length : (next?.order?.length ?? 0) - 1;
    disassembly = removable > 0 && view.available ? next : null;
    const length = disassembly ? removable : 0;
    if (range) {
      range.disabled = !disassembly;
      range.max = String(Math.max(length, 1));
    }
    if (playButton) playButton.disabled = !disassembly;
    // Previous / Next say what they do: a move, or a removal.
    for (const [button, titles] of [[previousButton, stepTitles.previous], [nextButton, stepTitles.next]]) {
      if (button && titles.removal !== null) button.title = steps ? titles.move : titles.removal;
    }
    if (explodedRange) {
      explodedRange.disabled = !view.available;
      view.setExploded(Number(explodedRange.value));
    }
    player.setLength(length);
    if (range) range.title = disassembly ? `${length} ${steps ? 'moves' : 'removals'}, ${formatSeconds(length / player.stepsPerSecond)} at 1×` : '';
  }

  return {
    player,
    setDisassembly,
    play: () => player.play(),
    pause: () => player.pause(),
    seek: (step) => {
      player.pause();
      player.seek(step);
    },
    setExploded(factor) {
      const clamped = Math.min(Math.max(Number(factor) || 0, 0), 1);
      if (explodedRange) explodedRange.value = String(clamped);
      view.setExploded(clamped);
    },
    dispose() {
      player.dispose();
      for (const remove of listeners) remove();
    },
  };
}
