import type { DerivedSeries } from '../simulation.ts';
import type { Model } from '../types.ts';

/** A part of a model that failed the first time it was evaluated, and how; the caller words it for its reader. */
export type EvaluationFault =
  | { readonly part: 'equations' | 'H' | 'derived'; readonly name?: string; readonly reason: 'threw'; readonly error: unknown }
  | { readonly part: 'H' | 'derived'; readonly name?: string; readonly reason: 'not a number'; readonly value: unknown }
  | { readonly part: 'H' | 'derived'; readonly name?: string; readonly reason: 'NaN' }
  | { readonly part: 'equations'; readonly reason: 'unset'; readonly component: number };

/**
 * Evaluates a model once at `state` (its first dim values) and time t0 —
 * the equations of motion, H, then each derived series — so that a mistake
 * (a name error in a JS function, H returning something other than a
 * number, a vector field that leaves a component unwritten) is found before
 * a run, not as NaN in its output. Returns every fault in that order, [] when
 * there is none.
 *
 * A vector field's non-finite rate is a fault: a component it forgot to
 * write. The rates a Hamiltonian's derivatives give are not: their NaN is the
 * physics (bodies that meet), which the run reports as a blow-up.
 */
export function firstEvaluation(model: Model, state: ArrayLike<number>, t0 = 0, derived: readonly DerivedSeries[] = []): EvaluationFault[] {
  const x = Float64Array.from(state);
  const faults: EvaluationFault[] = [];
  const rate = new Float64Array(model.dim).fill(NaN);
  try {
    model.field(t0, x, rate);
    const unset = model.route === 'vector-field' ? rate.findIndex((v) => !Number.isFinite(v)) : -1;
    if (unset >= 0) faults.push({ part: 'equations', reason: 'unset', component: unset });
  } catch (error) {
    faults.push({ part: 'equations', reason: 'threw', error });
  }
  const value = (part: 'H' | 'derived', name: string | undefined, f: () => unknown): void => {
    let v: unknown;
    try {
      v = f();
    } catch (error) {
      faults.push({ part, name, reason: 'threw', error });
      return;
    }
    if (typeof v !== 'number') faults.push({ part, name, reason: 'not a number', value: v });
    else if (Number.isNaN(v)) faults.push({ part, name, reason: 'NaN' });
  };
  const h = model.hamiltonian;
  if (h) value('H', undefined, () => h(t0, x, 0));
  for (const d of derived) value('derived', d.name, () => d.evaluate(t0, x, 0));
  return faults;
}
