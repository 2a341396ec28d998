import { describe, expect, it } from 'vitest';
import { canonicalEquations, firstEvaluation, type Model } from '../../../../core/index.ts';

/** A model of one degree of freedom by hand: the route decides whether non-finite rates are a fault. */
function handModel(field: Model['field'], route: Model['route'], hamiltonian?: Model['hamiltonian']): Model {
  return { dof: 1, dim: 2, names: ['q', 'p'], paramNames: [], params: new Float64Array(0), route, field, hamiltonian } as unknown as Model;
}

describe('firstEvaluation(model, state, t0, derived)', () => {
  it('finds nothing wrong with the oscillator, and evaluates at the state given', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + q^2/2' });
    expect(firstEvaluation(model, [1, 0])).toEqual([]);
    const seen: number[] = [];
    firstEvaluation(model, [3, 4], 0, [{ name: 'r', evaluate: (_t, x, at) => (seen.push(x[at], x[at + 1]), 0) }]);
    expect(seen).toEqual([3, 4]);
  });

  it('reports H that is NaN or no number, and a derived series that throws, each by part', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + log(q)' });
    const faults = firstEvaluation(model, [-1, 0], 0, [{ name: 'I', evaluate: () => { throw new Error('I is broken'); } }]);
    expect(faults.map((f) => [f.part, f.reason])).toEqual([['H', 'NaN'], ['derived', 'threw']]);
    const text = handModel(() => {}, 'js-stencil', () => 'one' as unknown as number);
    expect(firstEvaluation(text, [1, 0])).toContainEqual({ part: 'H', name: undefined, reason: 'not a number', value: 'one' });
  });

  it('calls a vector field’s unwritten component a fault, a Hamiltonian route’s NaN rate not', () => {
    const halfField = handModel((_t, x, dxdt) => { dxdt[0] = x[1]; }, 'vector-field');
    expect(firstEvaluation(halfField, [1, 0])).toEqual([{ part: 'equations', reason: 'unset', component: 1 }]);
    const meeting = handModel((_t, _x, dxdt) => { dxdt[0] = NaN; dxdt[1] = NaN; }, 'expression');
    expect(firstEvaluation(meeting, [0, 0])).toEqual([]);
    const throwing = handModel(() => { throw new Error('k is not defined'); }, 'vector-field');
    expect(firstEvaluation(throwing, [1, 0])[0]).toMatchObject({ part: 'equations', reason: 'threw' });
  });
});
