/**
 * Long orbits, surfaces of section and the largest Lyapunov exponent of the
 * anisotropic Kepler problem, through its close approaches, by integrating
 * the Levi-Civita regularised flow (anisotropic-kepler.ts) in the fictitious
 * time s with the adaptive Dormand–Prince pair (integrators/dormand-prince.ts),
 * sampled every 1/SAMPLES_PER_TURN of the isotropic oscillator's turn.
 * Fixed steps suffice in s at isotropy; with a ≠ b the residual force near
 * the centre (∝ 1/√r, see anisotropic-kepler.ts) needs the step control.
 *
 * The section is the line v = 0 crossed with p_v > 0. Every bound orbit
 * crosses it, again and again: v̈ = −2b·k·v/r³, and r ≤ k/|E| on the energy
 * surface, so v obeys v̈ = −q(t)·v with q ≥ 2b·|E|³/k² > 0, and by Sturm's
 * comparison theorem it changes sign at least once every π·√(k²/(2b|E|³))
 * (returned as maxReturn). A line missing the centre would not do: orbits
 * near the heavy axis can stay on one side of it. The line passes through
 * the collision point, where p_u is unbounded; drawn in the Levi-Civita
 * coordinates of the crossing, σ = sign(u)·√|u| and π = 2√|u|·p_u (which
 * map area to area: ∂u/∂σ·∂p_u/∂π = 2|σ|·1/(2|σ|) = 1), the allowed region
 * a·π²/4 + |E|·σ² ≤ k is an ellipse with the collision at its centre line.
 * Scaled by its semi-axes, √(k/|E|) and 2√(k/a), it is the unit disk
 * whatever the parameters; those scaled coordinates are what is returned.
 *
 * In the (ξ, η) plane v = 2ξη vanishes on both axes: η = 0 is the half-line
 * u > 0, ξ = 0 is u < 0. A crossing is located by Hénon's trick (as in
 * poincare.ts): the axis coordinate becomes the independent variable and RK
 * 3/8 steps land on it, split into substeps short beside the distance √r to
 * the centre, where the field varies fastest.
 */
import { dormandPrince } from '../integrators/dormand-prince.ts';
import { rk38 } from '../integrators/rk38.ts';
import {
  type AnisotropicKepler,
  fromLeviCivita,
  regularisedField,
  regularisedHamiltonian,
  regularisedJacobian,
  toLeviCivita,
} from './anisotropic-kepler.ts';

/** Samples per turn of the isotropic oscillator, whose period in s is 2π/√((a + b)|E|/2). */
const SAMPLES_PER_TURN = 64;

export interface FlowOptions {
  /** the adaptive method's tolerances */
  rtol?: number;
  atol?: number;
}

const DEFAULT_TOLERANCES = { rtol: 1e-12, atol: 1e-12 };

/** The sampling interval in fictitious time, 1/SAMPLES_PER_TURN of the isotropic oscillator's turn. */
export function sampleInterval(system: AnisotropicKepler, energy: number): number {
  return (2 * Math.PI) / Math.sqrt(((system.a + system.b) * Math.abs(energy)) / 2) / SAMPLES_PER_TURN;
}

/** Sturm's bound on the physical time between two crossings of v = 0 with p_v > 0 (see above). */
export function maxReturn(system: AnisotropicKepler, energy: number): number {
  return 2 * Math.PI * Math.sqrt((system.k * system.k) / (2 * system.b * Math.abs(energy) ** 3));
}

/** The semi-axes of the section's allowed ellipse in (σ, π): √(k/|E|) and 2√(k/a). */
export function sectionScale(system: AnisotropicKepler, energy: number): { sigma: number; pi: number } {
  return { sigma: Math.sqrt(system.k / Math.abs(energy)), pi: 2 * Math.sqrt(system.k / system.a) };
}

/**
 * The regularised state [ξ, η, p_ξ, p_η, t = 0] on the section at the scaled
 * point (σ̂, π̂) of the unit disk, p_v > 0 solved from H = E; null outside
 * the disk, on its rim (p_v = 0) or at σ̂ = 0 (a collision).
 */
