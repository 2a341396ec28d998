import { toPixel, type Mapping } from './scale.ts';
import { includePoint, type Extent } from './extent.ts';

/** The part of a Canvas 2D context a path is traced into; tests pass a recording fake. */
export interface PathSink {
  moveTo(x: number, y: number): void;
  lineTo(x: number, y: number): void;
}

/**
 * Per track, kept between frames so that a frame's new line starts where the
 * last frame's ended: where the line was last drawn to (pixels), the last
 * sample (data units, for the jump test), and whether the pen is down.
 */
export interface Pens {
  readonly x: Float64Array;
  readonly y: Float64Array;
  readonly u: Float64Array;
  readonly v: Float64Array;
  readonly down: Uint8Array;
}

export function makePens(tracks: number): Pens {
  const n = () => new Float64Array(tracks);
  return { x: n(), y: n(), u: n(), v: n(), down: new Uint8Array(tracks) };
}

/** Lift every pen: the next sample of each track starts a new line (after a gap or a redraw). */
export function liftPens(pens: Pens): void {
  pens.down.fill(0);
}

/** How finely a line is drawn, and what counts as a jump of the state. */
export interface Stroke {
  /** samples closer than this to the last drawn point (pixels) are skipped: they would not show */
  minStep: number;
  /** a step between samples longer than this in x or in y (data units) is a jump, drawn as a break in the line */
  jumpX: number;
  jumpY: number;
}

/**
 * Traces track k through rows [r0, r1) of row-major `data` (`width` values
 * a row; the track's x in column cx, y in cy) into `sink`, continuing from
 * its pen. The line breaks at a non-finite sample or a jump (tested in data
 * units, so a symlog axis's stretch near zero is no jump); nothing is
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
  const { jumpX, jumpY } = stroke;
  let px = pens.x[k];
  let py = pens.y[k];
  let u = pens.u[k];
  let v = pens.v[k];
  let down = pens.down[k] === 1;
  if (down) sink.moveTo(px, py);
  for (let r = r0; r < r1; r++) {
    const at = r * width;
    const du = data[at + cx];
    const dv = data[at + cy];
    const x = toPixel(mx, du);
    const y = toPixel(my, dv);
    if (!Number.isFinite(x) || !Number.isFinite(y)) {
      down = false;
      continue;
    }
    const jumped = Math.abs(du - u) > jumpX || Math.abs(dv - v) > jumpY;
    u = du;
    v = dv;
    const dx = x - px;
    const dy = y - py;
    if (!down || jumped) {
      sink.moveTo(x, y);
      // a zero-length segment, so that a lone sample still shows with round caps
      sink.lineTo(x, y);
    } else if (dx * dx + dy * dy >= min2) {
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
  pens.u[k] = u;
  pens.v[k] = v;
  pens.down[k] = down ? 1 : 0;
}

/** Widens `e` in place to hold the (cx, cy) points of rows [r0, r1). */
export function includeRows(e: Extent, data: Float64Array, width: number, r0: number, r1: number, cx: number, cy: number): void {
  for (let r = r0; r < r1; r++) {
    const at = r * width;
    includePoint(e, data[at + cx], data[at + cy]);
  }
}
