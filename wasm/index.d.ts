// SPDX-License-Identifier: GPL-3.0-or-later
// Type declarations of the desia package (hand-written; tests/node/api.test.mjs checks that the
// names here match what wasm/index.js exports).

/** Where to find the WebAssembly binary; by default `dist/desia_wasm.wasm` beside the package. */
export interface LoadOptions {
  /** URL (browser) or file path / file: URL (node) of `desia_wasm.wasm`. */
  wasmUrl?: string | URL;
  /** The bytes of `desia_wasm.wasm`, when the caller already has them. */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

export type CheckMethod = 'dbg' | 'lp' | 'both';
export type VerdictName = 'interlocking' | 'deadlocked' | 'not-interlocking';
export type ErrorCode = 'bad-input' | 'too-large' | 'unsupported' | 'internal';

export interface CheckOptions {
  /** 'dbg' (directional blocking graphs, default), 'lp' (linear program) or 'both'. */
  method?: CheckMethod;
  /** Name used in error messages, e.g. the file name. */
  source?: string;
}

/** A part or part group that can move: the evidence of a negative verdict. */
export interface Witness {
  parts: number[];
  /** Common direction label ('+x'), or null when the parts move in different directions. */
  direction: string | null;
  velocities: [number, number, number][];
}

export interface Verdict {
  verdict: VerdictName;
  interlocking: boolean;
  deadlocked: boolean;
  reason: string;
  /** Part id of the key, or null. */
  key: number | null;
  /** Free directions of the key, e.g. ['+y']. */
  keyDirections: string[];
  witness: Witness | null;
}

export interface Move {
  /** Direction label, e.g. '+y'. */
  dir: string;
  /** Unit steps (voxels) along dir; the last move of a path clears the remaining parts. */
  steps: number;
}

export interface BlockingGraph {
  direction: string;
  vector: [number, number, number];
  /** [from, to] part ids: `from` is blocked by `to` along the direction. */
  edges: [number, number][];
  /** Strongly connected components (part ids). */
  components: number[][];
}

/** The report of `check`; the same object as `desia check --json`. */
export interface CheckReport extends Verdict {
  parts: number;
  partIds: number[];
  kind: 'voxel' | 'plate' | 'frame' | 'contacts';
  method: CheckMethod;
  baseDirections: { label: string; vector: [number, number, number] }[];
  graphs: BlockingGraph[];
  /** Per-method verdicts when method is 'both'. */
  methods?: { dbg: Verdict; lp: Verdict };
  /** Removal order (part ids) and one path per removed part; null when no disassembly exists. */
  disassembly: { order: number[]; paths: Move[][] } | null;
  /**
   * When no disassembly was found: the parts removed before getting stuck, the stuck ones, and
   * whether a path search stopped at its work limit (then "stuck" is not proven).
   */
  disassemblyFailure?: { removed: number[]; stuck: number[]; searchLimitReached: boolean };
}

/** The JSON assembly document (see docs/json-schema.md). */
export interface AssemblyDocument {
  format: 'desia-assembly';
  version: 1;
  kind: 'voxel' | 'plate' | 'frame' | 'contacts';
  name?: string;
  voxel?: { size: [number, number, number]; labels: number[] };
  parts: { id: number; name?: string; voxelCount?: number }[];
  contacts?: { a: number; b: number; normal: [number, number, number]; area?: number }[];
  [section: string]: unknown;
}

/** A mesh file's contents (OBJ or STL, ASCII or binary), or OBJ text. */
export type MeshInput = Uint8Array | ArrayBuffer | ArrayBufferView | string;

export interface VoxelizeOptions {
  /** Voxels along the longest side of the mesh's bounding box, 1 to 1024 (default 32). */
  resolution?: number;
  /**
   * Name of the mesh, e.g. its file name 'bunny.obj': used in error messages, as the document's
   * `name` (without folders and extension), and its extension (.obj / .stl) helps tell the format.
   */
  source?: string;
}

/** Options of designVoxel (the same meaning as `desia design voxel`'s flags). */
export interface DesignVoxelOptions {
  /** N, the number of parts (at least 3). */
  parts: number;
  /** Seed of all randomness (default 1): the same seed gives the same puzzle, natively and here. */
  seed?: number;
  /** m, children kept per construction-tree node (default 30). */
  candidates?: number;
  rank?: 'compactness' | 'x' | 'y' | 'z' | '-x' | '-y' | '-z';
  /** 'desia' (default) or 'recursive' (Song et al. 2012's local interlocking groups). */
  mode?: 'desia' | 'recursive';
  minPartSize?: number;
  /** Seconds; 0 or absent: none. */
  timeLimit?: number;
  nodeLimit?: number;
  /** The key's only free direction (default '+y'). */
  keyDirection?: '+x' | '-x' | '+y' | '-y' | '+z' | '-z';
  /** Appearance constraints: voxel coordinates [x, y, z] that must end up in one part. */
  groups?: [number, number, number][][];
  /** Called after every visited node; return false to stop the search. */
  onProgress?: (progress: DesignProgress) => boolean | void;
  /** Name used in error messages. */
  source?: string;
}

export interface DesignProgress {
  nodesVisited: number;
  /** Parts in the current node (placed parts plus the remainder). */
  depth: number;
  /** The most parts any node reached so far. */
  bestDepth: number;
  targetParts: number;
  elapsedSeconds?: number;
}

export interface DesignResult {
  status: 'success' | 'not-found' | 'limit-reached' | 'cancelled';
  message: string;
  progress: DesignProgress;
  /** The verified puzzle as .puz text (part 1 = key), or null. */
  puz: string | null;
  /** The verified puzzle as a JSON assembly document, or null. */
  document: AssemblyDocument | null;
  /** The check that verified it (the same fields as `desia check --json`), or null. */
  verification: CheckReport | null;
}

/**
 * Step-by-step design. Holds WebAssembly memory until dispose() is called.
 */
export interface DesignSession {
  /** The current assembly: partsPlaced counts its parts (placed parts plus the remainder). */
  state(): { partsPlaced: number; targetParts: number; complete: boolean; document: AssemblyDocument };
  /** The number of ranked children of the current node (generated on first call). */
  childCount(): number;
  /** The assembly the n-th child (0 = best ranked) would give. */
  preview(n: number): AssemblyDocument;
  /** Moves to the n-th child. */
  choose(n: number): void;
  /** Moves to the best-ranked child; false when the node has none (go back). */
  next(): boolean;
  /** Moves to the parent; false at the root. */
  back(): boolean;
  /** The check report of the current assembly. */
  check(): CheckReport;
  /** Frees the session; later calls throw. */
  dispose(): void;
}

/** Synchronous core, for workers and node. */
export interface DesiaCore {
  check(text: string, options?: CheckOptions): CheckReport;
  parseDocument(text: string, options?: { source?: string }): AssemblyDocument;
  /**
   * Solid voxelization of a closed triangle mesh (OBJ, or ASCII / binary STL): one part (label 1)
   * made of every voxel whose centre lies inside. Voxel (0,0,0) sits at the bounding-box minimum
   * and the mesh's axes are kept (+y up). The same document as `desia voxelize --output x.json`.
   * Throws a DesiaError for an unreadable or open mesh (naming file, line and value, or the open
   * edge), a result that is empty or falls apart (raise the resolution), or a grid above the
   * limits ('too-large').
   */
  voxelize(mesh: MeshInput, options?: VoxelizeOptions): AssemblyDocument;
  /** A voxel assembly (.puz text, JSON text or a document object) as DESIA .puz text. */
  toPuz(assembly: string | AssemblyDocument, options?: { source?: string }): string;
  designVoxel(shapeText: string, options: DesignVoxelOptions): DesignResult;
  designSession(shapeText: string, options: Omit<DesignVoxelOptions, 'onProgress'>): DesignSession;
  version(): string;
}

/** Promise-based API. */
export interface Desia {
  check(text: string, options?: CheckOptions): Promise<CheckReport>;
  parseDocument(text: string, options?: { source?: string }): Promise<AssemblyDocument>;
  /** Solid voxelization of a closed OBJ / STL mesh; see {@link DesiaCore.voxelize}. */
  voxelize(mesh: MeshInput, options?: VoxelizeOptions): Promise<AssemblyDocument>;
  toPuz(assembly: string | AssemblyDocument, options?: { source?: string }): Promise<string>;
  designVoxel(shapeText: string, options: DesignVoxelOptions): Promise<DesignResult>;
  designSession(shapeText: string, options: Omit<DesignVoxelOptions, 'onProgress'>): Promise<DesignSession>;
  version(): string;
}

/** Error thrown for bad input (with the core's message, naming file, line and value) and failures. */
export class DesiaError extends Error {
  constructor(message: string, code?: ErrorCode, options?: { fatal?: boolean });
  readonly name: 'DesiaError';
  readonly code: ErrorCode;
  /** True when the WebAssembly instance trapped (e.g. out of memory): load a new module. */
  readonly fatal: boolean;
}

export function loadDesiaModule(options?: LoadOptions): Promise<DesiaCore>;
export function createDesia(options?: LoadOptions): Promise<Desia>;