export function sectionLaunch(system: AnisotropicKepler, energy: number, sigmaHat: number, piHat: number): Float64Array | null {
  if (!(energy < 0) || !(sigmaHat * sigmaHat + piHat * piHat < 1) || sigmaHat === 0) return null;
  const scale = sectionScale(system, energy);
  const sigma = sigmaHat * scale.sigma;
  const u = sigma * Math.abs(sigma);
  const pu = (piHat * scale.pi) / (2 * Math.abs(sigma));
  const pv2 = (energy + system.k / Math.abs(u) - system.a * pu * pu) / system.b;
  if (!(pv2 > 0)) return null;
  const z = toLeviCivita([u, 0, pu, Math.sqrt(pv2)]);
  return Float64Array.of(z[0], z[1], z[2], z[3], 0);
}

/** The regularised state [ξ, η, p_ξ, p_η, t = 0] of a physical state [u, v, p_u, p_v]. */
export function regularisedStart(state: ArrayLike<number>): Float64Array {
  const z = toLeviCivita(state);
  return Float64Array.of(z[0], z[1], z[2], z[3], 0);
}

/** |H − E|/|E| at z, from K = r(H − E). */
function relativeEnergyError(system: AnisotropicKepler, energy: number, z: ArrayLike<number>): number {
  const r = z[0] * z[0] + z[1] * z[1];
  return Math.abs(regularisedHamiltonian(system, energy, z) / r / energy);
}

/**
 * Steps the flow of `field` (dimension dim, fictitious time) sample by
 * sample with the adaptive method. `z` holds the current sample; `next()`
 * advances it and returns false when the orbit could not be continued (an
 * exact collision, where the step falls to nothing, or a non-finite state).
 */
function sampler(field: (s: number, z: Float64Array, out: Float64Array) => void, dim: number, start: ArrayLike<number>, ds: number, tolerances: FlowOptions) {
  const stepper = dormandPrince(field, dim, { ...DEFAULT_TOLERANCES, ...tolerances });
  const z = Float64Array.from(start);
  const none = new Float64Array(0);
  let k = 0;
  return {
    z,
    stats: stepper.stats,
    next(): boolean {
      try {
        if (stepper.advance(z, 1, none, 0, k, ds, 1) < 1) return false;
      } catch {
        return false;
      }
      k++;
      return true;
    },
    /** call after changing z by hand: the method restarts from it as a new sample */
    restart() {
      k = 0;
    },
  };
}

export interface OrbitSamples {
  /** physical time and the physical state at each sample */
  t: number[];
  u: number[];
  v: number[];
  /** |H − E|/|E| at each sample */
  energyError: number[];
  /** L = u·p_v − v·p_u at each sample */
  angularMomentum: number[];
  finished: boolean;
}

/** Samples the orbit from `start` (regularised, as from sectionLaunch or regularisedStart) until physical time `time`. */
export function regularisedOrbit(system: AnisotropicKepler, energy: number, start: ArrayLike<number>, time: number, options: FlowOptions = {}): OrbitSamples {
  const run = sampler(regularisedField(system, energy), 5, start, sampleInterval(system, energy), options);
  const out: OrbitSamples = { t: [], u: [], v: [], energyError: [], angularMomentum: [], finished: true };
  const record = () => {
    const s = fromLeviCivita(run.z);
    out.t.push(run.z[4]);
    out.u.push(s[0]);
    out.v.push(s[1]);
    out.energyError.push(relativeEnergyError(system, energy, run.z));
    out.angularMomentum.push(s[0] * s[3] - s[1] * s[2]);
  };
  record();
  while (run.z[4] < time) {
    if (!run.next()) {
      out.finished = false;
      break;
    }
    record();
  }
  return out;
}

