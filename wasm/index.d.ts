// SPDX-License-Identifier: GPL-3.0-or-later
// Type declarations of the desia package (hand-written; tests/node/api.test.mjs checks that the
// names here match what wasm/index.js exports, and that the methods of the objects it returns
// match the interfaces below).

/**
 * The two WebAssembly modules, built from the same core (docs/architecture.md): 'full' has every
 * kind (dist/desia_wasm.wasm); 'light' (dist/desia_light.wasm, about half the bytes) has voxels,
 * contacts and meshes and rejects a plate or frame with code 'kind-not-built'.
 */
export type ModuleName = 'light' | 'full';

/** Where to find the WebAssembly binary; by default `dist/desia_wasm.wasm` beside the package. */
export interface LoadOptions {
  /** URL (browser) or file path / file: URL (node) of `desia_wasm.wasm` (loadDesiaModule: of the module asked for). */
  wasmUrl?: string | URL;
  /** The bytes of `desia_wasm.wasm`, when the caller already has them (createDesia then loads only the full module). */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

/** Options of {@link loadDesiaModule}. */
export interface LoadModuleOptions extends LoadOptions {
  /** Which module: 'full' (default) or 'light'. */
  module?: ModuleName;
}

export type CheckMethod = 'dbg' | 'lp' | 'both';
export type VerdictName = 'interlocking' | 'deadlocked' | 'not-interlocking';
/**
 * Why a call failed. From the core: 'bad-input' (the message names file, line and value, as the
 * CLI does), 'too-large' (above the grid or mesh limits, or out of memory), 'unsupported' (e.g. a
 * designer that has not landed yet), 'internal' (a bug, a trap or a crashed worker). From
 * {@link createDesia}: 'terminated' (terminate() was called while the call was pending) and
 * 'session-lost' (the worker that held a design session was stopped). From the light module
 * (loadDesiaModule({ module: 'light' })): 'kind-not-built', a plate or frame it does not hold
 * (createDesia never shows it: its worker loads the full module and asks again).
 */
export type ErrorCode = 'bad-input' | 'too-large' | 'unsupported' | 'internal' | 'terminated' | 'session-lost' | 'kind-not-built';

export interface CheckOptions {
  /** 'dbg' (directional blocking graphs, default), 'lp' (linear program) or 'both'. */
  method?: CheckMethod;
  /** Name used in error messages, e.g. the file name. */
  source?: string;
  /**
   * Keep every base direction and DBG in the report (default false: only when there are at most
   * 128 of them; hundreds of distinct normals give hundreds of thousands).
   */
  graphs?: boolean;
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

/**
 * One move of a voxel disassembly plan: the listed parts move together by whole voxels along one
 * axis, e.g. `{ parts: [2, 4], move: [1, 0, 0], out: false }` ("move 3: parts 2, 4  +x 1"). With
 * `out: true`, `move` is a unit axis and the parts leave to infinity along it ("+z out"): they
 * form a sub-assembly of their own, and later steps move parts within one sub-assembly, checked
 * against the other parts of that same sub-assembly only.
 */
export interface DisassemblyStep {
  /** Part ids moved together, ascending. */
  parts: number[];
  /** Direction times voxels ([0, 0, -2]: two voxels along -z); a unit axis when `out`. */
  move: [number, number, number];
  /** A separation: the parts go out to infinity along `move`. */
  out: boolean;
  /** Mesh plans: a finite move's length in mm (`move` is then in mm), its direction label and unit vector. */
  length?: number;
  dir?: string;
  vector?: [number, number, number];
}

/**
 * A disassembly that takes every part apart. Plans from contacts alone (contact documents, plate
 * and frame plans) have only `order` and `paths`; voxel plans add their moves and level.
 */
export interface Disassembly {
  /**
   * The parts in the order they come free (the last one stays). With `paths` null this is only
   * an order: `steps` is the plan.
   */
  order: number[];
  /**
   * One path per part of `order` (the last one empty): each part taken out alone, the others
   * standing still. null when the plan needs parts moved together.
   */
  paths: Move[][] | null;
  /**
   * Voxel plans: the disassembly level in BurrTools' notation, [98, 2, 5] written "98.2.5": the
   * moves up to and including the first separation, then those of the separations below it (in
   * pre-order) where a sub-assembly needs more than one move to come apart.
   */
  level?: number[];
  /**
   * True when the plan was found breadth-first, so that no plan needs fewer moves before each
   * separation; false when it was found otherwise (`limit` then says which search limit stopped
   * the breadth-first search).
   */
  levelMinimal?: boolean;
  /** The number of moves of `steps` (separations included). */
  moves?: number;
  /**
   * Voxel plans: the whole plan, move by move. When `paths` is not null both plans are valid;
   * `steps` may then be a different plan with fewer moves, or the same one, move by move.
   */
  steps?: DisassemblyStep[];
  /** Which search limit was reached, in words (absent when none was). */
  limit?: string;
}

/** Why no disassembly was found (CheckReport.disassemblyFailure). */
export interface DisassemblyFailure {
  /** Parts removed (come free) before the plan stopped, in order. */
  removed: number[];
  /** Every part not removed. */
  stuck: number[];
  /** A search stopped at its work limit: `stuck` is not proven (see `limit`). */
  searchLimitReached: boolean;
  /**
   * Voxel plans that moved parts together: the parts still together when the plan stopped, one
   * list per sub-assembly (e.g. [[1, 2, 3]]: parts 1, 2 and 3 are stuck together).
   */
  unseparated?: number[][];
  /** With `unseparated`: the level of the moves made, as in {@link Disassembly.level}. */
  level?: number[];
  /** With `unseparated`: the moves made before the plan stopped (a partial plan to replay). */
  steps?: DisassemblyStep[];
  /** Which search limit was reached, in words. */
  limit?: string;
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
  kind: 'voxel' | 'plate' | 'frame' | 'contacts' | 'mesh';
  method: CheckMethod;
  /** Empty when there are more than 128 base directions and `graphs` was not asked for. */
  baseDirections: { label: string; vector: [number, number, number] }[];
  /** The number of base directions, listed or not. */
  baseDirectionCount: number;
  /** Same rule as baseDirections. */
  graphs: BlockingGraph[];
  /** True when baseDirections and graphs were left out for their number. */
  graphsOmitted: boolean;
  /** Per-method verdicts when method is 'both'. */
  methods?: { dbg: Verdict; lp: Verdict };
  /**
   * How every part comes free; null when no disassembly was found (then see disassemblyFailure).
   * Voxel assemblies add the moves of the plan (`level`, `levelMinimal`, `moves`, `steps`).
   */
  disassembly: Disassembly | null;
  /**
   * When no disassembly was found: the parts removed before getting stuck, the stuck ones, and
   * whether a search stopped at its work limit (then "stuck" is not proven). A voxel plan that
   * needed parts moved together adds the moves made before it stopped.
   */
  disassemblyFailure?: DisassemblyFailure;
  /**
   * Plate results with cut or milled joints and frame results: their removal plan replayed on the
   * real shapes (plates: contacts recomputed from the jointed plates and each plate swept; frames:
   * each beam and its joint voxels swept along its axis). `failure` names the part that cannot
   * leave; absent for other documents.
   */
  shapeRemoval?: { checked: string; clear: boolean; failure: string };
  /**
   * Mesh assemblies (kind 'mesh'): the contact tolerance in force and the model's bounding-box
   * diagonal (mm), the planar faces, contacts and triangles found, and the parts' names (OBJ
   * objects or groups, STL solids or files) in the order of partIds.
   */
  mesh?: {
    tolerance: number; diagonal: number; planarFaces: number; contacts: number; triangles: number; partNames: string[];
    /** Curved contact regions (a pin in a hole), approximated by their planar facets (docs/meshes.md). */
    curvedContacts: { parts: [number, number]; facets: number; area: number }[];
  };
}

/**
 * A mesh assembly (docs/meshes.md): closed triangle meshes drawn elsewhere, one part per OBJ
 * object or group, per STL file or ASCII STL solid. `check` of it is `desia check FILES --json`.
 */
export interface MeshDocument {
  /** The files; `name` is the file name (its extension, .obj or .stl, chooses the reader). */
  files: ({ name: string; bytes: MeshInput } | { name: string; text: string })[];
  /** The files' unit: 'mm' (default), 'm' or 'inch'. */
  unit?: 'mm' | 'm' | 'inch';
  /** mm: faces this close touch; 0 or absent = 1e-5 of the model's bounding-box diagonal. */
  tolerance?: number;
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
  /** Plate design results: how the joints were made. */
  jointGeometry?: PlateJointGeometry;
  /** Plate design results: a joint per pair of touching plates (part ids). */
  joints?: { mover: number; other: number; type: PlateJointType; direction: [number, number, number] }[];
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

/** Options every call of the promise-based API ({@link Desia}) accepts besides its own. */
export interface CallOptions {
  /**
   * Aborts the call. Already aborted: the call rejects at once. Aborted while the call runs in the
   * worker: the worker is terminated at once (any design sessions in it are lost), the call
   * rejects with `signal.reason` (a DOMException named 'AbortError' when `abort()` was called
   * without a reason, as with fetch) and the next call starts a fresh worker. Aborted while the call
   * waits behind another one: it is simply dropped. With `{ worker: false }` a running call blocks
   * the thread, so an abort takes effect before the call starts, or (for designs) when `abort()`
   * is called from inside `onProgress`: the search then stops at its next node.
   */
  signal?: AbortSignal;
}

/** The promise-based designVoxel's portfolio of seeds (`desia design voxel --jobs`). */
export interface PortfolioOptions {
  /**
   * Searches at once (default 1), each in a worker of its own with seeds seed, seed + 1, ...; at
   * most navigator.hardwareConcurrency (node: os.availableParallelism()), and one with
   * `{ worker: false }`. The first verified puzzle wins and the other workers are terminated; the
   * result's `seed` names the winner, and `onProgress` sees the deepest search. The caller's own
   * worker (and its design sessions) is not used. Limits apply to each search.
   */
  jobs?: number;
  /**
   * Live design (default false): every snapshot a progress value delivers also carries
   * `surfaces`, the part surfaces of the deepest node (as partSurfaces gives them), made in the
   * worker beside the search at most four times a second (a snapshot in between rides on a
   * later value), so that the caller's thread only draws them. The playground draws with it.
   */
  liveSurfaces?: boolean;
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
  /** Smallest part in voxels, the key and the last remainder included (default: a quarter of voxels / N, at least 2). */
  minPartSize?: number;
  /** Largest part in voxels (default: none). Bounds no N parts can meet are a 'bad-input' DesiaError. */
  maxPartSize?: number;
  /**
   * Even parts: every part between floor(mean) - t and ceil(mean) + t voxels, mean = voxels / N,
   * t = max(1, floor(0.2 * mean)); combined with minPartSize / maxPartSize.
   */
  evenParts?: boolean;
  /** Seconds; 0 or absent: none. */
  timeLimit?: number;
  nodeLimit?: number;
  /** The key's only free direction (default '+y'). */
  keyDirection?: '+x' | '-x' | '+y' | '-y' | '+z' | '-z';
  /** Appearance constraints: voxel coordinates [x, y, z] that must end up in one part. */
  groups?: [number, number, number][][];
  /**
   * Progress of the search. The synchronous core ({@link DesiaCore.designVoxel}) calls it after
   * every visited node, and returning false stops the search (status 'cancelled'). The
   * promise-based API ({@link Desia.designVoxel}) calls it about ten times a second, always with
   * the final progress before the promise resolves; its return value is ignored (use `signal`).
   */
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
  /**
   * designVoxel with `jobs` > 1: the seed of the deepest search, whose depths these are
   * (`nodesVisited` counts the nodes of all searches).
   */
  seed?: number;
  /**
   * Live design: the deepest node found so far, present only on a progress value whose deepest
   * node is deeper than the last one delivered (so at most once per new depth; the promise-based
   * API keeps one that falls between two of its deliveries for the next). Taken from the search,
   * never fed back: the same seed gives the same result with or without a listener.
   */
  snapshot?: VoxelSnapshot | PlacedSnapshot;
}

/** designVoxel's snapshot: the deepest node as voxel labels. */
export interface VoxelSnapshot {
  /** Parts placed: labels 1..depth are parts 1..depth (part 1 the key), depth + 1 the remainder. */
  depth: number;
  /**
   * One label per cell of the shape's grid in the order of the document's `voxel.labels` (x
   * fastest), 0 outside the shape: the shape's document with these labels is an assembly that
   * partSurfaces and check take.
   */
  labels: Int32Array;
  /** With `liveSurfaces`: the part surfaces of the shape with these labels (moved, not copied). */
  surfaces?: PartSurface[];
}

/** designPlate's and designFrame's snapshot: the plates or beams of the deepest node. */
export interface PlacedSnapshot {
  /** Plates or beams taken: `placed.length`. */
  depth: number;
  /** Their indices in the input's `plates` or `beams` (0-based), in the order taken (the key first). */
  placed: number[];
}

export interface DesignResult {
  /** 'cut-point' (designPlate, designFrame): the parts-graph has a cut point, named in `message`. */
  status: 'success' | 'not-found' | 'limit-reached' | 'cancelled' | 'cut-point';
  message: string;
  progress: DesignProgress;
  /**
   * designVoxel: the seed of the search that gave this result. With `jobs` > 1 the winner's:
   * designVoxel with `{ seed }` and one worker gives the same puzzle byte for byte.
   */
  seed?: number;
  /** designVoxel on success: the part sizes in voxels, smallest, largest and mean (voxels / N); else null. */
  partSizes?: { min: number; max: number; mean: number } | null;
  /** The verified puzzle as .puz text (part 1 = key), or null (always null for plates and frames). */
  puz: string | null;
  /** The verified puzzle as a JSON assembly document, or null. */
  document: AssemblyDocument | null;
  /** The check that verified it (the same fields as `desia check --json`), or null. */
  verification: CheckReport | null;
  /**
   * designPlate with status 'cut-point': the repair the core proposes (bars that bypass the cut
   * point, paper Fig. 18) as a plate design to open and design, or null when none was found.
   */
  repair?: { message: string; document: AssemblyDocument } | null;
}


/** The current node of a design session. */
export interface DesignSessionState {
  /** Parts in the current assembly (placed parts plus the remainder). */
  partsPlaced: number;
  targetParts: number;
  /**
   * True when the assembly has all its parts (plates, frames: every part placed and the design
   * verified).
   */
  complete: boolean;
  /**
   * Voxels: the current assembly. Plates, frames: the verified result document once complete, else
   * the input design or frame.
   */
  document: AssemblyDocument;
  /**
   * Plates: the plates taken so far (input ids, the key first) and the direction each leaves along.
   * Frames: the same with `beam` for the beams taken.
   */
  steps?: ({ plate: number; direction: [number, number, number] } | { beam: number; direction: [number, number, number] })[];
  /** Plates, frames: how far the session got, or the result's message once complete. */
  message?: string;
}

/** The joint between two plates ('dovetail': a sliding dovetail; 'mitre-tenon': a tenon across a mitre into a pocket, paper Fig. 16a; both made with joints 'milled'). */
export type PlateJointType = 'mortise-tenon' | 'halved' | 'dovetail' | 'mitre-tenon' | 'mitre-slide' | 'face-tenon' | 'step-tenon' | 'slanted-tenon' | 'slanted-dovetail' | 'inplane-dovetail' | 'through-slot' | 'empty';

/** How a plate design result's joints were made: its `jointGeometry` (see {@link PlateDesignOptions.joints}). */
export type PlateJointGeometry = 'cut' | 'milled' | 'planned';

/** Plates: a child of a session's node, the plate it takes and the joints it gets (input ids). */
export interface PlateSessionStep {
  plate: number;
  direction: [number, number, number];
  joints: { mover: number; other: number; type: PlateJointType; direction: [number, number, number] }[];
}

/**
 * Frames: a child of a session's node, the beam it takes, the axis it leaves along and the free
 * voxels it takes in the joint cubes at its two ends (input ids; voxels 0..26, x fastest).
 */
export interface FrameSessionStep {
  beam: number;
  direction: [number, number, number];
  joints: { joint: number; voxels: number[] }[];
}

/**
 * Step-by-step design with the synchronous core (the original tool's "Generate Next Part",
 * "Child Index" and "Go Back"). Holds WebAssembly memory until dispose() is called.
 */
export interface DesignSession {
  /** The current assembly: partsPlaced counts its parts (placed parts plus the remainder). */
  state(): DesignSessionState;
  /** The number of ranked children of the current node (generated on first call). */
  childCount(): number;
  /**
   * The assembly the n-th child (0 = best ranked) would give. `n` must be an integer from 0 to
   * 2^31 - 1 (else a DesiaError 'bad-input'); a child that does not exist is one too.
   */
  /** Voxels: the assembly the n-th child would give. Plates, frames: the n-th child's step. */
  preview(n: number): AssemblyDocument | PlateSessionStep | FrameSessionStep;
  /** Moves to the n-th child (`n` as for preview). */
  choose(n: number): void;
  /** Moves to the best-ranked child; false when the node has none (go back). */
  next(): boolean;
  /** Moves to the parent; false at the root. */
  back(): boolean;
  /** The check report of the current assembly. */
  check(): CheckReport;
  /**
   * "Finish automatically from here": the designer's search (restarts, verification) below the
   * current node, so the parts placed so far stay as chosen, in order (a plate or frame session:
   * the plates or beams taken so far first in the order, with their directions; the result as
   * designPlate's or designFrame's). The session does not move. The same
   * path and seed give the same result.
   */
  finish(options?: SessionFinishOptions & { onProgress?: (progress: DesignProgress) => boolean | void }): DesignResult;
  /** Frees the session; later calls throw. */
  dispose(): void;
}

/** The limits of a session's finish(): as designVoxel's (0 or absent: none). */
export interface SessionFinishOptions {
  /** Seconds (>= 0). */
  timeLimit?: number;
  /** Search nodes (>= 0). */
  nodeLimit?: number;
}

/**
 * Step-by-step design with the promise-based API: the same methods as {@link DesignSession},
 * each forwarded to the session, which lives in the worker. When that worker is stopped (an
 * aborted call, terminate() or a crash), every method rejects with a DesiaError with code
 * 'session-lost' (dispose() then simply resolves).
 */
export interface AsyncDesignSession {
  state(): Promise<DesignSessionState>;
  childCount(): Promise<number>;
  preview(n: number): Promise<AssemblyDocument | PlateSessionStep | FrameSessionStep>;
  choose(n: number): Promise<void>;
  next(): Promise<boolean>;
  back(): Promise<boolean>;
  check(): Promise<CheckReport>;
  /**
   * As {@link DesignSession.finish}, in the worker, with progress about ten times a second. An
   * abort terminates the worker, so the session is lost with it (start a new one).
   */
  finish(options?: SessionFinishOptions & { onProgress?: (progress: DesignProgress) => void; signal?: AbortSignal }): Promise<DesignResult>;
  /** Frees the session in the worker; later calls reject with code 'bad-input'. */
  dispose(): Promise<void>;
}

/**
 * Export formats: 'stl' (binary STL), 'stl-ascii', 'obj' (Wavefront OBJ, one object per part) and
 * 'xmpuzzle' (BurrTools, voxel puzzles only, with desia's assembly and disassembly as a saved
 * solution).
 */
export type ExportFormat =
  | 'stl' | 'stl-ascii' | 'obj' | 'xmpuzzle' | 'svg' | 'dxf' | 'fpuz' | 'csv'
  /** Voxel assemblies: a ZIP (stored) of one binary STL per part, `part-01.stl`, ..., each part lying flat on z = 0. */
  | 'stl-zip'
  /** Voxel assemblies: one binary STL with every part turned onto its largest layer and laid out on z = 0, `spacing` apart. */
  | 'build-plate-stl'
  /** Frames: every beam body and glued joint piece its own OBJ object, in place. */
  | 'pieces-obj'
  /** Frames: the joint pieces alone, laid out on z = 0 to print and glue. */
  | 'joint-pieces-stl';

export interface ExportOptions {
  /** The file format (default 'stl'). */
  format?: ExportFormat;
  /** 0 (default): every part; k: only part k. */
  part?: number;
  /** Model units per voxel edge for voxel assemblies (default 1), e.g. mm for printing. */
  voxelSize?: number;
  /**
   * Voxel meshes (stl, stl-ascii, obj, stl-zip, build-plate-stl): every face of a part against
   * another part moves in by this much (same units as voxelSize; 0 to below half a voxel; default
   * 0), so touching parts print with a gap of twice the clearance; faces against empty space stay.
   */
  clearance?: number;
  /** Name used in error messages. */
  source?: string;
  /** 'svg' and 'dxf' only: which sheet (default 0); the other cut sheet options as for cutSheets. */
  sheetIndex?: number;
  sheet?: string;
  kerf?: number;
  /** 'svg' and 'dxf': as for cutSheets; 'build-plate-stl': the gap between the parts' boxes (default one voxel). */
  spacing?: number;
  hairline?: boolean;
}

/** Options of cutSheets: the cut files of a plate structure. */
export interface CutSheetOptions {
  /** 'svg' (default; true size in mm, red outer cuts, blue inner cuts, black engraving) or 'dxf' (R12, mm, one layer each). */
  format?: 'svg' | 'dxf';
  /** 'WIDTHxHEIGHT' in mm, e.g. '600x400' (default: one sheet as large as the plates need). */
  sheet?: string;
  /** mm the cutter removes: outlines move out and holes in by half of it (0 to 5, default 0). */
  kerf?: number;
  /** mm between plates and from the sheet's edges (default 5). */
  spacing?: number;
  /** SVG strokes 0.01 mm wide, for lasers that cut hairlines only (default false: 0.1 mm). */
  hairline?: boolean;
  /** Name used in error messages. */
  source?: string;
}

/**
 * The surface of one part of a voxel assembly, ready to draw (e.g. as a three.js BufferGeometry
 * with `position` and `normal` attributes and no index): the triangles of the part's STL/OBJ
 * export, one square per voxel face against empty space, another part or the grid's border.
 */
export interface PartSurface {
  /** The part's id (labels 1 to N of the document). */
  partId: number;
  /** Non-indexed triangles: 9 floats (3 vertices x, y, z) each, counter-clockwise seen from outside, in voxel units. */
  positions: Float32Array;
  /** One outward unit axis normal per vertex, the same for the 3 vertices of a triangle (flat shading). */
  normals: Float32Array;
}

/** Options of designPlate. */
export interface PlateDesignOptions {
  /** Default 1: the same seed gives the same plan, natively and in WebAssembly. */
  seed?: number;
  /** Children kept per node of the construction tree (the paper's m), default 30. */
  candidates?: number;
  nodeLimit?: number;
  /** Seconds, default 60. */
  timeLimit?: number;
  /**
   * 'auto' (default): 'cut' if a plan with cut joints exists, else 'milled', else 'planned', within
   * one time limit; the result's `jointGeometry` is the one used and its message says why (first
   * line `joints: milled (no laser-cut plan: …)`). Step by step, 'auto' steps with cut joints.
   * 'cut': joints cut into the plates (through and open mortise-and-tenon joints where a
   * square edge stands on a face at a right angle), verified on the jointed plates. 'planned': the
   * paper's graph design alone (halved, mortise-and-tenon or empty joints by angle), verified on
   * the joints' model contacts; nothing to cut. 'milled': as 'cut', and where no mortise-and-tenon
   * lets a plate out, a sliding dovetail along its square edge (paper Fig. 2, right; joint type
   * 'dovetail'), for a CNC: the jointed plates carry `attached` solids (the tongue, the housing's
   * lips), drawn by partSurfaces and written by the STL and OBJ exports, verified on those shapes
   * (`jointGeometry: 'milled'`). Cut sheets (SVG, DXF) cannot hold a dovetail and refuse such a
   * result.
   */
  joints?: 'auto' | 'cut' | 'milled' | 'planned';
  /** mm of play between a tenon and its mortise, cut into `fabricationPlates` (0 to 10, default 0). */
  clearance?: number;
  /** mm along the edge (default: from the edge's length). */
  tenonWidth?: number;
  /** Tenons per joint, 1 to 20 (default: 1, or 2 on edges longer than 8 thicknesses). */
  tenonCount?: number;
  /**
   * Each joint family's sizes, e.g. `{ dovetail: { slope: 0.2, stop: 12 }, stepTenon: { width: 0.25 } }`
   * (shares of a length as numbers: 0.25 = a quarter); the names, meanings and ranges are in
   * docs/plates.md ("Joint sizes"). Unknown names and values out of range throw.
   */
  jointSizes?: Record<string, Record<string, number>>;
  onProgress?: (progress: DesignProgress) => boolean | void;
  /** Name used in error messages. */
  source?: string;
}

/** Options of designFrame (the same as `desia design frame`'s flags). */
export interface FrameDesignOptions {
  /** Default 1: the same seed gives the same result document, natively and in WebAssembly. */
  seed?: number;
  /** Children kept per node of the construction tree (the paper's m), default 2. */
  candidates?: number;
  nodeLimit?: number;
  /** Seconds, default 60; 0 = none. */
  timeLimit?: number;
  /** Edge of a joint cube in the frame's units (default: the file's, else from the geometry). */
  jointSize?: number;
  onProgress?: (progress: DesignProgress) => boolean | void;
  /**
   * Name used in error messages; its extension picks the input format: '.obj' (lines and face
   * edges are beams), '.fpuz' (FrameInterlock), otherwise a JSON document of kind 'frame'.
   */
  source?: string;
}

/** Options of parseFrame. */
export interface ParseFrameOptions {
  /** Name used in error messages; '.obj' and '.fpuz' pick those formats, otherwise JSON. */
  source?: string;
  /** Edge of a joint cube in the frame's units; 0 (default) = the file's or from the geometry. */
  jointSize?: number;
}

export interface StructureDesignOptions {
  onProgress?: (progress: DesignProgress) => boolean | void;
  /** Name used in error messages. */
  source?: string;
  [option: string]: unknown;
}

/**
 * The synchronous core, for workers and node scripts ({@link loadDesiaModule}). Every method
 * throws a DesiaError for bad input. Options are undefined or a plain object; anything else, and
 * any option name a function does not know, is a DesiaError with code 'bad-input' (the designers'
 * option names are checked by the core).
 */
export interface DesiaCore {
  /**
   * The interlocking check of .puz or JSON text, or of a mesh assembly ({@link MeshDocument}); the
   * same fields as `desia check --json` (of the mesh files). Errors in a mesh name the file and line,
   * or the part and what is wrong with it (open, self-intersecting, overlapping another).
   */
  check(text: string | MeshDocument, options?: CheckOptions): CheckReport;
  /** Parses .puz or JSON text into the JSON assembly document. */
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
  /**
   * An assembly (.puz text, JSON text or a document object) as a file for other tools: STL or OBJ
   * meshes of its parts (3D printing; with a `clearance`, as a ZIP of one STL per part or all parts
   * on a build plate), or a BurrTools .xmpuzzle; a frame also as FrameInterlock '.fpuz' or its
   * 'csv' cut list (both need designed joints). Returns the file's bytes. Throws a DesiaError
   * ('bad-input') for a clearance of half a voxel or more, naming the value.
   */
  exportAssembly(assembly: string | AssemblyDocument, options?: ExportOptions): Uint8Array;
  /**
   * The cut files of a plate structure (a design result: its `fabricationPlates` when it has a
   * clearance, else its `plates`): one SVG or DXF text per sheet, the plates laid flat, turned to
   * their smallest box and nested. Throws a DesiaError naming a plate that fits no sheet, or a
   * plate with milled joints (`jointGeometry: 'milled'`: a sliding dovetail is no 2D cut; export
   * STL or OBJ for the CNC instead).
   */
  cutSheets(assembly: string | AssemblyDocument, options?: CutSheetOptions): string[];
  /**
   * The surface of every part of an assembly (.puz text, JSON text or a document object), in
   * increasing part id, computed by the core from the same faces as the STL/OBJ export: voxels in
   * voxel units, plates and frames in their model units (a frame without designed joints: its
   * beams, then its bare joint cubes as part 0). Throws a DesiaError ('bad-input') for a voxel
   * document without voxels, as the export does. Of a {@link MeshDocument}: each part's triangles in
   * millimetres with flat normals (part ids as `check` numbers them).
   */
  partSurfaces(assembly: string | AssemblyDocument | MeshDocument, options?: { source?: string }): PartSurface[];
  /**
   * Designs an N-part interlocking voxel puzzle from a shape (.puz or JSON text). `puz` and
   * `document` are set when status is 'success' (the puzzle passed the project's own check);
   * otherwise they are null and `message` says how far the search got.
   */
  designVoxel(shapeText: string, options: DesignVoxelOptions): DesignResult;
  /** An interactive design session; call dispose() when done. */
  /**
   * An interactive design session for a voxel shape (options as designVoxel's) or a plate design
   * (options as designPlate's: a choice that completes the plan is accepted only if it verifies,
   * else choose() throws with the reason and that child is dropped) or a frame (JSON, or .fpuz /
   * OBJ text with `source` naming the extension; options as designFrame's, verified the same way;
   * a frame with a cut-point beam throws naming it).
   */
  designSession(
    shapeText: string,
    options: Omit<DesignVoxelOptions, 'onProgress'> | Omit<PlateDesignOptions, 'onProgress'> | Omit<FrameDesignOptions, 'onProgress'>,
  ): DesignSession;
  /**
   * Designs the joints of a plate design (paper Section 5.2: key, removal order and directions, a
   * joint per pair of touching plates). The result's `document` (kind 'plate', part 1 = the key)
   * holds the plates with their tenons and mortises cut (`jointGeometry: 'cut'`; with
   * `joints: 'milled'`, also sliding dovetails whose solids are the plates' `attached`, and
   * `jointGeometry: 'milled'`; with `joints: 'planned'`, the plates as given and
   * `jointGeometry: 'planned'`), verified by both tests and, when cut or milled, by sweeping each
   * plate out past the ones still in place. Its `joints` list `{ mover, other, type, direction }`
   * with `type` a {@link PlateJointType}.
   */
  designPlate(input: string | AssemblyDocument, options?: PlateDesignOptions): DesignResult;
  /**
   * Designs the 3x3x3 voxel joints of a frame structure (paper Section 5.3). `input`: a frame
   * document (JSON text or object), or OBJ / .fpuz text named by `source`. The result's `document`
   * (kind 'frame': beams renumbered in removal order, part 1 = the key, `jointVoxels`, `removal`)
   * is byte for byte the document `desia design frame` writes for the same seed; `verification`
   * is its DBG check. A frame whose beams' graph has a cut point gives status 'cut-point'.
   */
  designFrame(input: string | AssemblyDocument, options?: FrameDesignOptions): DesignResult;
  /**
   * A frame from a JSON document, OBJ (lines and face edges) or .fpuz text as its checked JSON
   * document (kind 'frame'), ready for partSurfaces and designFrame. Throws a DesiaError naming the
   * joint and beams of an invalid frame.
   */
  parseFrame(input: string | AssemblyDocument, options?: ParseFrameOptions): AssemblyDocument;
  /** Every file format exportAssembly writes, from the core's registry (the CLI's `export` asks the same). */
  exportFormats(): ExportFormatInfo[];
  /** The core's version, e.g. '0.1.0'. */
  version(): string;
  /** The module this core runs. */
  module(): ModuleName;
}

/** One export format of the core's registry. */
export interface ExportFormatInfo {
  /** The `format` exportAssembly takes, e.g. 'stl', 'svg', 'fpuz'. */
  name: string;
  /** The assemblies it exports. */
  kinds: Array<'voxel' | 'plate' | 'frame'>;
  /** The options it reads ('part', 'voxelSize', 'clearance', 'spacing', 'sheet'); others are refused or ignored. */
  options: Array<'part' | 'voxelSize' | 'clearance' | 'spacing' | 'sheet'>;
  /** One file per sheet (cut files: exportAssembly returns sheet `sheetIndex`, cutSheets all). */
  perSheet: boolean;
  /** One line about the format. */
  what: string;
}

/** Options of {@link createDesia}. */
export interface CreateOptions extends LoadOptions {
  /**
   * 'light-first' (default): the worker loads the light module and, the first time a call is
   * about a plate or a frame, the full one, which then answers every call (same API, same
   * results). 'full': only the full module, at once.
   */
  modules?: 'light-first' | 'full';
  /**
   * URL (browser) or file path (node) of `desia_light.wasm` (default: the package's). A `wasmUrl`
   * without it, or a `wasmBinary`, names only the full module: only that one is loaded.
   */
  lightWasmUrl?: string | URL;
  /**
   * true (default): the core runs in a worker (a module Web Worker in browsers, a worker_threads
   * Worker in node), so long calls never block the caller and an AbortSignal stops them at once.
   * false: the core runs in the calling thread (e.g. where workers are not allowed); the API is
   * the same, but a running call blocks the thread, so aborting works only before a call starts
   * or from inside a design's onProgress.
   */
  worker?: boolean;
  /**
   * Where the package's worker script (`wasm/worker.js`) is, when a bundler or a CDN moved it. In
   * browsers it must be same-origin with the page (a rule of Web Workers).
   */
  workerUrl?: string | URL;
  /**
   * Milliseconds a worker may take to load the core (default 30000). A worker that has not
   * loaded it by then is stopped and the pending call (createDesia itself, at first) rejects with
   * a fatal DesiaError (code 'internal').
   */
  startTimeout?: number;
}

/**
 * The promise-based API, the same in browsers and node. Calls run one at a time, in the order
 * they were made; each accepts a `signal` (see {@link CallOptions}). Bad input rejects with a
 * {@link DesiaError} carrying the core's message (the same text as the CLI's) and its `code`.
 * In node an idle worker does not keep the process alive; a crashed worker fails the call it
 * was running (code 'internal', `fatal` true) and is replaced by the next call.
 */
export interface Desia {
  /** The interlocking check of .puz or JSON text or of a mesh assembly; see {@link DesiaCore.check}. */
  check(text: string | MeshDocument, options?: CheckOptions & CallOptions): Promise<CheckReport>;
  /** Parses .puz or JSON text into the JSON assembly document. */
  parseDocument(text: string, options?: { source?: string } & CallOptions): Promise<AssemblyDocument>;
  /**
   * Solid voxelization of a closed OBJ / STL mesh; see {@link DesiaCore.voxelize}. The bytes are
   * copied once and the copy is moved to the worker: the caller's buffer stays usable.
   */
  voxelize(mesh: MeshInput, options?: VoxelizeOptions & CallOptions): Promise<AssemblyDocument>;
  /** A voxel assembly as DESIA .puz text; see {@link DesiaCore.toPuz}. */
  toPuz(assembly: string | AssemblyDocument, options?: { source?: string } & CallOptions): Promise<string>;
  /** An assembly as an STL, OBJ or BurrTools file; see {@link DesiaCore.exportAssembly}. */
  exportAssembly(assembly: string | AssemblyDocument, options?: ExportOptions & CallOptions): Promise<Uint8Array>;
  /** The cut files of a plate structure, one text per sheet; see {@link DesiaCore.cutSheets}. */
  cutSheets(assembly: string | AssemblyDocument, options?: CutSheetOptions & CallOptions): Promise<string[]>;
  /**
   * The surface of every part of a voxel assembly, ready to draw; see
   * {@link DesiaCore.partSurfaces}. The float arrays are moved out of the worker, not copied.
   */
  partSurfaces(assembly: string | AssemblyDocument | MeshDocument, options?: { source?: string } & CallOptions): Promise<PartSurface[]>;
  /**
   * Designs an N-part interlocking voxel puzzle; resolves to the same object as
   * {@link DesiaCore.designVoxel} (byte-identical `.puz` for the same seed). `onProgress` is
   * called about ten times a second and once more with the final progress before the promise
   * resolves.
   */
  designVoxel(shapeText: string, options: DesignVoxelOptions & PortfolioOptions & CallOptions): Promise<DesignResult>;
  /** An interactive design session living in the worker; dispose() it when done. */
  designSession(
    shapeText: string,
    options: (Omit<DesignVoxelOptions, 'onProgress'> | Omit<PlateDesignOptions, 'onProgress'> | Omit<FrameDesignOptions, 'onProgress'>) & CallOptions,
  ): Promise<AsyncDesignSession>;
  /** {@link DesiaCore.designPlate} in the worker. */
  designPlate(input: string | AssemblyDocument, options?: PlateDesignOptions & CallOptions): Promise<DesignResult>;
  /** {@link DesiaCore.designFrame} in the worker. */
  designFrame(input: string | AssemblyDocument, options?: FrameDesignOptions & CallOptions): Promise<DesignResult>;
  /** {@link DesiaCore.parseFrame} in the worker. */
  parseFrame(input: string | AssemblyDocument, options?: ParseFrameOptions & CallOptions): Promise<AssemblyDocument>;
  /** {@link DesiaCore.exportFormats} in the worker. */
  exportFormats(options?: CallOptions): Promise<ExportFormatInfo[]>;
  /** The core's version, e.g. '0.1.0' (known since createDesia resolved). */
  version(): string;
  /** The WebAssembly modules loaded so far: ['light'], then ['light', 'full'] once a plate or frame came; ['full'] with modules 'full'. */
  modules(): ModuleName[];
  /**
   * Ends the worker (in-process: drops the module). Pending calls reject with code 'terminated'
   * and design sessions are lost; a later call starts a fresh worker, so terminate() is also how
   * to free the worker's memory between bursts of work.
   */
  terminate(): Promise<void>;
}

/** Error thrown for bad input (with the core's message, naming file, line and value) and failures. */
export class DesiaError extends Error {
  constructor(message: string, code?: ErrorCode, options?: { fatal?: boolean });
  readonly name: 'DesiaError';
  readonly code: ErrorCode;
  /**
   * True when the WebAssembly instance trapped (e.g. out of memory) or the worker died: with
   * createDesia the next call runs in a fresh worker; with loadDesiaModule load a new module.
   */
  readonly fatal: boolean;
}

/**
 * Loads the WebAssembly module in the calling thread and returns the synchronous core: for use
 * inside a worker of your own, or in node scripts that need nothing asynchronous.
 */
export function loadDesiaModule(options?: LoadModuleOptions): Promise<DesiaCore>;

/**
 * The promise-based API (see {@link Desia}); resolves once the core is loaded in its worker.
 *
 * ```js
 * import { createDesia } from 'desia';
 * const desia = await createDesia();
 * const report = await desia.check(puzText);
 * const controller = new AbortController();
 * const result = await desia.designVoxel(shapeText, { parts: 7, seed: 1, signal: controller.signal,
 *   onProgress: (p) => console.log(p.bestDepth, 'of', p.targetParts) });
 * ```
 */
export function createDesia(options?: CreateOptions): Promise<Desia>;
