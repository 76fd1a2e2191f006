// Types of scantrace's JavaScript API (scantrace.mjs; docs/web.md).

/** JSON text of a scene file, a parsed scene object, or a named file (".obj": a model). */
export type SceneInput = string | object | { name: string; data: string | Uint8Array };

/** The CLI's fill flags, same names and values (missing: the CLI's defaults). Each option's
 * names are those of its table in src/option_table.hpp, which the module parses them with; read
 * them, and the defaults, at run time from Scantrace.optionTable() (winding: winding_rule's
 * names, depth: visibility's). They are typed as strings rather than a union of names written
 * here, so a name is spelled only in that table; web/tests/node_options.mjs holds
 * optionTable() to the command's choices. */
export interface FillOptions {
  shading?: string;
  fill_rule?: string;
  subpixel_bits?: number;
  method?: string;
  winding?: string;
  cull?: string;
  depth?: string;
  clamp_colors?: boolean;
}

export interface TraceOptions extends FillOptions {
  /** One of optionTable().level.names. */
  level?: string;
  triangles?: number[];
  max_events?: number;
  /** Record the trace in memory and keep it for frames(null, …) (the same events and text). */
  keep?: boolean;
  /** false, with keep: no JSON Lines written (traceText returns ''); keptStep reads the trace. */
  text?: boolean;
  /** `trace --max-bytes`: the text's byte cap (1 GiB, lowered to the longest JavaScript string;
   * 1024 to 2^50); past it the text ends with a footer saying truncated, and lastWarning says so. */
  max_bytes?: number;
}

/** One option's table (src/option_table.hpp): its names, in the command's order, and its default. */
export interface OptionTableEntry {
  names: string[];
  default: string;
}

export interface KeptStep {
  /** The kept trace's event count. */
  events: number;
  /** The face's edge_table event and its scanline event of the row, or null. */
  edge_table: TraceEvent | null;
  scanline: TraceEvent | null;
}

export type TraceInput =
  | { scene: SceneInput }
  | { triangle: [number, number][]; colors?: [number, number, number][]; width?: number; height?: number }
  | { polygon: [number, number][][]; colors?: [number, number, number][]; width?: number; height?: number };

/** One JSON Lines event of trace format v1 (trace/trace_schema.json). */
export interface TraceEvent {
  event: string;
  [key: string]: unknown;
}

export interface Rendered {
  width: number;
  height: number;
  /** Row-major RGBA, 8 bits a channel: the pixels of `scantrace render`'s PNG. */
  rgba: Uint8ClampedArray;
  faces: number;
  /** The fill's time inside the module, in milliseconds. */
  ms: number;
}

export interface FrameStep {
  kind: string;
  triangle: number;
  first_row: number;
  last_row: number;
}

/** A display list in the canvas JSON of viz/frame_json.hpp, for drawScantraceFrame. */
export interface CanvasFrame {
  w: number;
  h: number;
  bg: string;
  ops: unknown[];
  /** Text as "G" ops: glyph id's strokes ([dx, dy, dx, dy, …] each) relative to its origin
   * (Float64Arrays with encoding: 'binary'). */
  glyphs?: (number[] | Float64Array)[][];
}

export interface FrameOptions {
  width?: number;
  height?: number;
  first?: number;
  count?: number;
  rows_per_step?: number;
  source?: string;
  /** 'rgba': each pixel block ("P" op) ends with a RunsBlock, which drawScantraceFrame draws at
   * once; 'png' (default): a PNG data URI, loaded asynchronously. */
  blocks?: 'png' | 'rgba';
  /** 'binary': each frame handed over as numbers, not JSON text, and read back into the same
   * frame (its blocks as with blocks: 'rgba'; the lists of numbers of its "G" ops, glyphs and
   * blocks as Float64Arrays); what the explorer does on every mouse move. 'json' (default). */
  encoding?: 'json' | 'binary';
  /** The byte cap of the result (as TraceOptions.max_bytes); past it, a ScantraceError. */
  max_bytes?: number;
}

