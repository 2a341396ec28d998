/**
 * The boundary of a blob of initial conditions carried by the flow, as a
 * closed polygon refined where it stretches, so that the area the blob keeps
 * (Liouville's theorem) or loses (a damped flow) can be measured and drawn.
 *
 * Each vertex is the image of one point of the initial curve, named by its
 * parameter s there. A flow that shears, as any nonlinear oscillator's does
 * (the period depends on the energy), draws the blob out into a filament
 * whose length grows without bound while its area stays put; a fixed set of
 * points would soon lie too far apart to say where the boundary runs. So
 * after every advance, a side that has grown too long, or that meets a
 * sharp turn, gets a new vertex at its midpoint in s — and that vertex is the
 * point of the initial curve at that s advanced from the first step by the
 * same stepper, not an interpolation between its neighbours: interpolating
 * would cut corners that the flow will then stretch, and the area would drift
 * by an error of the tracking's own making. Advanced from step 0, a new vertex
 * is bit for bit the state it would hold had it been tracked from the start,
 * whenever the stepper's numbers do not depend on how a run is cut into calls
 * (true of the core's steppers: each step's t is computed, never summed).
 *
 * The price is that a vertex added at step k costs k steps, so refinement
 * grows dearer as time goes on; the length of a filament grows about linearly
 * in t for a shearing flow, so the work to time t grows about as t².
 * `maxVertices` bounds it.
 */
import { InputError } from '../errors.ts';
import type { Stepper } from '../types.ts';
import type { BoundaryCurve } from './boundary-curve.ts';
import { polygonArea, polygonAreaError, polygonAreaShortfall } from './polygon-area.ts';
import { markSplits, type SplitLimits } from './side-splits.ts';

/**
 * The smallest gap in s that is still split. Doubles resolve s to 2⁻⁵³, so a
 * much smaller gap would soon produce midpoints equal to their ends; and a
 * side that still stretches after forty halvings sits where the flow
 * separates neighbouring points faster than any refinement can follow (a
 * hyperbolic point, a singularity), which the boundary reports as unresolved.
 */
export const MIN_PARAMETER_GAP = 2 ** -40;

export interface TrackedBoundaryOptions {
  readonly stepper: Stepper;
  /** the model's parameters; copied, since a vertex added later must see the values the others saw */
  readonly params: Float64Array;
  /** the initial boundary, counter-clockwise in the (q, p) plane of the first degree of freedom */
  readonly curve: BoundaryCurve;
  /** 2·dof, the stepper's */
  readonly dim: number;
  /** the time of step 0, 0 by default */
  readonly t0?: number;
  readonly dt: number;
  /** vertices at the start, evenly spaced in s; 256 by default */
  readonly initialVertices?: number;
  /** the longest side allowed, in units of `scale` */
  readonly maxSegment: number;
  /** the largest turn allowed at a vertex, radians; 0.3 by default */
  readonly maxTurn?: number;
  /** the most vertices the boundary may grow to; 50 000 by default */
  readonly maxVertices?: number;
  /** the lengths in q and p of one unit of `maxSegment` (and of the turning angles); [1, 1] by default */
  readonly scale?: readonly [number, number];
}

const DEFAULTS = { t0: 0, initialVertices: 256, maxTurn: 0.3, maxVertices: 50_000 };

/** `array` with room for `length` elements at least, its first `used` kept: doubled, so that growth costs O(1) per element. */
function grown<A extends Float64Array | Uint8Array>(array: A, length: number, used: number, make: (n: number) => A): A {
  if (array.length >= length) return array;
  const bigger = make(Math.max(length, 2 * array.length));
  bigger.set(array.subarray(0, used));
  return bigger;
}

const float64 = (n: number) => new Float64Array(n);

