/**
 * The physics the check sweeps (check-sweeps.test.mjs) judge the pages by,
 * computed here and independently of the page: closed forms, conservation
 * laws, and numerical methods written out in this file (classical RK4, a
 * period integral, a direct windowed Fourier sum), never the book's core.
 * Each function names its source.
 *
 * And the rule that turns them into the verdict a check must give:
 * {@link expectedVerdict}.
 */

/**
 * The verdict a check must give, from the test's own physics:
 * - 'outside' when the test's own evaluation of the formula's regime fails;
 * - 'agrees' when the formula is within its stated error of the truth,
 *   |reference − predicted| ≤ formula: a measurement within its own stated
 *   errors of the truth (asserted separately) then lies inside their sum;
 * - 'disagrees' when the formula misses the truth by more than its error plus
 *   twice the measurement's and the integrator's, so that no measurement
 *   within those errors of the truth could agree;
 * - 'ambiguous' in between, where the verdict depends on where the
 *   measurement falls inside its errors: a sweep must not use such a point.
 * `formula` and `slack` are fractions of |predicted| when `relative`.
 */
export function expectedVerdict({ valid, reference, predicted, formula, slack, relative = false }) {
  if (!valid) return 'outside';
  const missed = Math.abs(reference - predicted) / (relative ? Math.abs(predicted) : 1);
  if (missed <= formula) return 'agrees';
  if (missed > formula + 2 * slack) return 'disagrees';
  return 'ambiguous';
}

/** "≪ 1" as the book reads it (widgets/chapter/theory-check/check-verdict.ts): at most a third. */
export const SMALL = 1 / 3;

/**
 * The classical Runge–Kutta method (Hairer, Nørsett & Wanner I, §II.1, the
 * "classical" 1/6, 1/3, 1/3, 1/6 scheme, not the book's 3/8 rule), n steps of
 * h for ẋ = rate(t, x) from x at t. Returns the final state.
 */
