/**
 * The standard map p' = p + K sin q, q' = q + p' (core/maps/standard-map.ts)
 * read the way the literature reads it: the breakup of the last invariant
 * circle by Greene's residue criterion (Greene 1979, J. Math. Phys. 20,
 * 1183), the diffusion in p beyond it against the quasilinear value and
 * Rechester & White's correction (1980, Phys. Rev. Lett. 44, 1586), the
 * bands of K with accelerator modes that spoil that diffusion, and one
 * orbit's rotation number, Lyapunov exponent and range in p.
 *
 * The convention for the diffusion coefficient, everywhere here:
 *
 *   D = ⟨(p_n − p_0)²⟩ / n,
 *
 * the mean square spread of the unreduced momentum per iterate, so that
 * kicks of random phase give D = K²⟨sin²q⟩ = K²/2. (Some authors divide by
 * 2n, and quote K²/4.)
 */
import { TWO_PI } from '../maps/area-preserving-map.ts';
import { standardMap } from '../maps/standard-map.ts';
import { CounterRandom } from '../dataset/philox.ts';

/**
 * The K at which the last invariant circle of the standard map, the one of
 * golden-mean rotation number, breaks: Greene 1979 (J. Math. Phys. 20,
 * 1183) by the residues of its convergents; MacKay 1983 (Physica D 7, 283)
 * gives 0.971635406 by renormalisation. Above it no circle bars p from
 * wandering the whole cylinder.
 */
export const GREENE_K = 0.971635406;

/**
 * The overlap estimates of the critical K (Chirikov 1979, Phys. Rep. 52,
 * 263, §5.1; Lichtenberg & Lieberman §4.1b), for comparison with GREENE_K:
 * - primary: the integer resonances at p = 0 and p = 2π, each a pendulum of
 *   half-width 2√K, touch when 4√K = 2π, K = π²/4 ≈ 2.47;
 * - withSecondary: counting also the 1:2 resonance at p = π, of half-width
 *   K/2, between them: 4√K + K = 2π, K = (√(4 + 2π) − 2)² ≈ 1.456
 *   (Chirikov's 1.46). Both overestimate the true 0.9716, since the thin
 *   chaotic layers at the separatrices destroy the circle first.
 */
export const CHIRIKOV_OVERLAP = Object.freeze({ primary: Math.PI ** 2 / 4, withSecondary: (Math.sqrt(4 + TWO_PI) - 2) ** 2 });

/** Throws unless K is a finite number; `what` names the function in the message. */
function checkK(K: number, what: string): void {
  if (typeof K !== 'number' || !Number.isFinite(K)) throw new RangeError(`${what}: the kick strength K must be a finite number, not ${String(K)}`);
}

/** Throws unless `x` is a whole number in [low, high]; `what` names it in the message. */
function checkWhole(x: number, low: number, high: number, what: string): void {
  if (!Number.isInteger(x) || x < low || x > high) throw new RangeError(`${what} must be a whole number from ${low} to ${high}, not ${x}`);
}

/**
 * The Bessel function J_n(x) of integer order n ≥ 0, from Bessel's integral
 * J_n(x) = (1/π)∫₀^π cos(nτ − x sin τ) dτ (Abramowitz & Stegun 9.1.21) by
 * the trapezoid rule. The integrand is even in τ and 2π-periodic, so the
 * rule on [0, π] is the periodic one on [0, 2π], whose error falls faster
 * than any power of the step: with N intervals it is of the size of
 * J_{2N−n}(x), negligible once 2N exceeds |x| + n by a margin, hence the
 * number of intervals chosen here.
 */
