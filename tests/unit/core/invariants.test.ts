import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../core/model/canonical-equations.ts';
import { evaluateAlong, relativeDrift } from '../../../core/invariants.ts';
import { Simulation } from '../../../core/simulation.ts';

describe('invariants', () => {
  it('relativeDrift(values) is max |I − I0| / |I0|, and absolute when I0 = 0', () => {
    expect(relativeDrift([2, 2.5, 1, 2])).toBe(0.5);
    expect(relativeDrift([0, 1e-3, -2e-3])).toBe(2e-3);
    expect(relativeDrift([])).toBe(0);
  });

  it('evaluateAlong(table, f) evaluates the action I = H/ω along an adiabatic ramp, which stays nearly constant', async () => {
    // Paper 7.2: H = p²/2 + ω(t)²q²/2 with ω = 4 + 0.05t. The action I = H/ω is an adiabatic invariant
    // (Landau & Lifshitz, Mechanics §49): with ω̇/ω² ≈ 0.003 its change stays at the 1e-3 level, while H itself grows with ω.
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + (4 + 0.05 t)^2 q^2/2' });
    const sim = new Simulation(model, { initial: [1, 0], every: 20 });
    sim.run(100_000); // t = 50: ω from 4 to 6.5
    const table = sim.record.table();
    const action = evaluateAlong(table, (t, x, o) => model.hamiltonian!(t, x, o) / (4 + 0.05 * t));
    const H = sim.record.column('H');
    expect(H[H.length - 1] / H[0]).toBeCloseTo(6.5 / 4, 1); // H ∝ ω when I is fixed
    expect(relativeDrift(action)).toBeLessThan(1e-2);
    // The same, evaluated independently of the model: I = (p²/2 + ω²q²/2)/ω from the recorded state.
    const direct = evaluateAlong(table, (t, x, o) => {
      const w = 4 + 0.05 * t;
      return (x[o + 1] ** 2 / 2 + (w * w * x[o] ** 2) / 2) / w;
    });
    for (let i = 0; i < direct.length; i += 97) expect(action[i]).toBeCloseTo(direct[i], 12);
  });
});