export class TrackedBoundary {
  readonly dim: number;
  readonly t0: number;
  readonly dt: number;
  /**
   * The latest refinement wanted more vertices than maxVertices allows: some
   * sides are longer, or turn more, than asked, and the area's error may
   * exceed areaError's model (its vertices no longer resolve the curve).
   */
  saturated = false;
  /**
   * The latest refinement met a side it wanted to split whose gap in s was
   * already below MIN_PARAMETER_GAP, and left it: the boundary is not
   * resolved there.
   */
  unresolved = false;
  /**
   * A state stopped being finite, and further advances do nothing. If it was
   * a vertex's step, the boundary stays as the last good advance left it (the
   * step ran on a copy); if it was a new vertex, advanced from the start, the
   * boundary has the time and the vertices it had before that insertion.
   */
  failed = false;

  private readonly stepper: Stepper;
  private readonly params: Float64Array;
  private readonly curve: BoundaryCurve;
  private readonly limits: SplitLimits;
  private readonly maxVertices: number;
  /** where the first momentum sits in a state */
  private readonly pIndex: number;
  /** whole steps taken */
  private k = 0;
  private n = 0;
  /** the vertices' states, packed, and their parameters on the initial curve, increasing from s = 0 */
  private x: Float64Array;
  private s: Float64Array;
  /** the other halves of double buffers: a step writes to these, so a failed one leaves the boundary intact */
  private spareX: Float64Array;
  private spareS: Float64Array;
  /** the first coordinate and momentum of each vertex, the plane the polygon lies in */
  private qs: Float64Array;
  private ps: Float64Array;
  /** which sides a refinement pass splits */
  private split: Uint8Array;
  /** the states and parameters of a pass's new vertices */
  private newX: Float64Array = new Float64Array(0);
  private newS: Float64Array = new Float64Array(0);
  private readonly point: Float64Array;

  constructor(options: TrackedBoundaryOptions) {
    const { stepper, curve, dim, dt, maxSegment } = options;
    const t0 = options.t0 ?? DEFAULTS.t0;
    const initial = options.initialVertices ?? DEFAULTS.initialVertices;
    const maxTurn = options.maxTurn ?? DEFAULTS.maxTurn;
    const maxVertices = options.maxVertices ?? DEFAULTS.maxVertices;
    const scale = options.scale ?? [1, 1];
    if (!(dim >= 2 && dim % 2 === 0 && Number.isInteger(dim)) || dim !== stepper.dim) {
      throw new InputError(`dim must be the stepper's 2·dof (${stepper.dim}), not ${dim}`);
    }
    if (!(Number.isFinite(dt) && dt !== 0)) throw new InputError(`dt must be finite and not 0, not ${dt}`);
    if (!Number.isFinite(t0)) throw new InputError(`t0 must be finite, not ${t0}`);
    if (!(Number.isInteger(initial) && initial >= 3)) throw new InputError(`initialVertices must be a whole number ≥ 3, not ${initial}`);
    if (!(Number.isInteger(maxVertices) && maxVertices >= initial)) {
      throw new InputError(`maxVertices must be a whole number ≥ initialVertices (${initial}), not ${maxVertices}`);
    }
    if (!(maxSegment > 0)) throw new InputError(`maxSegment must be > 0, not ${maxSegment}`);
    if (!(maxTurn > 0 && maxTurn < Math.PI)) throw new InputError(`maxTurn must lie in (0, π), not ${maxTurn}`);
    if (!(scale[0] > 0 && scale[1] > 0 && Number.isFinite(scale[0]) && Number.isFinite(scale[1]))) {
      throw new InputError(`scale must be two finite lengths > 0, not [${scale.join(', ')}]`);
    }
    this.stepper = stepper;
    this.params = Float64Array.from(options.params);
    this.curve = curve;
    this.dim = dim;
    this.t0 = t0;
    this.dt = dt;
    this.limits = { maxSegment, maxTurn, scale: [scale[0], scale[1]] };
    this.maxVertices = maxVertices;
    this.pIndex = dim / 2;
    this.point = new Float64Array(dim);

    const capacity = Math.min(maxVertices, 4 * initial);
    this.x = new Float64Array(capacity * dim);
    this.spareX = new Float64Array(capacity * dim);
    this.s = new Float64Array(capacity);
    this.spareS = new Float64Array(capacity);
    this.qs = new Float64Array(capacity);
    this.ps = new Float64Array(capacity);
    this.split = new Uint8Array(capacity);
    for (let i = 0; i < initial; i++) {
      const s = i / initial;
      this.s[i] = s;
      curve.point(s, this.point);
      this.x.set(this.point, i * dim);
    }
    this.n = initial;
    this.extractPlane();
    this.refine();
  }

