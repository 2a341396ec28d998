/**
 * What the chapter's theory checks of the anisotropic Kepler problem need,
 * from one orbit (the paper's initial state, reduced to the relative motion)
 * integrated through its close approaches by the regularised flow
 * (core/analysis/anisotropic-kepler-flow.ts): twice, at the tolerance 1e−12
 * the figure uses and at 1e−10, so that each measured number comes with the
 * change a 100 times looser tolerance makes, the estimate of its
 * integration error. DOM-free: it runs in the section's worker.
 */
import { angularMomentum, keplerLyapunov, keplerSection, regularisedStart } from '../../../core/index.ts';
import { keplerSetting } from '../poincare-section/section-systems.ts';

const FINE = { rtol: 1e-12, atol: 1e-12 };
const COARSE = { rtol: 1e-10, atol: 1e-10 };

export interface KeplerRun {
  factor: number;
  /** H_rel = a·p_u² + b·p_v² − k/r */
  a: number;
  b: number;
  k: number;
  energy: number;
  /** m_heavy/m_light */
  mu: number;
  /** a = b to rounding: the Kepler problem */
  isotropic: boolean;
  /** L = u·p_v − v·p_u at the start, and whether it vanishes: a collision orbit, which meets v = 0 only at the centre */
  angularMomentum: number;
  collision: boolean;
  /** physical time integrated */
  time: number;
  /** mean time between crossings of v = 0 with p_v > 0, at both tolerances, and Kepler's third law for the mass 1/(2a) */
  period: { measured: number; coarse: number; kepler: number; crossings: number; last: number };
  /** the largest |H − E|/|E| at the crossings with r ≥ 0.04·k/|E| (`crossings` of them), at both tolerances; the close approaches passed */
  energyError: { measured: number; coarse: number; crossings: number; approaches: number; closest: number; scale: number };
  /** λ(T) at both tolerances, and the bound ln κ / T that a bounded tangent flow obeys at isotropy */
  exponent: { measured: number; coarse: number; bound: number; time: number };
}

export function keplerRun(factor: number, time: number): KeplerRun {
  if (!(time > 0 && time <= 1e5)) throw new RangeError(`the time must be between 0 and 1e5, not ${String(time)}`);
  const { system, state, energy, mu } = keplerSetting(factor);
  const start = regularisedStart(state);
  const fine = keplerSection(system, energy, start, { ...FINE, maxTime: time, count: Infinity });
  const coarse = keplerSection(system, energy, start, { ...COARSE, maxTime: time, count: Infinity });
  const mean = (t: number[]) => (t.length > 1 ? (t[t.length - 1] - t[0]) / (t.length - 1) : NaN);
  const m = 1 / (2 * system.a);
  const A = system.k / (2 * Math.abs(energy));
  const isotropic = Math.abs(system.a - system.b) <= 1e-12 * system.b;
  const lyapunov = keplerLyapunov(system, energy, start, { ...FINE, time });
  // Only at isotropy is the exponent compared, and only there is the second run needed.
  const looser = isotropic ? keplerLyapunov(system, energy, start, { ...COARSE, time }).exponent : NaN;
  // At isotropy each canonical pair of δ keeps ω²δq² + α²δp² (α = (a + b)/4, ω² = (a + b)|E|/2), so ‖δ‖ stays within a factor κ = max(α, ω)/min(α, ω) of its start.
  const alpha = (system.a + system.b) / 4;
  const omega = Math.sqrt(((system.a + system.b) * Math.abs(energy)) / 2);
  const T = lyapunov.times[lyapunov.times.length - 1] ?? NaN;
  const L = angularMomentum(state);
  return {
    factor,
    a: system.a,
    b: system.b,
    k: system.k,
    energy,
    mu,
    isotropic,
    angularMomentum: L,
    // compared with the angular momentum of a circular orbit at this energy, √(k·A/(2a))·…, to rounding
    collision: Math.abs(L) <= 1e-9 * Math.sqrt((system.k * A) / system.a),
    time,
    period: { measured: mean(fine.times), coarse: mean(coarse.times), kepler: 2 * Math.PI * Math.sqrt((m * A ** 3) / system.k), crossings: fine.times.length, last: fine.times[fine.times.length - 1] ?? NaN },
    energyError: { measured: fine.energyError, coarse: coarse.energyError, crossings: fine.sigma.filter((s) => Math.abs(s) >= 0.2).length, approaches: fine.approaches, closest: fine.closest, scale: system.k / Math.abs(energy) },
    exponent: { measured: lyapunov.exponent, coarse: looser, bound: Math.log(Math.max(alpha, omega) / Math.min(alpha, omega)) / T, time: T },
  };
}