export function rk4(rate, x, t, h, n, each) {
  let y = Float64Array.from(x);
  const d = y.length;
  const at = (base, k, c) => Float64Array.from(base, (v, i) => v + c * k[i]);
  for (let s = 0; s < n; s++) {
    const time = t + s * h;
    const k1 = rate(time, y);
    const k2 = rate(time + h / 2, at(y, k1, h / 2));
    const k3 = rate(time + h / 2, at(y, k2, h / 2));
    const k4 = rate(time + h, at(y, k3, h));
    const next = new Float64Array(d);
    for (let i = 0; i < d; i++) next[i] = y[i] + (h / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    y = next;
    each?.(time + h, y);
  }
  return y;
}

/**
 * The Runge–Kutta 3/8 rule (Kutta 1901; Hairer, Nørsett & Wanner I, Table
 * II.1.1), written out here for the Introduction's order check: its global
 * error is what that check measures.
 */
export function rk38(rate, x, t, h, n) {
  let y = Float64Array.from(x);
  const d = y.length;
  for (let s = 0; s < n; s++) {
    const time = t + s * h;
    const k1 = rate(time, y);
    const k2 = rate(time + h / 3, y.map((v, i) => v + (h / 3) * k1[i]));
    const k3 = rate(time + (2 * h) / 3, y.map((v, i) => v + h * (-k1[i] / 3 + k2[i])));
    const k4 = rate(time + h, y.map((v, i) => v + h * (k1[i] - k2[i] + k3[i])));
    const next = new Float64Array(d);
    for (let i = 0; i < d; i++) next[i] = y[i] + (h / 8) * (k1[i] + 3 * k2[i] + 3 * k3[i] + k4[i]);
    y = next;
  }
  return y;
}

/** Hamilton's equations of the paper's default model, H = p²/2 + ω²(1 + u cos γt)q²/2 − fq cos(κt + β). */
export function defaultModel({ u, gamma, beta, kappa, omega, f }) {
  return (t, [q, p]) => [p, -omega * omega * (1 + u * Math.cos(gamma * t)) * q + f * Math.cos(kappa * t + beta)];
}

/**
 * Floquet data of q̈ + ω²(1 + u cos γt)q = 0 (Landau & Lifshitz §27; Arnold
 * §25): the monodromy matrix over T = 2π/γ by classical RK4, its trace, the
 * growth rate ln|λ_max|/T, and, for a start (q0, p0), the share ρ of the
 * decaying solution in the motion at time `from`, measured in (q, p/ω).
 */
export function mathieuFloquet({ u, gamma, omega }, { start = [2, 0], from = 10, steps = 4000 } = {}) {
  const T = (2 * Math.PI) / gamma;
  const rate = defaultModel({ u, gamma, beta: 0, kappa: 0, omega, f: 0 });
  const [m11, m21] = rk4(rate, [1, 0], 0, T / steps, steps);
  const [m12, m22] = rk4(rate, [0, 1], 0, T / steps, steps);
  const trace = m11 + m22;
  const half = trace / 2;
  if (Math.abs(half) < 1) return { trace, stable: true, growth: 0, decaying: 0 };
  const big = half + Math.sign(half) * Math.sqrt(half * half - 1);
  const small = 1 / big;
  // eigenvectors (m12, λ − m11) of M = [[m11, m12], [m21, m22]]
  const g = [m12, big - m11];
  const d = [m12, small - m11];
  const det = g[0] * d[1] - d[0] * g[1];
  const [q0, p0] = start;
  const cg = (q0 * d[1] - d[0] * p0) / det;
  const cd = (g[0] * p0 - q0 * g[1]) / det;
  const size = ([a, b]) => Math.hypot(a, b / omega);
  const decaying = ((Math.abs(cd) * size(d)) / (Math.abs(cg) * size(g))) * Math.abs(small / big) ** (from / T);
  return { trace, stable: false, growth: Math.log(Math.abs(big)) / T, decaying };
}

/** Landau & Lifshitz §27 to first order in u: s = ½√((uω/2)² − (γ − 2ω)²) inside the band, 0 outside. */
export function firstOrderGrowth({ u, gamma, omega }) {
  const half = (Math.abs(u) * omega) / 2;
  const epsilon = gamma - 2 * omega;
  return Math.abs(epsilon) < half ? 0.5 * Math.sqrt(half * half - epsilon * epsilon) : 0;
}

/**
 * The regime of the first-order formula, and its stated error (the
 * parametric-resonance chapter's error model, rederived here): the next order
 * moves the band down by δ = u²ω/32 (Landau & Lifshitz §27, problem 1), the
 * one after by uδ; the formula's error is the largest change of s over that
 * move plus uδ. Inside the band it holds while that is at most a third of s;
 * outside, while the moved band stays clear of γ. And |u| < 1 keeps the
 * stiffness positive.
 */
export function firstOrderRegime({ u, gamma, omega }) {
  const half = (Math.abs(u) * omega) / 2;
  const rate = (e) => (Math.abs(e) < half ? 0.5 * Math.sqrt(half * half - e * e) : 0);
  const epsilon = gamma - 2 * omega;
  const s = rate(epsilon);
  const shift = (u * u * omega) / 32;
  const ends = [epsilon + shift * (1 - Math.abs(u)), epsilon + shift * (1 + Math.abs(u))];
  const moved = [...ends, ...(ends[0] < 0 && ends[1] > 0 ? [0] : [])].map(rate);
  const neglected = Math.max(...moved.map((r) => Math.abs(r - s))) + Math.abs(u) * shift;
  const inside = Math.abs(epsilon) < half;
  const clear = inside ? neglected <= s * SMALL : moved.every((r) => r === 0);
  return { s, neglected, valid: Math.abs(u) < 1 && clear };
}

/**
 * The nonlinear oscillator V(q) = ω0²q²/2 + αq³ + βq⁴ released at rest from
 * q = b: whether it stays in the well (its energy below the lower barrier,
 * the first maxima of V on either side of 0), and if so its exact angular
 * frequency from the period integral T = 2∮dq/√(2(E − V)) between the
 * turning points, with q = c + d sin θ taking out the endpoint singularities
 * (midpoint rule, spectrally accurate for the smooth integrand).
 */
export function anharmonic({ omega0, alpha, beta }, b) {
  const V = (q) => (omega0 ** 2 * q ** 2) / 2 + alpha * q ** 3 + beta * q ** 4;
  const E = V(b);
  // The barriers: V'(q) = q(ω0² + 3αq + 4βq²) = 0 away from 0, when β < 0 or α ≠ 0.
  const roots = [];
  if (beta !== 0) {
    const disc = 9 * alpha ** 2 - 16 * beta * omega0 ** 2;
    if (disc >= 0) for (const sign of [1, -1]) roots.push((-3 * alpha + sign * Math.sqrt(disc)) / (8 * beta));
  } else if (alpha !== 0) roots.push(-(omega0 ** 2) / (3 * alpha));
  const maxima = roots.filter((q) => omega0 ** 2 + 6 * alpha * q + 12 * beta * q * q < 0);
  const barrier = maxima.length ? Math.min(...maxima.map(V)) : Infinity;
  const side = (sign) => maxima.filter((q) => Math.sign(q) === sign);
  // Escape amplitude on each side: where V first reaches the lower barrier.
  const escape = (sign) => {
    const limit = side(sign).length ? Math.abs(side(sign)[0]) : 1e3;
    let lo = 0;
    let hi = limit;
    if (V(sign * hi) < barrier) return Infinity;
    for (let i = 0; i < 200; i++) {
      const mid = (lo + hi) / 2;
      if (V(sign * mid) < barrier) lo = mid;
      else hi = mid;
    }
    return lo;
  };
  const bound = E < barrier && (b > 0 ? b < escape(1) : -b < escape(-1));
  if (!bound) return { bound, E, barrier };
  // The other turning point: where V = E on the other side of 0.
  let far = -b;
  while (V(far) < E) far *= 1.01;
  let near = 0;
  for (let i = 0; i < 200; i++) {
    const mid = (far + near) / 2;
    if (V(mid) < E) near = mid;
    else far = mid;
  }
  const other = (far + near) / 2;
  const c = (b + other) / 2;
  const d = (b - other) / 2;
  const n = 40000;
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const theta = -Math.PI / 2 + ((i + 0.5) * Math.PI) / n;
    const q = c + d * Math.sin(theta);
    const gap = 2 * (E - V(q));
    sum += (Math.abs(d) * Math.cos(theta)) / Math.sqrt(Math.max(gap, 1e-300));
  }
  const period = (2 * sum * Math.PI) / n;
  return { bound, E, barrier, omega: (2 * Math.PI) / period };
}

