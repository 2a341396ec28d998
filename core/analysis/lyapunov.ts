/**
 * The largest Lyapunov exponent by tangent-space integration (Benettin,
 * Galgani, Giorgilli & Strelcyn 1980, Meccanica 15, 9): the variational
 * equations dδ/dt = J(s(t))·δ, with J the exact Jacobian of the canonical
 * equations, are integrated alongside the orbit by the same RK 3/8 step;
 * every `renormEvery` time units the tangent vector's growth is logged and
 * it is scaled back to unit length, so it never overflows. The exponent is
 * the mean logarithmic growth rate, λ(t) = Σ ln‖δ‖ / t.
 *
 * For a regular (quasi-periodic) orbit ‖δ‖ grows at most linearly in t, so
 * λ(t) decays like ln t / t; for a chaotic one it tends to a positive limit.
 */
import { rk38 } from '../integrators/rk38.ts';
import type { PlanarSystem } from './henon-heiles.ts';

export interface LyapunovOptions {
  dt?: number;
  /** total time */
  time?: number;
  /** time between renormalisations of the tangent vector */
  renormEvery?: number;
  /** the initial tangent vector (normalised here); a generic direction by default */
  direction?: ArrayLike<number>;
}

export interface LyapunovResult {
  /** λ at the final time */
  exponent: number;
  /** the running estimate λ(t) at each renormalisation */
  times: number[];
  estimates: number[];
  /** |H(end) − H(start)|: the integrator's energy error, to judge the run by */
  energyError: number;
  /** false if the orbit left (non-finite state) before the end */
  finished: boolean;
}

export function largestLyapunov(system: PlanarSystem, start: ArrayLike<number>, options: LyapunovOptions = {}): LyapunovResult {
  const { dt = 0.02, time = 1000, renormEvery = 1 } = options;
  const J = new Float64Array(16);
  // State and tangent vector together: z = [s (4), δ (4)], dz/dt = [f(s), J(s)·δ].
  const step = rk38((t, z, out) => {
    system.field(t, z, out);
    system.jacobian(z, J);
    for (let i = 0; i < 4; i++) {
      let sum = 0;
      for (let j = 0; j < 4; j++) sum += J[i * 4 + j] * z[4 + j];
      out[4 + i] = sum;
    }
  }, 8);
  const z = new Float64Array(8);
  for (let i = 0; i < 4; i++) z[i] = start[i];
  const direction = options.direction ?? [1, 0.7, -0.3, 0.5];
  const norm0 = Math.hypot(...Array.from(direction));
  for (let i = 0; i < 4; i++) z[4 + i] = direction[i] / norm0;
  const energy0 = system.energy(z);
  const stepsPerRenorm = Math.max(1, Math.round(renormEvery / dt));
  const blocks = Math.max(1, Math.round(time / (stepsPerRenorm * dt)));
  const none = new Float64Array(0);
  const result: LyapunovResult = { exponent: NaN, times: [], estimates: [], energyError: NaN, finished: true };
  let logSum = 0;
  for (let b = 0; b < blocks; b++) {
    const done = step.advance(z, 1, none, 0, b * stepsPerRenorm, dt, stepsPerRenorm);
    if (done < stepsPerRenorm) {
      result.finished = false;
      break;
    }
    const n = Math.hypot(z[4], z[5], z[6], z[7]);
    logSum += Math.log(n);
    for (let i = 4; i < 8; i++) z[i] /= n;
    const t = (b + 1) * stepsPerRenorm * dt;
    result.times.push(t);
    result.estimates.push(logSum / t);
  }
  result.exponent = result.estimates.length ? result.estimates[result.estimates.length - 1] : NaN;
  result.energyError = Math.abs(system.energy(z) - energy0);
  return result;
}
