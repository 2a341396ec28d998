/**
 * Which H the splitting methods take: H = T(p) + V(q, t), read off the
 * derivative trees (expression/separable.ts). The truth of each case is the
 * form of H itself, worked by hand.
 */
import { describe, expect, it } from 'vitest';
import { canonicalEquations } from '../../../../core/model/canonical-equations.ts';
import { hamiltonEquations, parseHamiltonian } from '../../../../core/expression/compile-expression.ts';
import { loadMathjs } from '../../../../core/expression/mathjs.ts';
import { separability } from '../../../../core/expression/separable.ts';
import { methodChoice } from '../../../../core/integrators/methods.ts';

async function separates(source: string, dof = 1, paramNames: string[] = []) {
  const math = await loadMathjs();
  const parsed = parseHamiltonian(math, { source, dof, paramNames });
  const { rates } = await hamiltonEquations(math, parsed);
  const derivatives = parsed.names.map((_, i) => rates[i < dof ? i + dof : i - dof].node);
  return separability(parsed.names, derivatives);
}

describe('separability of H into T(p) + V(q, t)', () => {
  it.each([
    ['the pendulum', 'p^2/2 - cos(q)', 1, []],
    ['a driven oscillator, V depending on t', 'p^2/2 + q^2/2 - F*q*cos(Omega*t)', 1, ['F', 'Omega']],
    ['the relativistic particle, T not quadratic', 'sqrt(p^2 + 10) - 0.8 q', 1, []],
    ['Hénon–Heiles', 'p0^2/2 + p1^2/2 + q0^2/2 + q1^2/2 + q0^2*q1 - q1^3/3', 2, []],
    ['Kepler', 'p0^2/2 + p1^2/2 - 1/sqrt(q0^2 + q1^2)', 2, []],
  ])('%s separates', async (_, source, dof, params) => {
    expect(await separates(source as string, dof as number, params as string[])).toEqual({ separable: true });
  });

  it.each([
    ['a position-dependent mass', 'p^2/2*(1 + q^2) + q^2/2', /∂H\/∂q = .* depends on p/],
    ['a kinetic energy changing in time', 'p^2/2*cos(t) + q^2/2', /∂H\/∂p = .* depends on t/],
    ['a coupling of q and p', 'p^2/2 + q^2/2 + q*p', /∂H\/∂q = q \+ p depends on p/],
    // Separable only after cancellation: the trees say otherwise, and the method refuses rather than guess.
    ['a separable H written with cancelling cross terms', '(p + q)^2 - 2*p*q - q^2', /depends on/],
  ])('%s does not separate, and says which derivative shows it', async (_, source, message) => {
    const result = await separates(source as string);
    expect(result.separable).toBe(false);
    if (!result.separable) expect(result.reason).toMatch(message as RegExp);
  });

  it('a splitting method refuses an H that does not separate, with one line saying why and what to use', async () => {
    const attempt = canonicalEquations({ dof: 1, hamiltonian: 'p^2/2*(1 + q^2) + q^2/2', method: methodChoice('verlet') });
    await expect(attempt).rejects.toThrow(
      /^the method verlet needs H = T\(p\) \+ V\(q, t\), and this H does not separate: ∂H\/∂q = .* depends on p, so the potential part is not a function V\(q, t\) of the coordinates and time alone; use rk38, midpoint or adaptive$/,
    );
    await expect(canonicalEquations({ dof: 1, hamiltonian: 'p^2/2*cos(t) + q^2/2', method: methodChoice('yoshida4') })).rejects.toThrow(/yoshida4 needs .* depends on t/);
  });

  it('a JavaScript function that translates to an expression is checked like one', async () => {
    const separable = await canonicalEquations({ dof: 1, hamiltonian: '(t, [q, p]) => p * p / 2 - Math.cos(q)', method: methodChoice('verlet') });
    expect(separable.route).toBe('js-translated');
    expect(separable.method).toEqual({ name: 'verlet' });
    await expect(canonicalEquations({ dof: 1, hamiltonian: '(t, [q, p]) => p * p * q', method: methodChoice('verlet') })).rejects.toThrow(/does not separate/);
  });

  it('an opaque function or a vector field is refused: its separation cannot be shown', async () => {
    // differentiation: 'stencil' keeps a function opaque even when it could be translated.
    const opaque = (t: number, x: Float64Array) => x[1] * x[1] / 2 - Math.cos(x[0]);
    await expect(canonicalEquations({ dof: 1, hamiltonian: opaque, differentiation: 'stencil', method: methodChoice('yoshida4') })).rejects.toThrow(
      /yoshida4 needs H = T\(p\) \+ V\(q, t\), and H is an opaque JavaScript function, whose separation into T\(p\) \+ V\(q, t\) cannot be shown; use rk38, midpoint or adaptive/,
    );
    const field = (t: number, x: Float64Array, dxdt: Float64Array) => {
      dxdt[0] = x[1];
      dxdt[1] = -x[0];
    };
    await expect(canonicalEquations({ dof: 1, vectorField: field, method: methodChoice('verlet') })).rejects.toThrow(/the model is a vector field/);
  });

  it('an unknown method name is refused with the list of names', () => {
    expect(() => methodChoice('rk4')).toThrow('the method must be one of rk38, verlet, yoshida4, midpoint, adaptive, not "rk4"');
  });
});