export function besselJ(n: number, x: number): number {
  checkWhole(n, 0, 10_000, 'besselJ: the order n');
  if (!Number.isFinite(x)) throw new RangeError(`besselJ: the argument x must be a finite number, not ${x}`);
  const intervals = Math.max(64, Math.ceil(2 * (Math.abs(x) + n)) + 40);
  const h = Math.PI / intervals;
  // the end points with half weight: cos(0) = 1 at τ = 0, cos(nπ) = (−1)ⁿ at τ = π
  let sum = (1 + (n % 2 === 0 ? 1 : -1)) / 2;
  for (let i = 1; i < intervals; i++) {
    const tau = i * h;
    sum += Math.cos(n * tau - x * Math.sin(tau));
  }
  return (sum * h) / Math.PI;
}

/** The quasilinear diffusion coefficient D = K²/2: kicks K sin q of independent, uniformly distributed phases (D = ⟨(Δp)²⟩/n). */
export function quasilinearDiffusion(K: number): number {
  return (K * K) / 2;
}

/**
 * Rechester & White's diffusion coefficient for large K (1980, Phys. Rev.
 * Lett. 44, 1586; as quoted by Lichtenberg & Lieberman, Regular and Chaotic
 * Dynamics, §5.5), without noise:
 *
 *   D = (K²/2)(1 − 2J₂(K) − 2J₁²(K) + 2J₂²(K) + 2J₃²(K)),
 *
 * the quasilinear value corrected by the correlations of kicks two and
 * three iterates apart. It oscillates about K²/2, with the period 2π of the
 * Bessel functions, and tends to it as K grows.
 */
export function rechesterWhiteDiffusion(K: number): number {
  const [j1, j2, j3] = [besselJ(1, K), besselJ(2, K), besselJ(3, K)];
  return quasilinearDiffusion(K) * (1 - 2 * j2 - 2 * j1 * j1 + 2 * j2 * j2 + 2 * j3 * j3);
}

/**
 * The error model of the terms Rechester & White's series leaves out,
 * relative to K²/2: 6·(2/(πK))^{3/2}. The kept terms are a Bessel function
 * and products of two, and J_n(K) has the amplitude √(2/(πK)) for large K
 * (Abramowitz & Stegun 9.2.1); the next terms are products of three, so of
 * order (2/(πK))^{3/2}, and the 6 allows for their number. This is the
 * check's stated allowance, not a bound proved from the series.
 */
export function rechesterWhiteRemainder(K: number): number {
  return 6 * (2 / (Math.PI * Math.abs(K))) ** 1.5;
}

/** The upper end of the m-th accelerator band, √((2πm)² + 16), where the mode's fixed point turns unstable. */
function bandTop(m: number): number {
  return Math.sqrt((TWO_PI * m) ** 2 + 16);
}

/**
 * The m ≥ 1 for which the standard map has accelerator modes, or 0:
 * for 2πm ≤ |K| ≤ √((2πm)² + 16) there are stable orbits with q fixed and
 * p gaining 2πm every iterate (sin q = 2πm/K), surrounded by islands that
 * carry their neighbours along (Chirikov 1979 §5.3; Lichtenberg &
 * Lieberman §5.5). There ⟨(Δp)²⟩ grows like n², not n. The sign of K does
 * not matter: K → −K is the shift q → q + π.
 */
export function acceleratorMode(K: number): number {
  checkK(K, 'acceleratorMode');
  const k = Math.abs(K);
  const m = Math.floor(k / TWO_PI);
  return m >= 1 && k <= bandTop(m) ? m : 0;
}

/**
 * Whether |K| lies in or near an accelerator band, within
 * [2πm − 0.2, √((2πm)² + 16) + 0.7] for some m ≥ 1: just outside a band the
 * modes are gone but their remnants are sticky, and an orbit that lingers
 * near one gains a long correlated run of kicks, so a measured D is biased
 * upward there and Rechester & White's formula is not a fair test. The
 * margins are this module's, chosen wider past the band's top, where the
 * remnant islands of the period-doubled modes linger.
 */