export interface KeplerSection {
  /** the crossings in the scaled section coordinates σ̂, π̂ (the unit disk) */
  sigma: number[];
  pi: number[];
  /** physical time of each crossing */
  times: number[];
  /**
   * the largest |H − E|/|E| at the crossings with |σ̂| ≥ 0.2, that is r ≥ 0.04·k/|E|:
   * inside an approach H is ill-conditioned (H − E = K/r magnifies the error of K),
   * and what matters is the energy the orbit carries away from it
   */
  energyError: number;
  /** the closest approach to the centre, r_min, over the samples, and how many samples were local minima of r below a hundredth of k/|E| */
  closest: number;
  approaches: number;
  /** physical time integrated */
  time: number;
  /** false if the orbit met an exact collision and could not be continued */
  finished: boolean;
}

export interface SectionRunOptions extends FlowOptions {
  /** stop after this many crossings */
  count?: number;
  /** or after this much physical time */
  maxTime?: number;
}

/** Integrates from `start` and records its crossings of v = 0 with p_v > 0. */
export function keplerSection(system: AnisotropicKepler, energy: number, start: ArrayLike<number>, options: SectionRunOptions = {}): KeplerSection {
  const { count = 300, maxTime = Infinity, ...tolerances } = options;
  const field = regularisedField(system, energy);
  const run = sampler(field, 5, start, sampleInterval(system, energy), tolerances);
  const scale = sectionScale(system, energy);
  const near = (0.01 * system.k) / Math.abs(energy);
  const out: KeplerSection = { sigma: [], pi: [], times: [], energyError: 0, closest: Infinity, approaches: 0, time: 0, finished: true };
  const before = new Float64Array(5);
  const hit = new Float64Array(5);
  const none = new Float64Array(0);
  // dz/dg = f/f_g for the axis coordinate g = z[axis], for Hénon's step onto g = 0.
  let axis = 0;
  const byAxis = rk38((s, z, o) => {
    field(s, z, o);
    const d = o[axis];
    for (let i = 0; i < 5; i++) o[i] /= d;
  }, 5);
  const land = (g: number) => {
    axis = g;
    // Start from the sample nearer the axis. The path to the axis passes the centre at about the
    // other coordinate's distance, |z[1 − g]|, the scale on which the field varies there: the
    // substeps are a fiftieth of it, and at least 16 to a sample interval, so that each turns the
    // orbit by less than 0.006 rad and RK 3/8's error, of order 0.006⁵, stays below the tolerance.
    hit.set(Math.abs(before[g]) < Math.abs(run.z[g]) ? before : run.z);
    const closest = Math.min(Math.hypot(hit[0], hit[1]), Math.abs(hit[1 - g]));
    const n = Math.min(5000, Math.max(16, Math.ceil(Math.abs(hit[g]) / (0.02 * closest))));
    byAxis.advance(hit, 1, none, 0, 0, -hit[g] / n, n);
    hit[g] = 0;
    const s = fromLeviCivita(hit);
    if (!(s[3] > 0)) return; // crossing downwards (p_v < 0)
    const u = s[0];
    out.sigma.push((Math.sign(u) * Math.sqrt(Math.abs(u))) / scale.sigma);
    out.pi.push((2 * Math.sqrt(Math.abs(u)) * s[2]) / scale.pi);
    out.times.push(hit[4]);
    if (Math.abs(out.sigma[out.sigma.length - 1]) >= 0.2) out.energyError = Math.max(out.energyError, relativeEnergyError(system, energy, hit));
  };
  let r1 = Infinity; // r at the sample before the last, and at the last
  let r2 = start[0] * start[0] + start[1] * start[1];
  while (out.sigma.length < count && run.z[4] < maxTime) {
    before.set(run.z);
    if (!run.next()) {
      out.finished = false;
      break;
    }
    const r = run.z[0] * run.z[0] + run.z[1] * run.z[1];
    if (r2 < r1 && r2 <= r && r2 < near) out.approaches++;
    out.closest = Math.min(out.closest, r);
    r1 = r2;
    r2 = r;
    // v = 2ξη changes sign when ξ or η does; each is a crossing of v = 0.
    // (A launch lies on an axis, at 0 exactly: it is not counted as a crossing.)
    for (const g of [0, 1]) {
      if ((before[g] < 0 && run.z[g] >= 0) || (before[g] > 0 && run.z[g] <= 0)) land(g);
    }
  }
  out.time = run.z[4];
  return out;
}