/** A frames() pixel block with blocks: 'rgba': the runs of equal columns (widths, left to right)
 * and of equal rows (heights, top to bottom) it is made of, one RGBA texel per run pair (row
 * by row), and `data`, the width × height RGBA bytes, expanded when first read. */
export interface RunsBlock {
  width: number;
  height: number;
  cols: number[] | Float64Array;
  rows: number[] | Float64Array;
  texels: Uint8ClampedArray;
  readonly data: Uint8ClampedArray;
}

export interface DecodedImage {
  width: number;
  height: number;
  rgba: Uint8Array | Uint8ClampedArray;
  name?: string;
}

/** An image file's name and bytes (a .npy for diff; any for checkImage). */
export interface ImageFile {
  name: string;
  data: Uint8Array;
}

export interface DiffOptions extends FillOptions {
  /** `diff --tolerance`: a finite number in [0, 1] (1/255). */
  tolerance?: number;
  undo?: boolean;
}

export class ScantraceError extends Error {
  /** 1: bad input (the CLI's one-line message); 2: a bad argument of the API. */
  status: 1 | 2;
}

export class Scantrace {
  render(scene: SceneInput, options?: FillOptions): Rendered;
  /** into: with options.keep, an ImageData (or Uint8ClampedArray) that takes the kept image's
   * RGBA bytes when it has their size, and is then lastTraceImage.rgba (no new array a call). */
  traceText(input: TraceInput, options?: TraceOptions, into?: ImageData | Uint8ClampedArray | null): string;
  trace(input: TraceInput, options?: TraceOptions): TraceEvent[];
  /** trace null: the trace kept by the last traceText/trace call with keep: true. */
  frames(trace: string | TraceEvent[] | null, options?: FrameOptions): { steps: FrameStep[]; frames: CanvasFrame[] };
  /** The kept trace's event count, and face `triangle`'s edge table and scanline event of row `y`. */
  keptStep(triangle: number, y: number): KeptStep;
  /** `scantrace why SCENE X Y --json`'s document (trace/why_schema.json). */
  /** x, y: integers on the canvas (checked as `scantrace why` checks X and Y). */
  why(scene: SceneInput, x: number, y: number, options?: FillOptions): Record<string, unknown>;
  /** After why: `scantrace why`'s text (without --json) of the same story, made by the module. */
  lastWhyText: string | null;
  /** Each option's table by its key: shading, fill_rule, method, winding_rule, cull, visibility,
   * occlusion, level. */
  optionTable(): Record<string, OptionTableEntry>;
  /** drawScantraceFrame's JavaScript source (viz/frame_json.hpp). */
  canvasScript(): string;
  /** The built-in demo scene (`scantrace demo`'s demo_scene.json) as scene JSON text. */
  demoScene(): string;
  /** The picture of the last diff's differences (grade/diff_picture.hpp), or null. */
  lastDiffPicture: { width: number; height: number; rgba: Uint8ClampedArray } | null;
  /** After traceText/trace with keep: true of a triangle or polygon: the image its traced fill drew. */
  lastTraceImage: { width: number; height: number; rgba: Uint8ClampedArray } | null;
  /** `scantrace diff SCENE IMAGE --json`'s report. */
  diff(scene: SceneInput, image: DecodedImage | ImageFile, options?: DiffOptions): Record<string, unknown>;
  /** The checks `scantrace diff` makes before decoding (header, size, memory, PNG chunks; a .npy
   * decoded): the format and size, or ScantraceError with the command's line. With the scene:
   * the command's pre-check against its canvas; a header of another size adds `report`, diff's
   * canvas_size report made from the header alone (nothing to decode). */
  checkImage(file: ImageFile, scene?: SceneInput | null, options?: DiffOptions): {
    format: 'png' | 'bmp' | 'npy';
    width: number;
    height: number;
    report?: Record<string, unknown>;
  };
  /** The warning of the last call, as the command prints it (a trace its byte cap cut), or null. */
  lastWarning: string | null;
}

/** Loads the module: its .wasm read beside scantrace.mjs, or the bytes given. */
export function load(options?: {
  wasmBinary?: Uint8Array;
  print?: (text: string) => void;
  printErr?: (text: string) => void;
}): Promise<Scantrace>;