  /** t = t0 + k·dt after k steps. */
  get t(): number {
    return this.t0 + this.k * this.dt;
  }

  /** Whole steps taken since t0. */
  get steps(): number {
    return this.k;
  }

  /** The number of vertices. */
  get count(): number {
    return this.n;
  }

  /**
   * Advances every vertex by `steps` steps in one call of the stepper, then
   * refines the polygon until every side is short enough and turns gently
   * enough, or the limits stop it (saturated, unresolved). Does nothing once
   * failed.
   */
  advance(steps: number): void {
    if (!(Number.isInteger(steps) && steps >= 0)) throw new InputError(`steps must be a whole number ≥ 0, not ${steps}`);
    if (this.failed || steps === 0) return;
    const { n, dim } = this;
    this.spareX.set(this.x.subarray(0, n * dim));
    const done = this.stepper.advance(this.spareX, n, this.params, this.t0, this.k, this.dt, steps);
    if (done < steps) {
      this.failed = true;
      return;
    }
    [this.x, this.spareX] = [this.spareX, this.x];
    this.k += steps;
    this.extractPlane();
    this.refine();
  }

  /** The first coordinate of each vertex, in order along the boundary: a view the next advance overwrites. */
  q(): Float64Array {
    return this.qs.subarray(0, this.n);
  }

  /** The first momentum of each vertex, in order along the boundary: a view the next advance overwrites. */
  p(): Float64Array {
    return this.ps.subarray(0, this.n);
  }

  /** Each vertex's parameter s on the initial curve, increasing from 0: a view the next advance overwrites. */
  parameters(): Float64Array {
    return this.s.subarray(0, this.n);
  }

  /** The vertices' full states, count·dim numbers packed: a view the next advance overwrites. */
  states(): Float64Array {
    return this.x.subarray(0, this.n * this.dim);
  }

  /**
   * The polygon's area in the (q, p) plane of the first degree of freedom.
   * For one degree of freedom a Hamiltonian flow keeps it (Liouville); for
   * more, a projection's area is not kept in general, only the sum over the
   * conjugate pairs (the Poincaré integral invariant ∮ Σ p_i dq_i).
   */
  area(): number {
    return polygonArea(this.qs, this.ps, this.n);
  }

  /** The bound of polygonAreaError on the polygon's own error against the curve through its vertices; no integrator error, no rounding. */
  areaError(): number {
    return polygonAreaError(this.qs, this.ps, this.n);
  }

  /**
   * polygonAreaShortfall's signed estimate of the curve's area less the
   * polygon's: far closer to the actual error than areaError once the blob
   * is a filament, whose two sides' errors cancel; an estimate, not a bound.
   */
  areaShortfall(): number {
    return polygonAreaShortfall(this.qs, this.ps, this.n);
  }

  /** Copies the plane (first q, first p) of the vertices' states out, where the refinement and the area read it. */
  private extractPlane(): void {
    const { n, dim, pIndex, x, qs, ps } = this;
    for (let i = 0, o = 0; i < n; i++, o += dim) {
      qs[i] = x[o];
      ps[i] = x[o + pIndex];
    }
  }

