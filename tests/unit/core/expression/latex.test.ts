/**
 * Hamilton's equations as the chapters typeset them (expression/latex.ts):
 * the derivatives are no longer simplified by mathjs, so this pins down that
 * the book's models still read as a physicist would write them.
 */
import { describe, expect, it } from 'vitest';
import { compileModel } from '../../../../core/model/compile-model.ts';

async function equations(dof: number, hamiltonian: string, params: Record<string, number> = {}): Promise<readonly string[]> {
  return (await compileModel({ dof, hamiltonian, params })).latex!.equations;
}

const SQRT_R2 = '\\sqrt{{\\left( q_{0}- q_{2}\\right)}^{2}+{\\left( q_{1}- q_{3}\\right)}^{2}}';

describe('the LaTeX of Hamilton’s equations', () => {
  it('writes the pendulum’s force without a bracket round it', async () => {
    const [qDot, pDot] = await equations(1, 'p^2/2 - omega0^2 * cos(q)', { omega0: 1 });
    expect(qDot).toBe('\\dot{q} = \\frac{\\partial H}{\\partial p} =  p');
    expect(pDot).toBe('\\dot{p} = -\\frac{\\partial H}{\\partial q} = -{ \\omega_{0}}^{2}\\cdot\\sin\\left( q\\right)');
  });

  it('writes the Kepler force as one fraction over r³, the minus worked into the difference', async () => {
    const lines = await equations(4, 'p0^2 + p1^2 + p2^2 + p3^2 - 500/sqrt((q0-q2)^2 + (q1-q3)^2)');
    expect(lines[0]).toBe('\\dot{q}_{0} = \\frac{\\partial H}{\\partial p_{0}} = 2\\cdot p_{0}');
    expect(lines[4]).toBe(`\\dot{p}_{0} = -\\frac{\\partial H}{\\partial q_{0}} = \\frac{500\\cdot\\left( q_{2}- q_{0}\\right)}{{${SQRT_R2}}^{3}}`);
    expect(lines[6]).toBe(`\\dot{p}_{2} = -\\frac{\\partial H}{\\partial q_{2}} = \\frac{500\\cdot\\left( q_{0}- q_{2}\\right)}{{${SQRT_R2}}^{3}}`);
  });

  it('writes the paper’s default model (eq. 7) with the drive first and the restoring force after', async () => {
    const params = { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 };
    const [, pDot] = await equations(1, 'p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t+beta)', params);
    expect(pDot).toBe(
      '\\dot{p} = -\\frac{\\partial H}{\\partial q} = \\cos\\left( \\kappa\\cdot t+ \\beta\\right)\\cdot f-{ \\omega}^{2}\\cdot\\left(1+ u\\cdot\\cos\\left( \\gamma\\cdot t\\right)\\right)\\cdot q',
    );
  });

  it.each([
    [1, 'p^2/2 + omega0^2*q^2/2 + alpha*q^3 + beta*q^4', { omega0: 1, alpha: 1, beta: 1 }],
    [1, 'p^2/2 + (omega0 + epsilon*t)^2 * q^2/2', { omega0: 1, epsilon: 1 }],
    [2, 'p0^2 + p1^2 + alpha/sqrt(q0^2 + q1^2)', { alpha: 30 }],
    [1, 'sqrt(p^2 + m^2) - F*q', { m: 1, F: 1 }],
    [2, '(p0^2 + p1^2)/2 + (q0^2 + 4*q1^2)/2', {}],
  ])('leaves no trace of the raw derivative in dof %i, H = %s', async (dof, h, params) => {
    for (const line of await equations(dof, h, params)) {
      const rhs = line.split(' = ').at(-1)!;
      // ×1, +0, ^1, 2/2, a unit coefficient, and the brackets of −(…) round a product.
      expect(rhs).not.toMatch(/(^|[^0-9.])1\\cdot|\\cdot1($|[^0-9.])|[+-]0($|[^0-9.])|\^\{1\}|\\frac\{2|^-\\left\(/);
    }
  });
});
