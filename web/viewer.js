// SPDX-License-Identifier: GPL-3.0-or-later
//
// The drop-in viewer: a live 3D view of an interlocking assembly for any page (a course page, a
// blog post), with the computed disassembly played back, an exploded view and the blocking
// graphs. Two ways in:
//
//   <script type="module" src="/path/to/web/viewer.js"></script>
//   <desia-viewer src="puzzles/cube.puz" autoplay></desia-viewer>
//
//   import { mountViewer } from '/path/to/web/viewer.js';          // or from 'desia/viewer'
//   const viewer = mountViewer(element, { document, report, surfaces });   // or { src } / { text, name }
//   viewer.play(); viewer.pause(); viewer.setExploded(0.5); viewer.update(document, report); viewer.dispose();
//
// The host page provides an import map for the bare specifier 'three' (and 'three/addons/'); this
// module brings its sibling files (view.js, dbg-panel.js) and the package's
// createDesia (../wasm/index.js), which checks files in a worker to get the report (verdict, key,
// removal order and paths, graphs) and the part surfaces to draw (desia.partSurfaces). Everything the viewer draws lives in the host's shadow root,
// with its own styles: the page's styles do not leak in, the viewer's do not leak out.
//
// Attributes of <desia-viewer>: src (a .puz or JSON assembly, or an OBJ / STL mesh assembly, on the page's origin), autoplay
// (play the disassembly and the assembly in a loop), loop, exploded (0..1; empty = 1),
// controls="none" (no control bar), graphs (offer the blocking-graph drawing).
// Events on the element (or on mountViewer's element): 'ready' (detail { report, document,
// name }) once an assembly is drawn, 'error' (detail { message }) when a file cannot be fetched,
// read or checked; the message is shown inside the viewer too. data-state on the element:
// loading | ready | error.

import { AssemblyView, createPlaybackControls, withPlannedRemoval } from './view.js';
import { renderBlockingGraphs } from './dbg-panel.js';
import { createDesia } from '../wasm/index.js';
import { isMeshAssemblyName, meshViewDocument } from './mesh-document.js';

/** Larger files are refused before they are read: a voxel file this big is surely a mistake. */
const MAX_FILE_BYTES = 32 * 1024 * 1024;