  /** Refinement passes until no side needs splitting or a limit stops them. */
  private refine(): void {
    this.saturated = false;
    this.unresolved = false;
    for (;;) {
      const { n, s, split } = this;
      let wanted = markSplits(this.qs, this.ps, n, this.limits, split);
      if (wanted === 0) return;
      for (let i = 0; i < n; i++) {
        if (split[i] === 0) continue;
        const gap = (i + 1 < n ? s[i + 1] : 1) - s[i];
        if (!(gap > MIN_PARAMETER_GAP)) {
          split[i] = 0;
          wanted--;
          this.unresolved = true;
        }
      }
      if (wanted === 0) return;
      const room = this.maxVertices - n;
      if (wanted > room) {
        this.saturated = true;
        if (room === 0) return;
        thin(split, n, wanted, room);
        wanted = room;
      }
      if (!this.insert(wanted)) return;
      if (this.saturated) return;
    }
  }

  /**
   * Adds a vertex at the midpoint in s of each side marked in `split`
   * (`added` of them), each computed from the initial curve and advanced by
   * all k steps in one call. False if a new vertex failed to stay finite,
   * which fails the boundary: that point would have failed had it been
   * tracked from the start.
   */
  private insert(added: number): boolean {
    const { n, dim, s, split, point } = this;
    this.newX = grown(this.newX, added * dim, 0, float64);
    this.newS = grown(this.newS, added, 0, float64);
    const { newX, newS } = this;
    for (let i = 0, j = 0; i < n; i++) {
      if (split[i] === 0) continue;
      const mid = (s[i] + (i + 1 < n ? s[i + 1] : 1)) / 2;
      newS[j] = mid;
      this.curve.point(mid, point);
      for (let c = 0, to = j * dim; c < dim; c++) newX[to + c] = point[c];
      j++;
    }
    if (this.k > 0) {
      const done = this.stepper.advance(newX, added, this.params, this.t0, 0, this.dt, this.k);
      if (done < this.k) {
        this.failed = true;
        return false;
      }
    }
    this.reserve(n + added);
    const { x, spareX, spareS } = this;
    const S = this.s;
    const marks = this.split;
    // Copied element by element: a subarray per vertex would allocate in a loop over every vertex.
    for (let i = 0, j = 0, out = 0; i < n; i++) {
      for (let c = 0, from = i * dim, to = out * dim; c < dim; c++) spareX[to + c] = x[from + c];
      spareS[out++] = S[i];
      if (marks[i] === 0) continue;
      for (let c = 0, from = j * dim, to = out * dim; c < dim; c++) spareX[to + c] = newX[from + c];
      spareS[out++] = newS[j++];
    }
    [this.x, this.spareX] = [this.spareX, this.x];
    [this.s, this.spareS] = [this.spareS, this.s];
    this.n = n + added;
    this.extractPlane();
    return true;
  }

  /** Room for `count` vertices in every per-vertex array, doubling; the live ones kept. */
  private reserve(count: number): void {
    if (this.s.length >= count) return;
    const capacity = Math.min(this.maxVertices, Math.max(count, 2 * this.s.length));
    const { n, dim } = this;
    this.x = grown(this.x, capacity * dim, n * dim, float64);
    this.spareX = grown(this.spareX, capacity * dim, 0, float64);
    this.s = grown(this.s, capacity, n, float64);
    this.spareS = grown(this.spareS, capacity, 0, float64);
    this.qs = grown(this.qs, capacity, n, float64);
    this.ps = grown(this.ps, capacity, n, float64);
    this.split = grown(this.split, capacity, n, (m) => new Uint8Array(m));
  }
}

/**
 * Keeps `room` of the `wanted` marks in `split`, spread evenly along the
 * boundary, so that a saturated boundary is refined alike everywhere rather
 * than from its first vertex on.
 */
function thin(split: Uint8Array, n: number, wanted: number, room: number): void {
  for (let i = 0, f = 0; i < n; i++) {
    if (split[i] === 0) continue;
    if (Math.floor(((f + 1) * room) / wanted) === Math.floor((f * room) / wanted)) split[i] = 0;
    f++;
  }
}