/** The Lindstedt frequency to O(b²) and its stated error (Landau & Lifshitz §28, in the paper's coefficients). */
export function lindstedt({ omega0, alpha, beta }, b) {
  const omega2 = (3 * beta) / (2 * omega0) - (15 * alpha ** 2) / (4 * omega0 ** 3);
  const neglected = Math.abs(((2 * alpha * omega2) / omega0 ** 2) * b ** 3) + (omega2 * b ** 2) ** 2 / omega0;
  return { omega: omega0 + omega2 * b ** 2, neglected, kept: Math.abs(omega2) * b ** 2 };
}

/**
 * The two stars of the paper's §7.1 (masses 1/2, μ = 1/4) reduced to their
 * relative motion (Landau & Lifshitz §15; Goldstein §3.7–3.9): E, a, e, the
 * period by Kepler's third law, the total L, the direction of A = p × L − μk r̂,
 * and the pericentre's time scale r_p/v_p.
 */
export function keplerElements([x1, y1, x2, y2, px1, py1, px2, py2], k) {
  const mu = 0.25;
  const rx = x1 - x2;
  const ry = y1 - y2;
  const r = Math.hypot(rx, ry);
  const px = (px1 - px2) / 2;
  const py = (py1 - py2) / 2;
  const E = (px * px + py * py) / (2 * mu) - k / r;
  const a = -k / (2 * E);
  const l = rx * py - ry * px;
  const A = [py * l - (mu * k * rx) / r, -px * l - (mu * k * ry) / r];
  const e = Math.hypot(...A) / (mu * k);
  const rp = a * (1 - e);
  const vp = Math.sqrt((2 * (E + k / rp)) / mu);
  return {
    E,
    a,
    e,
    T: E < 0 ? 2 * Math.PI * Math.sqrt((mu * a ** 3) / k) : NaN,
    L: x1 * py1 - y1 * px1 + x2 * py2 - y2 * px2,
    angle: Math.atan2(A[1], A[0]),
    tauP: rp / vp,
  };
}