const VIEWER_CSS = `
:host {
  display: block;
  position: relative;
  width: 100%;
  aspect-ratio: 4 / 3;
  min-height: 220px;
  overflow: hidden;
  border-radius: 6px;
  background: #1b1e24;
  color: #e6e8ec;
  font: 14px/1.4 system-ui, -apple-system, "Segoe UI", Roboto, "Noto Sans", sans-serif;
  contain: content;
}
:host([hidden]) { display: none; }
* { box-sizing: border-box; }
[hidden] { display: none !important; }
.frame, .viewport { position: absolute; inset: 0; }
.viewport canvas { display: block; width: 100%; height: 100%; touch-action: none; }
.badge {
  position: absolute; top: 0.5rem; left: 0.5rem; margin: 0; padding: 0.15rem 0.5rem;
  font-size: 0.85rem; background: rgba(21, 23, 28, 0.8); border-radius: 6px; pointer-events: none;
}
.badge[data-verdict="interlocking"] .verdict { color: #5fd38d; }
.badge[data-verdict="deadlocked"] .verdict { color: #f2b14c; }
.badge[data-verdict="not-interlocking"] .verdict { color: #ff7a6b; }
.badge .key { color: #ffc21a; }
.hover-label {
  position: absolute; top: 2.2rem; left: 0.5rem; padding: 0.1rem 0.45rem; font-size: 0.8rem;
  background: rgba(21, 23, 28, 0.8); border-radius: 6px; pointer-events: none;
}
.viewer-notice, .message, .loading {
  position: absolute; left: 0.75rem; right: 0.75rem; top: 50%; transform: translateY(-50%);
  margin: 0; padding: 0.6rem 0.8rem; text-align: center; border-radius: 6px; overflow-wrap: anywhere;
}
.viewer-notice { color: #f2b14c; background: rgba(21, 23, 28, 0.85); border: 1px solid #4b3f27; }
.message { color: #ffd9d4; background: #3a1f1d; border: 1px solid #7a3129; }
.loading { color: #9aa1ad; }
.controls {
  position: absolute; left: 0.5rem; right: 0.5rem; bottom: 0.5rem;
  display: flex; flex-wrap: wrap; align-items: center; gap: 0.3rem 0.5rem; padding: 0.3rem 0.5rem;
  font-size: 0.8rem; background: rgba(31, 35, 43, 0.88); border: 1px solid #2e333d; border-radius: 6px;
}
.controls button {
  font: inherit; color: #e6e8ec; background: #2a2f39; border: 1px solid #3a404c; border-radius: 6px;
  padding: 0.15rem 0.55rem; cursor: pointer;
}
.controls button:hover:not(:disabled) { border-color: #566072; }
.controls button:disabled, .controls input:disabled { opacity: 0.45; cursor: default; }
.controls button:focus-visible, .controls input:focus-visible { outline: 2px solid #ffc21a; outline-offset: 1px; }
.controls .play { min-width: 3.8rem; }
.controls input[type="range"] { accent-color: #ffc21a; margin: 0; }
.controls .step { flex: 1 1 6rem; min-width: 5rem; }
.controls .explode { width: 4.5rem; }
.controls .step-label { flex: 1 1 9rem; color: #9aa1ad; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
.controls label { display: inline-flex; align-items: center; gap: 0.3rem; color: #9aa1ad; }
.graphs {
  position: absolute; inset: 0.5rem 0.5rem 3.2rem; overflow: auto; padding: 0.4rem 0.6rem;
  background: rgba(21, 23, 28, 0.94); border: 1px solid #2e333d; border-radius: 6px;
}
.dbg-legend, .dbg-note { margin: 0.2rem 0 0.5rem; color: #9aa1ad; font-size: 0.78rem; }
.dbg-key-note { color: #ffc21a; }
.dbg-grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(9.5rem, 1fr)); gap: 0.5rem; }
.dbg-graph { margin: 0; padding: 0.3rem; background: #191c22; border: 1px solid #2e333d; border-radius: 6px; cursor: zoom-in; }
.dbg-graph.dbg-wide { grid-column: 1 / -1; cursor: zoom-out; }
.dbg-graph svg { display: block; width: 100%; height: auto; }
.dbg-graph figcaption { margin-top: 0.2rem; font-size: 0.75rem; color: #9aa1ad; }
.dbg-graph figcaption strong { color: #e6e8ec; }
.dbg-toolbar, .dbg-tool-group, .dbg-find, .dbg-matrix-directions { display: flex; flex-wrap: wrap; align-items: center; gap: 0.25rem 0.6rem; margin: 0.3rem 0; }
.dbg-tool { font: inherit; font-size: 0.75rem; padding: 0.1rem 0.45rem; background: #2b303a; color: #e6e8ec; border: 1px solid #3b414d; border-radius: 4px; }
.dbg-tool[aria-pressed="true"] { border-color: #ffc21a; color: #ffc21a; }
.dbg-find input { width: 4rem; font: inherit; font-size: 0.75rem; }
.dbg-find-status { color: #9aa1ad; font-size: 0.75rem; }
.dbg-graph svg.dbg-svg { touch-action: none; }
.dbg-matrix-scroll { max-height: 20rem; overflow: auto; }
`;

const VERDICT_TITLES = { interlocking: 'Interlocking', deadlocked: 'Deadlocked', 'not-interlocking': 'Not interlocking' };

/** The viewer mounted in each host, so that mounting again replaces it cleanly. */
const mountedViewers = new WeakMap();

/** One core for all viewers of a page, loaded on first use (a worker: the page never freezes). */
let sharedDesia = null;

function pageDesia() {
  sharedDesia ??= createDesia().catch((error) => {
    sharedDesia = null; // A later viewer may try again.
    throw error;
  });
  return sharedDesia;
}

/** Styles scoped to the shadow root; a constructed sheet also works under a strict style-src. */
function adoptStyles(root) {
  if ('adoptedStyleSheets' in root && typeof CSSStyleSheet === 'function' && 'replaceSync' in CSSStyleSheet.prototype) {
    const sheet = new CSSStyleSheet();
    sheet.replaceSync(VIEWER_CSS);
    root.adoptedStyleSheets = [sheet];
    return;
  }
  const style = document.createElement('style');
  style.textContent = VIEWER_CSS;
  root.append(style);
}

