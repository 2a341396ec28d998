/**
 * The truths exercises are graded against, by name: each is computed when
 * the exercise is checked, from arguments the exercise declares, never
 * stored. Each names the method and its source, which the verdict repeats,
 * and how exact it is, which the exercise's tolerance must exceed. They are
 * kept by subject in truths/, one module each.
 */
import type { Truth } from './truth.ts';
import { KEPLER_TRUTHS } from './truths/kepler.ts';
import { CHAOS_TRUTHS } from './truths/chaos.ts';
import { INTEGRATOR_TRUTHS } from './truths/integrators.ts';
import { OSCILLATOR_TRUTHS } from './truths/oscillators.ts';
import { PARAMETRIC_TRUTHS } from './truths/parametric.ts';
import { ADIABATIC_TRUTHS } from './truths/adiabatic.ts';
import { SCATTERING_TRUTHS } from './truths/scattering.ts';
import { RELATIVITY_TRUTHS } from './truths/relativity.ts';
import { THREE_BODY_TRUTHS } from './truths/three-body.ts';
import { STANDARD_MAP_TRUTHS } from './truths/standard-map.ts';
import { ACTION_ANGLE_TRUTHS } from './truths/action-angle.ts';
import { LIOUVILLE_TRUTHS } from './truths/liouville.ts';

export type { Truth } from './truth.ts';

export const TRUTHS: Readonly<Record<string, Truth>> = {
  ...OSCILLATOR_TRUTHS,
  ...PARAMETRIC_TRUTHS,
  ...KEPLER_TRUTHS,
  ...ADIABATIC_TRUTHS,
  ...SCATTERING_TRUTHS,
  ...RELATIVITY_TRUTHS,
  ...INTEGRATOR_TRUTHS,
  ...CHAOS_TRUTHS,
  ...THREE_BODY_TRUTHS,
  ...STANDARD_MAP_TRUTHS,
  ...ACTION_ANGLE_TRUTHS,
  ...LIOUVILLE_TRUTHS,
};

/** The truth's value for a declaration, or an error message naming what is wrong with it. */
export function computeTruth(name: string, args: Readonly<Record<string, number>>): { value: number; method: string } | { error: string } {
  const truth = Object.hasOwn(TRUTHS, name) ? TRUTHS[name] : undefined;
  if (!truth) return { error: `no truth named “${name}”: the book has ${Object.keys(TRUTHS).join(', ')}` };
  const missing = truth.args.filter((arg) => typeof args[arg] !== 'number' || !Number.isFinite(args[arg]));
  if (missing.length) return { error: `the truth ${name} needs the number${missing.length > 1 ? 's' : ''} ${missing.join(', ')}` };
  return { value: truth.compute(args), method: truth.method };
}