export function nearAcceleratorMode(K: number): boolean {
  checkK(K, 'nearAcceleratorMode');
  const k = Math.abs(K);
  for (let m = Math.max(1, Math.floor((k - 0.7) / TWO_PI) - 1); TWO_PI * m - 0.2 <= k; m++) {
    if (k <= bandTop(m) + 0.7) return true;
  }
  return false;
}

/** A measured diffusion coefficient, D = ⟨(p_n − p_0)²⟩/n, with its statistics. */
export interface DiffusionMeasure {
  /** the mean over the orbits of (p_n − p_0)²/n */
  D: number;
  /** the sample standard deviation of the per-orbit values over √orbits */
  standardError: number;
  /** the same mean at the half run, n/2 rounded down: equal to D within the errors when the spread is diffusive (grows like n) */
  halfRunD: number;
  orbits: number;
  iterations: number;
}

/**
 * The diffusion coefficient of the standard map measured by brute force:
 * `orbits` orbits started at (q, p) uniform on [0, 2π)² (drawn from
 * CounterRandom(seed), orbit j's two numbers at (j, 0, 0, 0) and (j, 0, 0, 1),
 * so a run is reproducible), iterated `iterations` times with p left on the
 * line. Each orbit gives one reading (p_n − p_0)²/n; D is their mean. For a
 * diffusive spread each reading is D times a χ² of one degree of freedom,
 * so the relative standard error is about √(2/orbits).
 */
export function measureDiffusion(K: number, options: { orbits?: number; iterations?: number; seed?: number } = {}): DiffusionMeasure {
  const { orbits = 400, iterations = 400, seed = 1 } = options;
  const map = standardMap(K);
  checkWhole(orbits, 2, 1_000_000, 'measureDiffusion: the number of orbits');
  checkWhole(iterations, 2, 10_000_000, 'measureDiffusion: the number of iterations');
  const random = new CounterRandom(seed);
  const half = Math.floor(iterations / 2);
  const state = new Float64Array(2);
  let sum = 0;
  let sumSquares = 0;
  let halfSum = 0;
  for (let j = 0; j < orbits; j++) {
    state[0] = TWO_PI * random.uniform(j, 0, 0, 0);
    state[1] = TWO_PI * random.uniform(j, 0, 0, 1);
    const p0 = state[1];
    for (let n = 0; n < half; n++) map.step(state);
    halfSum += (state[1] - p0) ** 2 / half;
    for (let n = half; n < iterations; n++) map.step(state);
    const reading = (state[1] - p0) ** 2 / iterations;
    sum += reading;
    sumSquares += reading * reading;
  }
  const D = sum / orbits;
  const variance = Math.max(0, (sumSquares - orbits * D * D) / (orbits - 1));
  return { D, standardError: Math.sqrt(variance / orbits), halfRunD: halfSum / orbits, orbits, iterations };
}

/**
 * Greene's residue R = (2 − tr M)/4 of the orbit of (q0, p0) over `period`
 * iterates, M the product of the map's Jacobians along it. For a periodic
 * orbit R < 0 means hyperbolic, 0 < R < 1 elliptic (stable), R > 1
 * hyperbolic with reflection. The orbit is followed by iterating the map,
 * so for a long, unstable orbit (q0, p0) must be periodic to the last bits:
 * errors grow like the matrix itself.
 */
export function residue(K: number, q0: number, p0: number, period: number): number {
  const map = standardMap(K);
  checkWhole(period, 1, 10_000_000, 'residue: the period');
  const state = Float64Array.of(q0, p0);
  // M, row-major, built up as J(z_{n−1}) ··· J(z_0)
  let [a, b, c, d] = [1, 0, 0, 1];
  for (let n = 0; n < period; n++) {
    const [j00, j01, j10, j11] = map.jacobian(state[0], state[1]);
    [a, b, c, d] = [j00 * a + j01 * c, j00 * b + j01 * d, j10 * a + j11 * c, j10 * b + j11 * d];
    map.step(state);
  }
  return (2 - (a + d)) / 4;
}