function make(tag, className, text) {
  const node = document.createElement(tag);
  if (className) node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

function prefersReducedMotion() {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}

function fileNameOf(url) {
  const last = decodeURIComponent(url.pathname.split('/').pop() || '');
  return last || url.href;
}

/**
 * Reads `src` (a URL relative to the page) as text. Only the page's own origin is asked: nothing
 * this viewer does sends a request elsewhere.
 */
async function fetchAssemblyText(src, baseUri) {
  const { name, buffer } = await fetchFile(src, baseUri);
  try {
    return { name, text: new TextDecoder('utf-8', { fatal: true }).decode(buffer) };
  } catch {
    throw new Error(`${name}: not a text file (it is not valid UTF-8); expected a .puz or desia .json assembly`);
  }
}

/** A mesh file of the page's origin (OBJ or STL, any encoding) as a mesh document of one file. */
async function fetchMeshDocument(src, baseUri) {
  const { name, buffer } = await fetchFile(src, baseUri);
  return { files: [{ name, bytes: new Uint8Array(buffer) }] };
}

/** { name, buffer } of a file on the page's origin, with the size cap. */
async function fetchFile(src, baseUri) {
  const url = new URL(src, baseUri);
  const name = fileNameOf(url);
  if (url.origin !== location.origin) {
    throw new Error(`${name}: not loaded: ${url.href} is not on this page's origin (${location.origin})`);
  }
  let response;
  try {
    // No redirects: one could lead off this origin, and the browser would follow it before we saw.
    response = await fetch(url, { credentials: 'same-origin', redirect: 'error' });
  } catch (error) {
    throw new Error(`${name}: cannot fetch ${url.pathname}: ${error.message} (redirects are not followed)`);
  }
  if (!response.ok) throw new Error(`${name}: cannot fetch ${url.pathname} (HTTP ${response.status})`);
  const declared = Number(response.headers.get('content-length'));
  if (declared > MAX_FILE_BYTES) throw new Error(`${name}: the file is too large (${(declared / 1048576).toFixed(1)} MiB)`);
  const buffer = await response.arrayBuffer();
  // Content-Length may be absent (chunked responses): check what actually arrived too.
  if (buffer.byteLength > MAX_FILE_BYTES) {
    throw new Error(`${name}: the file is too large (${(buffer.byteLength / 1048576).toFixed(1)} MiB)`);
  }
  return { name, buffer };
}

/**
 * Mounts a viewer into `host` (its shadow root; one is attached when it has none). Options:
 *   document, report   a parsed document and its check report (desia.parseDocument / desia.check)
 *   surfaces           and its part surfaces (desia.partSurfaces); fetched from `desia` when missing
 *   src                or a URL (relative to the page, same origin) of a .puz / JSON file, or of
 *                      an OBJ / STL mesh assembly (one part per object, group or solid)
 *   meshes             or a mesh document { files: [{ name, bytes | text }], unit?, tolerance? }
 *   text, name         or the file's text and a name for messages
 *   autoplay           play disassembly and assembly in a loop once shown (not with reduced motion)
 *   loop               loop when played (default: autoplay)
 *   exploded           explode factor 0..1 (default 0)
 *   controls           show the control bar (default true)
 *   graphs             offer the blocking-graph drawing (default false)
 *   speed              animation speed factor (default 1)
 *   desia              an object with check(), parseDocument() and partSurfaces() (default: one
 *                      createDesia() per page)
 * Returns { element, report, document, update(document, report, name, surfaces), load(source),
 * play(), pause(), setExploded(x), setStep(step), dispose() }; load() takes { src } or
 * { text, name } or { meshes, name? } (a mesh document: the parts of an assembly as OBJ/STL files,
 * docs/meshes.md; a src ending in .obj, .stl or .3mf is one) or a URL string and resolves with the report (it rejects, and shows the message,
 * on failure); update() resolves once the assembly is drawn (it rejects, and shows the message,
 * when its surfaces cannot be had).
 */
export function mountViewer(host, options = {}) {
  if (!(host instanceof Element)) throw new TypeError('mountViewer: the first argument must be an element');
  mountedViewers.get(host)?.dispose();
  const root = host.shadowRoot ?? host.attachShadow({ mode: 'open' });
  root.replaceChildren();
  adoptStyles(root);

  const frame = make('div', 'frame');
  const viewport = make('div', 'viewport');
  const notice = make('p', 'viewer-notice');
  notice.hidden = true;
  const badge = make('p', 'badge');
  badge.hidden = true;
  const loading = make('p', 'loading', 'Loading…');
  loading.hidden = true;
  const message = make('div', 'message');
  message.setAttribute('role', 'alert');
  message.hidden = true;
  const graphsPanel = make('div', 'graphs');
  graphsPanel.hidden = true;

  const controls = make('div', 'controls');
  const playButton = make('button', 'play', 'Play');
  playButton.type = 'button';
  playButton.title = 'Play the disassembly';
  const stepRange = make('input', 'step');
  Object.assign(stepRange, { type: 'range', min: '0', max: '1', step: '0.01', value: '0' });
  stepRange.setAttribute('aria-label', 'Disassembly step');
  const stepLabel = make('output', 'step-label');
  const explodeLabel = make('label', '', 'Explode');
  const explodeRange = make('input', 'explode');
  Object.assign(explodeRange, { type: 'range', min: '0', max: '1', step: '0.01', value: '0' });
  explodeLabel.append(explodeRange);
  const graphsButton = make('button', 'graphs-button', 'Graphs');
  graphsButton.type = 'button';
  graphsButton.title = 'Directional blocking graphs';
  graphsButton.setAttribute('aria-pressed', 'false');
  graphsButton.hidden = !options.graphs;
  controls.append(playButton, stepRange, stepLabel, explodeLabel, graphsButton);
  controls.hidden = options.controls === false;

  frame.append(viewport, notice, badge, loading, message, graphsPanel, controls);
  root.append(frame);

  const view = new AssemblyView(viewport, { notice });
  const playback = createPlaybackControls(view, {
    range: stepRange, label: stepLabel, playButton, explodedRange: explodeRange, root: frame,
  }, { loop: options.loop ?? Boolean(options.autoplay) });
  playback.player.speed = Number(options.speed) > 0 ? Number(options.speed) : 1;
  playback.setExploded(options.exploded ?? 0);

  let current = { document: null, report: null, name: '' };
  let generation = 0;
  let disposed = false;
  let autoplay = Boolean(options.autoplay);
  const desiaSource = options.desia ?? null;

  graphsButton.addEventListener('click', () => {
    graphsPanel.hidden = !graphsPanel.hidden;
    graphsButton.setAttribute('aria-pressed', String(!graphsPanel.hidden));
  });

  // Off screen the animation only costs time: pause it there, resume when it comes back.
  let resumeWhenVisible = false;
  const visibility = typeof IntersectionObserver === 'function' ? new IntersectionObserver((entries) => {
    const visible = entries[entries.length - 1].isIntersecting;
    if (!visible && playback.player.playing) {
      resumeWhenVisible = true;
      playback.pause();
    } else if (visible && resumeWhenVisible) {
      resumeWhenVisible = false;
      playback.play();
    }
  }) : null;
  visibility?.observe(host);

  function setState(state) {
    host.dataset.state = state;
    loading.hidden = state !== 'loading';
  }

  function emit(type, detail) {
    host.dispatchEvent(new CustomEvent(type, { detail }));
  }

  function renderBadge(report) {
    if (!report) {
      badge.hidden = true;
      return;
    }
    const verdict = report.verdict ?? (report.interlocking ? 'interlocking' : 'not-interlocking');
    badge.dataset.verdict = verdict;
    const parts = [make('span', 'verdict', VERDICT_TITLES[verdict] ?? verdict)];
    if (report.key !== null && report.key !== undefined && verdict === 'interlocking') {
      parts.push(' · ', make('span', 'key', `key: part ${report.key}`));
    }
    parts.push(` · ${report.parts ?? report.partIds?.length ?? 0} parts`);
    badge.replaceChildren(...parts);
    badge.hidden = false;
  }

  function showError(error) {
    const text = error?.message ?? String(error);
    view.clear();
    playback.setDisassembly(null);
    renderBadge(null);
    graphsPanel.replaceChildren();
    explodeRange.disabled = true; // Nothing to explode; the next assembly shown enables it again.
    message.textContent = text;
    message.hidden = false;
    setState('error');
    emit('error', { message: text });
  }

  /**
   * The part surfaces of `document_` from the viewer's core (null for documents without voxels,
   * plates or beams: the view says it cannot draw them).
   */
  async function surfacesOf(document_, name) {
    const drawn = document_?.kind === 'voxel' || (document_?.kind === 'plate' && document_.plates?.length > 0)
      || (document_?.kind === 'frame' && document_.beams?.length > 0);
    if (!drawn) return null;
    const desia = desiaSource ?? await pageDesia();
    return desia.partSurfaces(document_, { source: name || 'assembly' });
  }

  /**
   * Draws `document_` (with its part surfaces, fetched from the core when not given) and what
   * `report` found; resolves once it is drawn, rejects (and shows the message) on failure.
   */
  async function showDocument(document_, report, name = '', surfaces = undefined) {
    if (disposed) throw new Error('mountViewer: this viewer was disposed');
    if (surfaces !== undefined && surfaces !== null) {
      show(document_, report, name, surfaces);
      return;
    }
    const mine = ++generation;
    playback.pause();
    message.hidden = true;
    setState('loading');
    try {
      const fetched = await surfacesOf(document_, name);
      if (!disposed && mine === generation) show(document_, report, name, fetched);
    } catch (error) {
      if (!disposed && mine === generation) showError(error);
      throw error;
    }
  }

  /** Draws `document_` and its surfaces with what `report` found; 'ready' once the first frame is drawn. */
  function show(document_, report, name, surfaces) {
    if (disposed) throw new Error('mountViewer: this viewer was disposed');
    generation += 1;
    current = { document: document_, report, name };
    message.hidden = true;
    view.show(document_, surfaces);
    // A plate plan or a designed frame plays its own removal directions.
    const planned = report ? withPlannedRemoval(report, document_) : null;
    view.applyReport(planned ?? {});
    // A plan of moves plays move by move; a partial one (disassemblyFailure) up to where it stops.
    playback.setDisassembly(planned?.disassembly ?? planned?.disassemblyFailure ?? null);
    renderBadge(report);
    if (report) renderBlockingGraphs(graphsPanel, report);
    else graphsPanel.replaceChildren();
    if (autoplay && !prefersReducedMotion()) playback.play();
    setState('ready');
    const shown = generation;
    // 'ready' once the first frame with the parts is on the canvas.
    requestAnimationFrame(() => requestAnimationFrame(() => {
      if (!disposed && shown === generation) emit('ready', { report, document: document_, name });
    }));
  }

  async function load(source) {
    if (disposed) throw new Error('mountViewer: this viewer was disposed');
    const request = typeof source === 'string' ? { src: source } : (source ?? {});
    const mine = ++generation;
    playback.pause();
    message.hidden = true;
    setState('loading');
    try {
      const meshSrc = request.src !== undefined && request.src !== null && isMeshAssemblyName(new URL(String(request.src), host.baseURI).pathname);
      if (request.meshes !== undefined || meshSrc) {
        // A mesh assembly: its files checked as `desia check FILES` does, drawn from their triangles.
        const meshes = request.meshes ?? await fetchMeshDocument(String(request.src), host.baseURI);
        const name = request.name ?? meshes.files?.map((file) => file.name).join(', ') ?? 'meshes';
        const desia = desiaSource ?? await pageDesia();
        const report = await desia.check(meshes);
        const surfaces = await desia.partSurfaces(meshes);
        if (!disposed && mine === generation) show(meshViewDocument(name, report), report, name, surfaces);
        return report;
      }
      const { name, text } = request.src !== undefined && request.src !== null
        ? await fetchAssemblyText(String(request.src), host.baseURI)
        : { name: request.name ?? 'assembly', text: request.text };
      if (typeof text !== 'string') throw new Error('mountViewer: give src, or text with a name');
      const desia = desiaSource ?? await pageDesia();
      // `source` makes the core's messages name the file (and the line) they are about. Voxel
      // assemblies, plates and frames have surfaces: a voxel document's error counts once the document says it is one.
      const [document_, report, surfaces] = await Promise.all([
        desia.parseDocument(text, { source: name }),
        desia.check(text, { source: name }),
        desia.partSurfaces(text, { source: name }).catch((error) => error),
      ]);
      if (document_?.kind === 'voxel' && surfaces instanceof Error) throw surfaces;
      if (disposed || mine !== generation) return report;
      show(document_, report, name, surfaces instanceof Error ? null : surfaces);
      return report;
    } catch (error) {
      if (!disposed && mine === generation) showError(error);
      throw error;
    }
  }

  const handle = {
    get element() {
      return host;
    },
    get report() {
      return current.report;
    },
    get document() {
      return current.document;
    },
    /** Shows another assembly whose document and report (and maybe surfaces) are known. */
    update(document_, report, name, surfaces) {
      return showDocument(document_, report ?? null, name ?? '', surfaces);
    },
    load,
    play() {
      autoplay = false; // An explicit call decides from now on.
      playback.play();
    },
    pause() {
      autoplay = false;
      resumeWhenVisible = false;
      playback.pause();
    },
    /** 0 = assembled, 1 = fully exploded. */
    setExploded(factor) {
      playback.setExploded(factor);
    },
    /** Shows one moment of the disassembly: 0 = assembled, i..i+1 = the (i+1)-th part leaving (or move). */
    setStep(step) {
      playback.seek(step);
    },
    setLoop(loop) {
      playback.player.loop = Boolean(loop);
    },
    get playing() {
      return playback.player.playing;
    },
    get step() {
      return playback.player.step;
    },
    get steps() {
      return playback.player.length;
    },
    partPositions: () => view.partPositions(),
    dispose() {
      if (disposed) return;
      disposed = true;
      generation += 1;
      visibility?.disconnect();
      playback.dispose();
      view.dispose();
      root.replaceChildren();
      delete host.dataset.state;
      if (mountedViewers.get(host) === handle) mountedViewers.delete(host);
    },
  };
  mountedViewers.set(host, handle);

  if (options.document) {
    // Failures are on screen and in the 'error' event.
    showDocument(options.document, options.report ?? null, options.name ?? '', options.surfaces).catch(() => {});
  } else if (options.src !== undefined || options.text !== undefined || options.meshes !== undefined) {
    // Failures are on screen and in the 'error' event; a caller who wants the promise calls load().
    const source = options.src !== undefined ? { src: options.src }
      : options.meshes !== undefined ? { meshes: options.meshes, name: options.name } : { text: options.text, name: options.name };
    load(source).catch(() => {});
  }
  return handle;
}

/** The `exploded` attribute: absent = 0, present without a value = 1, else a number in 0..1. */
function explodedFromAttribute(value) {
  if (value === null) return 0;
  if (value.trim() === '') return 1;
  const number = Number(value);
  return Number.isFinite(number) ? Math.min(Math.max(number, 0), 1) : 0;
}

/** <desia-viewer src="…" autoplay loop exploded="0.5" controls="none" graphs> */
export class DesiaViewerElement extends HTMLElement {
  static get observedAttributes() {
    return ['src', 'exploded', 'autoplay', 'loop', 'controls', 'graphs'];
  }

  #viewer = null;

  connectedCallback() {
    if (this.#viewer) return;
    this.#mount();
  }

  disconnectedCallback() {
    // Moving the element fires disconnected and connected at once: keep the viewer then.
    queueMicrotask(() => {
      if (this.isConnected || !this.#viewer) return;
      this.#viewer.dispose();
      this.#viewer = null;
    });
  }

  attributeChangedCallback(name, oldValue, value) {
    if (!this.#viewer || oldValue === value) return;
    if (name === 'exploded') this.#viewer.setExploded(explodedFromAttribute(value));
    else if (name === 'loop') this.#viewer.setLoop(value !== null);
    else if (name === 'src' && value === null) {
      // No file any more: show nothing rather than the previous puzzle.
      this.#viewer.dispose();
      this.#mount();
    } else if (name === 'src') this.#load();
    else {
      // Control bar, graphs or autoplay changed: build the viewer again around the same file.
      this.#viewer.dispose();
      this.#mount();
    }
  }

  #mount() {
    this.#viewer = mountViewer(this, {
      autoplay: this.hasAttribute('autoplay'),
      loop: this.hasAttribute('loop') || this.hasAttribute('autoplay'),
      exploded: explodedFromAttribute(this.getAttribute('exploded')),
      controls: this.getAttribute('controls') !== 'none',
      graphs: this.hasAttribute('graphs'),
    });
    this.#load();
  }

  #load() {
    const src = this.getAttribute('src');
    if (src) this.#viewer.load({ src }).catch(() => {});
  }

  get src() {
    return this.getAttribute('src') ?? '';
  }

  set src(value) {
    this.setAttribute('src', value);
  }

  /** The mountViewer handle (play, pause, setExploded, setStep, update, load, report, …). */
  get viewer() {
    return this.#viewer;
  }

  get report() {
    return this.#viewer?.report ?? null;
  }

  play() {
    this.#viewer?.play();
  }

  pause() {
    this.#viewer?.pause();
  }

  setExploded(factor) {
    this.#viewer?.setExploded(factor);
  }
}

if (typeof customElements !== 'undefined' && !customElements.get('desia-viewer')) {
  customElements.define('desia-viewer', DesiaViewerElement);
}
