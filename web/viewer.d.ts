// SPDX-License-Identifier: GPL-3.0-or-later
// Type declarations of the drop-in viewer (`desia/viewer`, web/viewer.js; hand-written;
// tests/node/package.test.mjs checks that the names here match what viewer.js exports and that
// ViewerHandle lists the members mountViewer returns).

import type { AssemblyDocument, CheckReport, MeshDocument, PartSurface } from '../wasm/index.js';

/** What the viewer needs from a desia instance (by default one `createDesia()` per page). */
export interface ViewerCore {
  check(text: string | MeshDocument, options?: { source?: string }): Promise<CheckReport>;
  parseDocument(text: string, options?: { source?: string }): Promise<AssemblyDocument>;
  partSurfaces(assembly: string | AssemblyDocument | MeshDocument, options?: { source?: string }): Promise<PartSurface[]>;
}

/**
 * Where load() gets an assembly: a same-origin URL (an OBJ / STL URL is a mesh assembly), the
 * file's text and a name for messages, or a mesh assembly's files (docs/meshes.md).
 */
export type ViewerSource = string | { src: string } | { text: string; name?: string } | { meshes: MeshDocument; name?: string };

export interface ViewerOptions {
  /** A parsed document and its check report (desia.parseDocument / desia.check). */
  document?: AssemblyDocument;
  report?: CheckReport | null;
  /** The document's part surfaces (desia.partSurfaces); fetched from `desia` when missing. */
  surfaces?: PartSurface[];
  /** Or a URL (relative to the page, same origin only) of a .puz / JSON file or an OBJ / STL mesh assembly. */
  src?: string;
  /** Or a mesh assembly's files (one part per OBJ object or group, per STL file or solid). */
  meshes?: MeshDocument;
  /** Or the file's text, with `name` used in messages. */
  text?: string;
  name?: string;
  /** Play disassembly and assembly in a loop once shown (skipped with prefers-reduced-motion). */
  autoplay?: boolean;
  /** Loop when played (default: autoplay). */
  loop?: boolean;
  /** Explode factor 0..1 (default 0). */
  exploded?: number;
  /** Show the control bar (default true). */
  controls?: boolean;
  /** Offer the blocking-graph drawing (default false). */
  graphs?: boolean;
  /** Animation speed factor (default 1). */
  speed?: number;
  /** The core used to check and parse files and get part surfaces (default: one createDesia() per page). */
  desia?: ViewerCore;
}

export interface ViewerHandle {
  readonly element: Element;
  readonly report: CheckReport | null;
  readonly document: AssemblyDocument | null;
  /**
   * Shows another assembly whose document and report are known, with its part surfaces (fetched
   * from the viewer's core when not given). Resolves once it is drawn; rejects (and shows the
   * message) when the surfaces cannot be had.
   */
  update(document: AssemblyDocument, report: CheckReport | null, name?: string, surfaces?: PartSurface[]): Promise<void>;
  /** Loads and checks a file; rejects (and shows the message) on failure. */
  load(source: ViewerSource): Promise<CheckReport>;
  play(): void;
  pause(): void;
  /** 0 = assembled, 1 = fully exploded. */
  setExploded(factor: number): void;
  /**
   * One moment of the disassembly: 0 = assembled, i..i+1 = the (i+1)-th part leaving (a voxel plan
   * of moves of several parts: the (i+1)-th move under way).
   */
  setStep(step: number): void;
  setLoop(loop: boolean): void;
  readonly playing: boolean;
  readonly step: number;
  readonly steps: number;
  /** Current part positions (for tests and tools). */
  partPositions(): unknown;
  /** Stops the animation, frees the three.js resources and empties the host's shadow root. */
  dispose(): void;
}

/** Mounts a viewer into `host`'s shadow root (attached when missing); mounting again replaces it. */
export function mountViewer(host: Element, options?: ViewerOptions): ViewerHandle;

/**
 * `<desia-viewer src="…" autoplay loop exploded="0.5" controls="none" graphs>`; fires `ready`
 * (detail `{ report, document }`) and `error` (detail `{ message }`).
 */
export class DesiaViewerElement extends HTMLElement {
  src: string;
  readonly viewer: ViewerHandle | null;
  readonly report: CheckReport | null;
  play(): void;
  pause(): void;
  setExploded(factor: number): void;
}

declare global {
  interface HTMLElementTagNameMap {
    'desia-viewer': DesiaViewerElement;
  }
}