/** The Fibonacci number F_k, with F_1 = F_2 = 1. */
function fibonacci(k: number): number {
  let [a, b] = [1, 1];
  for (let i = 1; i < k; i++) [a, b] = [b, a + b];
  return a;
}

/** The deepest level of Greene's sequence computed here: F_25 = 75 025 iterates, where greeneLevels(24) takes some ten seconds (each level about 1.6 times the last). */
const DEEPEST_LEVEL = 24;

/** A symmetric periodic orbit of Greene's sequence. */
export interface GreeneOrbit {
  level: number;
  /** its rotation number is m/n = F_level/F_{level+1} */
  m: number;
  n: number;
  /** its point on the symmetry line q = π */
  q0: number;
  p0: number;
  /** Greene's residue (2 − tr M)/4 of the whole period */
  residue: number;
}

/**
 * The symmetric periodic orbit of rotation number m/n = F_k/F_{k+1}
 * (1/1, 1/2, 2/3, 3/5, 5/8 … → the golden mean (√5 − 1)/2) through the
 * symmetry line q = π, with its residue: Greene's sequence for the
 * golden-mean circle, found at every K from the same start.
 *
 * The map is reversible, T = I₂∘I₁ with the involutions
 * I₁(q, p) = (−q, p + K sin q) and I₂(q, p) = (p − q, p); I₁ fixes the lines
 * q = 0 and q = π. An orbit from q₀ = π is periodic, n = 2k, with
 * q_n = q₀ + 2πm, when its k-th point lies on I₁'s line q = π(1 + m), and
 * n = 2k − 1 when its k-th point lies on I₂'s (shifted) line
 * q_k + q_{k−1} = 2π(1 + m). Through q = π, which holds the elliptic fixed
 * point, pass the orbits of positive residue: the elliptic ones while K is
 * small (Greene's dominant symmetry line, x = 0 in his coordinates, where
 * the kick has the opposite sign).
 *
 * Rather than shoot from (π, p₀), whose error grows like the orbit's
 * instability (past the breakup, like √R, which is 10¹¹ at level 14 and K = 1.05),
 * the half orbit is solved as a boundary-value problem in the angles alone:
 * with p_t = q_t − q_{t−1} the map is q_{t+1} − 2q_t + q_{t−1} = K sin q_t,
 * and the deviations x_t of q_t from the uniform rotation π + 2πmt/n obey
 *
 *   x_{t+1} − 2x_t + x_{t−1} + K sin(2πmt/n + x_t) = 0,   t = 1 … k − 1,
 *
 * with x₀ = 0 and x_k = 0 (n even) or x_k = −x_{k−1} (n odd): a tridiagonal
 * system, solved by Newton's method from x = 0, the orbit at K = 0, with
 * the step halved until the residual falls. Its error stays at rounding
 * however unstable the orbit; the other half of the orbit is the mirror
 * image, x_{n−t} = −x_t.
 */