/**
 * The largest |I/I0 − 1| of the oscillator ω(t) = ω0 + εt over 0 ≤ t ≤ T,
 * I = H/ω, from (q0, p0), by classical RK4 with a step of h, sampled every
 * step: the truth that the first-order adiabatic formula predicts.
 */
export function adiabaticExcursion({ omega0, epsilon }, [q0, p0], { T = 60, h = 2.5e-4 } = {}) {
  const omega = (t) => omega0 + epsilon * t;
  const action = (t, [q, p]) => (p * p / 2 + (omega(t) ** 2 * q * q) / 2) / omega(t);
  const I0 = action(0, [q0, p0]);
  let worst = 0;
  rk4((t, [q, p]) => [p, -(omega(t) ** 2) * q], [q0, p0], 0, h, Math.round(T / h), (t, x) => {
    worst = Math.max(worst, Math.abs(action(t, x) / I0 - 1));
  });
  return worst;
}

/** The first-order adiabatic wobble and its stated relative error (the chapter's formula, Landau & Lifshitz §49–51). */
export function adiabaticWobble({ omega0, epsilon }, [q0, p0], T = 60) {
  const I0 = (p0 ** 2 / 2 + (omega0 ** 2 * q0 ** 2) / 2) / omega0;
  const omegaMin = Math.min(Math.abs(omega0), Math.abs(omega0 + epsilon * T));
  return {
    predicted: (Math.abs(epsilon) / 2) * (1 / omegaMin ** 2 + Math.abs(q0 * p0) / (I0 * omega0 ** 2)),
    neglected: ((2 * Math.PI + 2) * Math.abs(epsilon)) / omegaMin ** 2,
    positive: omega0 > 0 && omega0 + epsilon * T > 0,
  };
}

/**
 * ⟨ΔI/I0⟩ over the initial phase for ω rising linearly from ω0 to ω1 in τ:
 * the transfer matrix of the ramp by classical RK4, and the phase average of
 * the quadratic form I1/I0 done exactly (for a start (cos φ, −ω0 sin φ),
 * ⟨q²⟩ = ½, ⟨p²⟩ = ω0²/2, ⟨qp⟩ = 0).
 */
export function rampChange({ omega0, omega1, T_r: tau }, steps = 4000) {
  const omega = (t) => omega0 + ((omega1 - omega0) * t) / tau;
  const rate = (t, [q, p]) => [p, -(omega(t) ** 2) * q];
  const [a, c] = rk4(rate, [1, 0], 0, tau / steps, steps);
  const [b, d] = rk4(rate, [0, 1], 0, tau / steps, steps);
  // After the ramp: q = a q0 + b p0, p = c q0 + d p0.
  const meanQ2 = (a * a + b * b * omega0 ** 2) / 2;
  const meanP2 = (c * c + d * d * omega0 ** 2) / 2;
  const I1 = (meanP2 / 2 + (omega1 ** 2 * meanQ2) / 2) / omega1;
  const I0 = omega0 / 2;
  return I1 / I0 - 1;
}

