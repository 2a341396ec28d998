import { toPixel, type Mapping } from './axis-scale.ts';
import { includePoint, type Extent } from './extent.ts';

/** The part of a Canvas 2D context a path is traced into; tests pass a recording fake. */
export interface PathSink {
  moveTo(x: number, y: number): void;
  lineTo(x: number, y: number): void;
}

/**
 * Where each track's line was last drawn to, in pixels, and whether its pen
 * is down (so the next sample continues the line). One slot per track, kept
 * between frames: a frame's new line starts where the last frame's ended.
 */
export interface Pens {
  readonly x: Float64Array;
  readonly y: Float64Array;
  readonly down: Uint8Array;
}

export function makePens(tracks: number): Pens {
  return { x: new Float64Array(tracks), y: new Float64Array(tracks), down: new Uint8Array(tracks) };
}

/** Lift every pen: the next sample of each track starts a new line (after a gap or a redraw). */
export function liftPens(pens: Pens): void {
  pens.down.fill(0);
}

/** How finely and how far a line is drawn, in pixels. */
export interface Stroke {
  /** samples closer than this to the last drawn point are skipped (they would not show) */
  minStep: number;
  /** a step longer than this is a jump of the state, drawn as a break in the line */
  jump: number;
}

/**
 * Traces track k through rows [r0, r1) of row-major `data` (`width` values
 * a row; the track's x in column cx, y in cy) into `sink`, continuing from
 * its pen. The line breaks at a non-finite sample or a jump; nothing is
 * allocated, so this is the loop a batch of 1000 trajectories runs each frame.
 */
export function traceRows(
  sink: PathSink,
  data: Float64Array,
  width: number,
  r0: number,
  r1: number,
  cx: number,
  cy: number,
  mx: Mapping,
  my: Mapping,
  pens: Pens,
  k: number,
  stroke: Stroke,
): void {
  const min2 = stroke.minStep * stroke.minStep;
  const jump2 = stroke.jump * stroke.jump;
  let px = pens.x[k];
  let py = pens.y[k];
  let down = pens.down[k] === 1;
  if (down) sink.moveTo(px, py);
  for (let r = r0; r < r1; r++) {
    const at = r * width;
    const x = toPixel(mx, data[at + cx]);
    const y = toPixel(my, data[at + cy]);
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      down = false;
      continue;
    }
    const dx = x - px;
    const dy = y - py;
    const d2 = dx * dx + dy * dy;
    if (!down || d2 > jump2) {
      sink.moveTo(x, y);
      // a zero-length segment, so that a lone sample still shows with round caps
      sink.lineTo(x, y);
    } else if (d2 >= min2) {
      sink.lineTo(x, y);
    } else {
      continue;
    }
    px = x;
    py = y;
    down = true;
  }
  pens.x[k] = px;
  pens.y[k] = py;
  pens.down[k] = down ? 1 : 0;
}

/** Widens `e` in place to hold the (cx, cy) points of rows [r0, r1). */
export function includeRows(e: Extent, data: Float64Array, width: number, r0: number, r1: number, cx: number, cy: number): void {
  for (let r = r0; r < r1; r++) {
    const at = r * width;
    includePoint(e, data[at + cx], data[at + cy]);
  }
}
