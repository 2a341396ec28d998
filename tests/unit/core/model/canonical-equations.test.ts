import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { InputError } from '../../../../core/errors.ts';

const KEPLER_EXPRESSION = 'p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)';
// The paper's own code for 7.1, verbatim but for the comment.
const KEPLER_FUNCTION = `(t, qp) => {
  let [x1, y1, x2, y2, px1, py1, px2, py2] = qp;
  return px1**2 + py1**2 + px2**2 + py2**2 - 500 / hypot(x1-x2, y1-y2);
}`;
const START = [-3, -3, 3, 3, 2, -3, -2, 3];

/** ∇H of the Kepler model written by hand: the reference for the other routes. */
function keplerGradient(_t: number, x: Float64Array, g: Float64Array): void {
  const dx = x[0] - x[2];
  const dy = x[1] - x[3];
  const r3 = Math.pow(dx * dx + dy * dy, 1.5);
  g[0] = (500 * dx) / r3;
  g[1] = (500 * dy) / r3;
  g[2] = -g[0];
  g[3] = -g[1];
  for (let i = 4; i < 8; i++) g[i] = 2 * x[i];
}

async function finalState(spec: Parameters<typeof canonicalEquations>[0], steps = 4000): Promise<Float64Array> {
  const model = await canonicalEquations(spec);
  const x = Float64Array.from(START);
  expect(model.stepper.advance(x, 1, model.params, 0, 0, 5e-4, steps)).toBe(steps);
  return x;
}

describe('canonicalEquations(spec)', () => {
  it('routes an expression, a JS function and an opaque JS function to the same motion as a hand-written gradient', async () => {
    const reference = await finalState({ dof: 4, gradient: keplerGradient });
    const expression = await canonicalEquations({ dof: 4, hamiltonian: KEPLER_EXPRESSION });
    const translated = await canonicalEquations({ dof: 4, hamiltonian: KEPLER_FUNCTION });
    const stencil = await canonicalEquations({ dof: 4, hamiltonian: KEPLER_FUNCTION, differentiation: 'stencil' });
    expect(expression.route).toBe('expression');
    expect(translated.route).toBe('js-translated');
    expect(stencil.route).toBe('js-stencil');
    for (const [model, tolerance] of [
      [expression, 1e-11],
      [translated, 1e-11],
      // 5-point differences: about 1e-13 relative per derivative, accumulated over 4000 steps.
      [stencil, 1e-8],
    ] as const) {
      const x = Float64Array.from(START);
      model.stepper.advance(x, 1, model.params, 0, 0, 5e-4, 4000);
      for (let i = 0; i < 8; i++) expect(Math.abs(x[i] - reference[i])).toBeLessThan(tolerance);
    }
  });

  it('gives exact derivatives: field(t, x) equals the analytic Hamilton equations at a state', async () => {
    const model = await canonicalEquations({ dof: 4, hamiltonian: KEPLER_EXPRESSION });
    const x = Float64Array.from([0.3, -1.2, 2.5, 0.7, 1.1, -0.4, 0.2, 0.9]);
    const g = new Float64Array(8);
    keplerGradient(0, x, g);
    const rate = new Float64Array(8);
    model.field(0, x, rate);
    for (let i = 0; i < 4; i++) {
      expect(rate[i]).toBeCloseTo(g[i + 4], 13);
      expect(rate[i + 4]).toBeCloseTo(-g[i], 12);
    }
  });

  it('reads parameters live: writing model.params changes the motion without recompiling', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + omega^2*q^2/2', params: { omega: 1 } });
    model.params[0] = 2;
    const x = Float64Array.of(1, 0);
    model.stepper.advance(x, 1, model.params, 0, 0, 1e-3, 1000);
    expect(x[0]).toBeCloseTo(Math.cos(2), 10); // q = cos ωt with ω = 2 at t = 1
  });

  it('accepts the paper’s parameters as free names of a JS function, with Math by bare name', async () => {
    const model = await canonicalEquations({
      dof: 1,
      hamiltonian: '(t, qp) => { let [q, p] = qp; return p**2/2 + omega0**2*q**2/2 + alpha*q**3 + beta*q**4; }',
      params: { omega0: 10, alpha: -2, beta: -3 },
    });
    expect(model.route).toBe('js-translated');
    expect(model.hamiltonian!(0, Float64Array.of(1, 0))).toBe(50 - 2 - 3);
  });

  it('falls back to differences for a JS function it cannot translate, and says so', async () => {
    // A loop is beyond the translator (Math.min no longer is: min has exact derivative rules now).
    const model = await canonicalEquations({ dof: 1, hamiltonian: '(t, x) => { let h = 0; for (const v of [x[1]**2/2, x[0]**2/2]) h += v; return h; }' });
    expect(model.route).toBe('js-stencil');
    expect(model.accuracy).toMatch(/5-point/);
    const x = Float64Array.of(1, 0);
    model.stepper.advance(x, 1, model.params, 0, 0, 1e-3, 1000);
    expect(x[0]).toBeCloseTo(Math.cos(1), 9);
  });

  it('gives the LaTeX of H and of Hamilton’s equations', async () => {
    const model = await canonicalEquations({ dof: 1, hamiltonian: 'p^2/2 + omega0^2*q^2/2', params: { omega0: 10 } });
    const latex = model.latex!;
    expect(latex.hamiltonian).toContain('\\omega_{0}');
    expect(latex.equations[0]).toMatch(/^\\dot{q} = \\frac{\\partial H}{\\partial p} = \s*p$/);
    expect(latex.equations[1]).toMatch(/^\\dot{p} = -\\frac{\\partial H}{\\partial q} = .*\\omega_{0}.*q/);
  });

  it('accepts declared coordinate names', async () => {
    const model = await canonicalEquations({ dof: 2, hamiltonian: '(px^2 + py^2)/2 + (x^2 + y^2)/2', coordinates: ['x', 'y'], momenta: ['px', 'py'] });
    expect(model.names).toEqual(['x', 'y', 'px', 'py']);
    const rate = new Float64Array(4);
    model.field(0, Float64Array.of(1, 2, 3, 4), rate);
    expect(Array.from(rate)).toEqual([3, 4, -1, -2]);
  });

  it.each([
    ['p^2/2 + (q', /syntax error in H at column \d+/],
    ['p^2/2 + omega*q^2', /unknown name omega/],
    ['p^2/2 + foo(q)', /foo\(\), which is not a supported function/],
    ['(t, x) => x[1]**2/2 + * 3', /syntax error in H at line 1, column 23: Unexpected token/],
    ['(t, x) => x[1]**2/2 +', /syntax error in H: it ends too early/],
    ['', /H is empty/],
  ])('rejects %j with a one-line InputError', async (hamiltonian, message) => {
    const error = await canonicalEquations({ dof: 1, hamiltonian }).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(InputError);
    expect((error as Error).message).toMatch(message);
    expect((error as Error).message).not.toContain('\n');
  });
});