export function greeneOrbit(K: number, level: number): GreeneOrbit {
  checkK(K, 'greeneOrbit');
  checkWhole(level, 1, DEEPEST_LEVEL, 'greeneOrbit: the level');
  const m = fibonacci(level);
  const n = fibonacci(level + 1);
  const odd = n % 2 === 1;
  const k = odd ? (n + 1) / 2 : n / 2;
  // the uniform rotation's angles, reduced exactly through the integer m·t mod n, so sin and cos see small arguments
  const phase = (t: number) => (TWO_PI * ((m * t) % n)) / n;
  const x = new Float64Array(n + 1);
  const F = new Float64Array(k);
  const diagonal = new Float64Array(k);
  const step = new Float64Array(k);
  const sweep = new Float64Array(k);
  const trial = new Float64Array(k);

  /** The largest |F_t| at the deviations held in x[1 … k−1], with F filled in. */
  const residual = (): number => {
    let largest = 0;
    for (let t = 1; t < k; t++) {
      const next = t + 1 < k ? x[t + 1] : odd ? -x[t] : 0;
      F[t] = next - 2 * x[t] + x[t - 1] + K * Math.sin(phase(t) + x[t]);
      largest = Math.max(largest, Math.abs(F[t]));
    }
    return largest;
  };

  let size = residual();
  for (let iteration = 0; iteration < 100 && size > 0; iteration++) {
    // ∂F_t/∂x_t, with the last row's extra −1 when x_k = −x_{k−1}; the off-diagonals are 1
    for (let t = 1; t < k; t++) diagonal[t] = -2 + K * Math.cos(phase(t) + x[t]) - (odd && t === k - 1 ? 1 : 0);
    // the Thomas algorithm for J·step = −F
    for (let t = 1; t < k; t++) {
      const pivot = diagonal[t] - (t > 1 ? sweep[t - 1] : 0);
      sweep[t] = 1 / pivot;
      step[t] = (-F[t] - (t > 1 ? step[t - 1] : 0)) / pivot;
    }
    for (let t = k - 2; t >= 1; t--) step[t] -= sweep[t] * step[t + 1];
    trial.set(x.subarray(0, k));
    let scale = 1;
    let next = Infinity;
    for (let halving = 0; halving < 40; halving++, scale /= 2) {
      for (let t = 1; t < k; t++) x[t] = trial[t] + scale * step[t];
      next = residual();
      if (next < size) break;
    }
    if (!(next < size)) {
      // no step lowers the residual: it is at rounding, and the last accepted deviations stand
      x.set(trial);
      size = residual();
      break;
    }
    size = next;
    // Newton converges quadratically: after a step this small the residual is at rounding, and another would only confirm it
    let largest = 0;
    for (let t = 1; t < k; t++) largest = Math.max(largest, Math.abs(scale * step[t]));
    if (largest < 1e-12) break;
  }
  if (!(size < 1e-10)) throw new Error(`greeneOrbit: the orbit ${m}/${n} at K = ${K} was not found (residual ${size})`);

  if (odd) x[k] = -x[k - 1];
  for (let t = k + 1; t <= n; t++) x[t] = -x[n - t];
  // M = J(q_{n−1}) ··· J(q_0), with K cos q_t = −K cos(2πmt/n + x_t) since q_t = π + 2πmt/n + x_t.
  // Past the breakup the entries grow like R, beyond 10³⁰⁸ by level 20 at K = 1.05: M is carried as
  // 2^(SCALE·halvings) times a matrix kept below 2^SCALE, so the residue comes out ±∞, with its sign, rather than NaN.
  const SCALE = 500;
  let halvings = 0;
  let [a, b, c, d] = [1, 0, 0, 1];
  for (let t = 0; t < n; t++) {
    const kick = -K * Math.cos(phase(t) + x[t]);
    [a, b, c, d] = [(1 + kick) * a + c, (1 + kick) * b + d, kick * a + c, kick * b + d];
    if (Math.max(Math.abs(a), Math.abs(b), Math.abs(c), Math.abs(d)) > 2 ** SCALE) {
      [a, b, c, d] = [a * 2 ** -SCALE, b * 2 ** -SCALE, c * 2 ** -SCALE, d * 2 ** -SCALE];
      halvings++;
    }
  }
  const trace = halvings === 0 ? a + d : (a + d) * 2 ** (SCALE * halvings);
  // p₁ = q₁ − q₀ and p₁ = p₀ + K sin π = p₀
  return { level, m, n, q0: Math.PI, p0: (TWO_PI * m) / n + x[1], residue: (2 - trace) / 4 };
}

/** The residue of Greene's level-k orbit, rotation number F_k/F_{k+1}, at K (greeneOrbit). */
export function greeneResidueAt(K: number, level: number): number {
  return greeneOrbit(K, level).residue;
}

