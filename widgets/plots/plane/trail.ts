/**
 * Fading trails. The trail layer is drawn incrementally and, to fade, has its
 * alpha multiplied by a keep factor with a `destination-out` fill. After a
 * trail's length L its opacity is down to FLOOR, so the keep factor over an
 * elapsed time Δ is FLOOR^(Δ/L).
 *
 * Canvas alpha has 8 bits, so a fade by a fraction a leaves any pixel whose
 * alpha is below 0.5/a (of 255) where it is: measured in Chromium, 500 fades
 * of 0.02 leave alpha 25 of 255, a visible ghost of every old path. Fades are
 * therefore saved up until they reach MIN_STEP, which bounds the ghost at
 * 0.5/MIN_STEP = 4 of 255; a periodic redraw from the record clears even that.
 */

/** What a plot keeps of the motion: a fading tail, the whole path, none, or a tail of that many time units. */
export type TrailOption = 'fade' | 'full' | 'none' | number;

export interface TrailMode {
  kind: 'frames' | 'time' | 'full' | 'none';
  /** the trail's length in its unit: drawn frames for 'frames', time units for 'time' */
  length: number;
}

/** A 'fade' trail lasts this many drawn frames (with new samples): 1.5 s at 60 fps, whatever the model's time scale. */
export const FADE_FRAMES = 90;
/** Opacity left at the end of a trail. */
export const FLOOR = 0.02;
/** Smallest fade applied at once (see above). */
export const MIN_STEP = 0.125;

export function parseTrail(option: TrailOption | undefined): TrailMode {
  if (option === undefined || option === 'fade') return { kind: 'frames', length: FADE_FRAMES };
  if (option === 'full') return { kind: 'full', length: Infinity };
  if (option === 'none') return { kind: 'none', length: 0 };
  if (typeof option === 'number' && option > 0 && Number.isFinite(option)) return { kind: 'time', length: option };
  throw new Error(`trail must be 'fade', 'full', 'none' or a positive number of time units, not ${JSON.stringify(option)}`);
}

/** Opacity of the part of a trail drawn `age` (in the trail's unit) ago: FLOOR^(age/length), 0 past the end. */
export function ageOpacity(age: number, length: number): number {
  if (!(age > 0)) return 1;
  if (age >= length) return 0;
  return FLOOR ** (age / length);
}

/**
 * Saves up the fade owed for elapsed time and pays it out in steps of at
 * least MIN_STEP. `advance` returns the alpha of the destination-out fill to
 * apply now, 0 for none.
 */
export class Fader {
  /** the product of the keep factors not yet applied */
  private owed = 1;

  constructor(readonly length: number) {}

  advance(elapsed: number): number {
    if (!(elapsed > 0) || !Number.isFinite(this.length)) return 0;
    this.owed *= FLOOR ** (elapsed / this.length);
    const alpha = 1 - this.owed;
    if (alpha < MIN_STEP) return 0;
    this.owed = 1;
    return alpha;
  }

  /** Forget the owed fade, as after a redraw that placed everything at its true opacity. */
  clear(): void {
    this.owed = 1;
  }
}

/**
 * The age buckets a trail is redrawn in, oldest first: `count` equal slices
 * of [now − length, now] (or all of [start, now] for a full trail), each with
 * the opacity of its middle.
 */
export function ageBuckets(start: number, now: number, length: number, count: number): { t0: number; t1: number; opacity: number }[] {
  if (!Number.isFinite(length)) return [{ t0: start, t1: now, opacity: 1 }];
  const from = Math.max(start, now - length);
  const width = (now - from) / count;
  const buckets = [];
  for (let i = 0; i < count; i++) {
    const t0 = from + i * width;
    buckets.push({ t0, t1: t0 + width, opacity: ageOpacity(now - (t0 + width / 2), length) });
  }
  return buckets;
}