/** The τ² correction to the sudden limit and the chapter's estimate of the terms beyond (the chapter's formula). */
export function suddenLimit({ omega0: w0, omega1: w1, T_r: tau }) {
  const sudden = (w1 / w0 + w0 / w1) / 2 - 1;
  const correction = (((w1 - w0) ** 2 * (w0 ** 2 + 4 * w0 * w1 + w1 ** 2)) / (36 * w0 * w1)) * tau ** 2;
  return { sudden, neglected: correction * (1 + (Math.max(w0, w1) * tau) ** 2) };
}

/**
 * The exact deflection of a particle of mass m started at (x, y) with momentum
 * (px, py) in U = α/r: the orbit's axis lies along the Laplace–Runge–Lenz
 * vector A = p × L + mα r̂ and the asymptotes at arccos(1/e) from it,
 * e = |A|/mα (Goldstein §3.9–3.10).
 */
export function exactDeflection(x, y, px, py, alpha, m) {
  const r = Math.hypot(x, y);
  const L = x * py - y * px;
  const ax = py * L + (m * alpha * x) / r;
  const ay = -px * L + (m * alpha * y) / r;
  const e = Math.hypot(ax, ay) / (m * alpha);
  const out = Math.atan2(ay, ax) + Math.sign(L) * Math.acos(1 / e);
  return Math.abs(Math.atan2(px * Math.sin(out) - py * Math.cos(out), px * Math.cos(out) + py * Math.sin(out)));
}

/** Rutherford (Landau & Lifshitz §19): tan(θ/2) = |α|/(2E b). */
export const rutherford = (b, E, alpha) => 2 * Math.atan(Math.abs(alpha) / (2 * E * Math.abs(b)));

/**
 * The closest approach r_min of the exact orbit and the time scale r_min/v_max
 * of the passage, from energy and angular momentum conservation:
 * E = p²/2m + α/r, r_min the larger root of E r² − α r − L²/2m = 0.
 */
export function closestApproach(x0, b, p0, alpha, m) {
  const E = (p0 * p0) / (2 * m) + alpha / Math.hypot(x0, b);
  const L = Math.abs(b * p0);
  const rMin = (alpha + Math.sqrt(alpha * alpha + (2 * E * L * L) / m)) / (2 * E);
  const vMax = Math.sqrt((2 * Math.max(E, E - alpha / rMin)) / m);
  return { E, rMin, tau: rMin / vMax };
}

/** Hyperbolic motion under a constant force (Landau & Lifshitz, Fields §20): p = p0 + Ft, q = q0 + (E − E0)/F, v = p/E. */
export function hyperbolic({ m, F }, [q0, p0], t) {
  const p = p0 + F * t;
  const E = Math.sqrt(p * p + m * m);
  const E0 = Math.sqrt(p0 * p0 + m * m);
  return { q: F === 0 ? q0 + (p0 / E0) * t : q0 + (E - E0) / F, v: p / E };
}

/** The complete elliptic integral K(k) by the arithmetic–geometric mean (Abramowitz & Stegun 17.6). */
export function ellipticK(k) {
  let a = 1;
  let g = Math.sqrt(1 - k * k);
  for (let i = 0; i < 60 && Math.abs(a - g) > 1e-16 * a; i++) [a, g] = [(a + g) / 2, Math.sqrt(a * g)];
  return Math.PI / (2 * a);
}

/**
 * The pendulum H = p²/2 − ω0² cos q from a start: its amplitude θ0 from the
 * energy (cos θ0 = −H/ω0²), the exact period 4K(sin θ0/2)/ω0 (Landau &
 * Lifshitz §11), the series to θ0² and the template's stated error of it.
 */