/** One level of Greene's sequence: the K at which its orbit's residue is 1/4. */
export interface GreeneLevel {
  level: number;
  m: number;
  n: number;
  K: number;
}

/**
 * Greene's estimate of the breakup, level by level: for each level from
 * `first` to `deepest`, the K in [0.9, 1.05] at which the residue of the
 * F_k/F_{k+1} orbit equals 1/4, by bisection. Greene's criterion: the
 * golden circle exists while the residues of its convergents tend to 0 and
 * is gone when they grow without bound; at the breakup they tend to a
 * universal 0.2500888 (MacKay 1983), so the K of residue 1/4 converge to
 * GREENE_K, the deeper the closer, since the residues' slope in K grows
 * with the level.
 */
export function greeneLevels(deepest: number, first = 5): GreeneLevel[] {
  checkWhole(first, 1, DEEPEST_LEVEL, 'greeneLevels: the first level');
  checkWhole(deepest, first, DEEPEST_LEVEL, 'greeneLevels: the deepest level');
  const levels: GreeneLevel[] = [];
  for (let level = first; level <= deepest; level++) {
    const excess = (K: number) => greeneResidueAt(K, level) - 0.25;
    let [low, high] = [0.9, 1.05];
    if (!(excess(low) < 0 && excess(high) >= 0)) throw new Error(`greeneLevels: the level-${level} residue does not cross 1/4 between K = ${low} and ${high}`);
    for (let i = 0; i < 60 && high - low > 1e-13; i++) {
      const mid = (low + high) / 2;
      if (excess(mid) < 0) low = mid;
      else high = mid;
    }
    levels.push({ level, m: fibonacci(level), n: fibonacci(level + 1), K: (low + high) / 2 });
  }
  return levels;
}

/** What one orbit of the standard map does, read off `iterations` iterates of it. */
export interface OrbitReading {
  /** the rotation number: the mean advance of the lifted angle per iterate, in turns, (q_N − q_0)/(2πN) */
  rotation: number;
  /** the largest Lyapunov exponent per iterate, from the tangent map along the orbit */
  lyapunov: number;
  /** the range of the unreduced p */
  pMin: number;
  pMax: number;
  /** whether the unreduced p ever moved more than 2π from its start: it crossed a band that an invariant circle would bar */
  crossed: boolean;
}

/**
 * One orbit of the standard map from `start`, read for its rotation number,
 * its Lyapunov exponent and its excursion in p. The angle is followed
 * unreduced (q_{n+1} = q_n + p_{n+1}), so its advance counts whole turns.
 * The exponent is Benettin's: a tangent vector carried by the Jacobian,
 * its growth logged and its length reset to 1 every iterate so it never
 * overflows; it tends to 0 like ln N/N on an invariant circle or island.
 */
export function orbitReading(K: number, start: readonly [number, number], iterations: number): OrbitReading {
  const map = standardMap(K);
  checkWhole(iterations, 1, 10_000_000, 'orbitReading: the number of iterations');
  const [q0, p0] = start;
  let [q, p] = [q0, p0];
  // a generic tangent direction, not an eigenvector of anything simple
  let [dq, dp] = [0.8, 0.6];
  let logGrowth = 0;
  let [pMin, pMax] = [p0, p0];
  let crossed = false;
  for (let n = 0; n < iterations; n++) {
    const [j00, j01, j10, j11] = map.jacobian(q, p);
    [dq, dp] = [j00 * dq + j01 * dp, j10 * dq + j11 * dp];
    const length = Math.hypot(dq, dp);
    logGrowth += Math.log(length);
    dq /= length;
    dp /= length;
    p += K * Math.sin(q);
    q += p;
    if (p < pMin) pMin = p;
    if (p > pMax) pMax = p;
    if (Math.abs(p - p0) > TWO_PI) crossed = true;
  }
  return { rotation: (q - q0) / (TWO_PI * iterations), lyapunov: logGrowth / iterations, pMin, pMax, crossed };
}