export interface KeplerLyapunov {
  /** λ at the final time, per unit of physical time */
  exponent: number;
  /** the running estimate λ(t) = ln‖δ(t)‖/t at the samples, about every `every` time units */
  times: number[];
  estimates: number[];
  /** the largest |H − E|/|E| over the samples with r ≥ 0.04·k/|E| (see KeplerSection) */
  energyError: number;
  finished: boolean;
}

export interface LyapunovRunOptions extends FlowOptions {
  /** physical time */
  time?: number;
  /** physical time between recorded estimates */
  every?: number;
  /** initial tangent vector in (ξ, η, p_ξ, p_η), normalised here */
  direction?: ArrayLike<number>;
}

/**
 * The largest Lyapunov exponent by tangent-space integration (Benettin et
 * al. 1980, as lyapunov.ts), in the regularised coordinates: dδ/ds = J·δ
 * with J the exact Jacobian of the regularised field, integrated with the
 * orbit by the same adaptive steps (its error control covers δ too). The
 * growth is averaged over physical time t, not s: λ = ln‖δ‖/t. The norm in
 * (ξ, η, p_ξ, p_η) differs from the physical one by factors bounded along a
 * bound orbit away from collisions, which do not change the exponent.
 *
 * At isotropy K is a harmonic oscillator whose frequency depends on E but
 * not on K, so the tangent flow is a rotation and ‖δ‖ stays bounded:
 * λ(t)·t stays bounded, the sharpest form of "zero".
 *
 * δ is rescaled only when its norm leaves [1e−50, 1e50], so the adaptive
 * method rarely restarts.
 */
export function keplerLyapunov(system: AnisotropicKepler, energy: number, start: ArrayLike<number>, options: LyapunovRunOptions = {}): KeplerLyapunov {
  const { time = 500, every = 1, direction = [1, 0.7, -0.3, 0.5], ...tolerances } = options;
  const field = regularisedField(system, energy);
  const J = new Float64Array(16);
  // z = [ξ, η, p_ξ, p_η, t, δ (4)]
  const augmented = (s: number, z: Float64Array, out: Float64Array) => {
    field(s, z, out);
    regularisedJacobian(system, energy, z, J);
    for (let i = 0; i < 4; i++) {
      let sum = 0;
      for (let j = 0; j < 4; j++) sum += J[i * 4 + j] * z[5 + j];
      out[5 + i] = sum;
    }
  };
  const z0 = new Float64Array(9);
  for (let i = 0; i < 5; i++) z0[i] = start[i] ?? 0;
  const norm0 = Math.hypot(...Array.from(direction));
  for (let i = 0; i < 4; i++) z0[5 + i] = direction[i] / norm0;
  const run = sampler(augmented, 9, z0, sampleInterval(system, energy), tolerances);
  const out: KeplerLyapunov = { exponent: NaN, times: [], estimates: [], energyError: 0, finished: true };
  const far = (0.04 * system.k) / Math.abs(energy);
  let logScale = 0;
  let nextRecord = every;
  while (run.z[4] < time) {
    if (!run.next()) {
      out.finished = false;
      break;
    }
    const z = run.z;
    if (z[0] * z[0] + z[1] * z[1] >= far) out.energyError = Math.max(out.energyError, relativeEnergyError(system, energy, z));
    const n = Math.hypot(z[5], z[6], z[7], z[8]);
    if (n > 1e50 || n < 1e-50) {
      logScale += Math.log(n);
      for (let i = 5; i < 9; i++) z[i] /= n;
      run.restart();
    }
    if (z[4] >= nextRecord || z[4] >= time) {
      out.times.push(z[4]);
      out.estimates.push((logScale + Math.log(Math.hypot(z[5], z[6], z[7], z[8]))) / z[4]);
      nextRecord = z[4] + every;
    }
  }
  out.exponent = out.estimates.length ? out.estimates[out.estimates.length - 1] : NaN;
  return out;
}