export function pendulum(omega0, [q0, p0]) {
  const H = (p0 * p0) / 2 - omega0 ** 2 * Math.cos(q0);
  const swings = H < omega0 ** 2;
  const theta0 = swings ? Math.acos(Math.max(-1, -H / omega0 ** 2)) : NaN;
  const kept = theta0 ** 2 / 16;
  const left = (11 * theta0 ** 4) / 3072 / (1 - (theta0 / Math.PI) ** 2);
  return {
    swings,
    theta0,
    exact: swings ? (4 / omega0) * ellipticK(Math.sin(theta0 / 2)) : NaN,
    predicted: ((2 * Math.PI) / omega0) * (1 + kept),
    neglected: left / (1 + kept),
    valid: swings && left <= kept * SMALL,
  };
}

/**
 * |Σ w_j y_j e^{−2πi f t_j}| / Σ w_j with Hamming weights (the paper's eq. 6),
 * the windowed amplitude of the samples y at frequency f, summed directly.
 */
export function windowedAmplitude(y, interval, f) {
  const n = y.length;
  let re = 0;
  let im = 0;
  let weights = 0;
  const mean = y.reduce((a, b) => a + b, 0) / n;
  for (let j = 0; j < n; j++) {
    const w = 25 / 46 - (21 / 46) * Math.cos((2 * Math.PI * j) / n);
    const phase = 2 * Math.PI * f * j * interval;
    re += w * (y[j] - mean) * Math.cos(phase);
    im -= w * (y[j] - mean) * Math.sin(phase);
    weights += w;
  }
  return (2 * Math.hypot(re, im)) / weights;
}

/**
 * The two stars of the Kepler chapter, H = Σp² − k/√((c·x1 − x2)² + (y1 − y2)²)
 * (c = 1 is Kepler's problem, c = 1.5 the chapter's broken symmetry),
 * integrated here by classical RK4 over `duration`: the mean spacing of the
 * upward zero crossings of y1 − y2, and the values of the total angular
 * momentum and of the direction of the relative Laplace–Runge–Lenz vector
 * farthest from their starting values.
 */
export function twoStars({ k, c = 1 }, initial, duration, h = 5e-4) {
  const rate = (t, [x1, y1, x2, y2, px1, py1, px2, py2]) => {
    const dx = c * x1 - x2;
    const dy = y1 - y2;
    const f = k / Math.hypot(dx, dy) ** 3;
    return [2 * px1, 2 * py1, 2 * px2, 2 * py2, -f * c * dx, -f * dy, f * dx, f * dy];
  };
  const angularMomentum = ([x1, y1, x2, y2, px1, py1, px2, py2]) => x1 * py1 - y1 * px1 + x2 * py2 - y2 * px2;
  const direction = (x) => keplerElements(x, k).angle;
  const L0 = angularMomentum(initial);
  const A0 = direction(initial);
  let L = L0;
  let angle = A0;
  const up = [];
  let last = initial[1] - initial[3];
  let lastT = 0;
  rk4(rate, initial, 0, h, Math.ceil(duration / h), (t, x) => {
    if (Math.abs(angularMomentum(x) - L0) > Math.abs(L - L0)) L = angularMomentum(x);
    const turn = (a) => Math.abs(Math.atan2(Math.sin(a - A0), Math.cos(a - A0)));
    if (turn(direction(x)) > turn(angle)) angle = direction(x);
    const dy = x[1] - x[3];
    if (last < 0 && dy >= 0) up.push(lastT + (last / (last - dy)) * (t - lastT));
    [last, lastT] = [dy, t];
  });
  const period = up.length > 1 ? (up[up.length - 1] - up[0]) / (up.length - 1) : NaN;
  return { period, L, angle };
}

/** A seeded uniform generator on [0, 1) (mulberry32): the suite's own random numbers, reproducible, and independent of the book's. */
export function seededUniform(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
