import type { MathNode } from 'mathjs';
import type { MathJs } from './mathjs.ts';

const GREEK = new Set(
  'alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi pi rho sigma tau upsilon phi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega'.split(
    ' ',
  ),
);

/** `omega0` → `\omega_{0}`, `q1` → `q_{1}`, `x_a` → `x_{a}`; `dot` puts a dot over the base. */
export function symbolTex(name: string, dot = false): string {
  const m = /^([A-Za-z]+?)(\d+|_\w+)?$/.exec(name);
  const base = m ? m[1] : name;
  const sub = m?.[2]?.replace(/^_/, '');
  let head = GREEK.has(base) ? `\\${base}` : base.length > 1 ? `\\mathrm{${base}}` : base;
  if (dot) head = `\\dot{${head}}`;
  return sub ? `${head}_{${sub}}` : head;
}

function toTex(node: MathNode): string {
  return node.toTex({
    parenthesis: 'auto',
    implicit: 'hide',
    // The leading space keeps `\cdot` from running into the name (`\cdotp` is another command).
    handler: (n: MathNode) =>
      n.type === 'SymbolNode' ? ` ${symbolTex((n as unknown as { name: string }).name)}` : undefined,
  } as never);
}

/**
 * LaTeX of H and of Hamilton's equations q̇ = ∂H/∂p, ṗ = −∂H/∂q, for the
 * chapters to typeset. The right-hand sides are the derivatives the stepper
 * integrates, simplified once more for reading.
 */
export function latexOf(
  math: MathJs,
  hamiltonian: MathNode,
  rates: readonly { node: MathNode; negate: boolean }[],
  names: readonly string[],
  dof: number,
): { hamiltonian: string; equations: string[] } {
  const equations = names.map((name, i) => {
    const conjugate = i < dof ? names[i + dof] : names[i - dof];
    const partial = `${rates[i].negate ? '-' : ''}\\frac{\\partial H}{\\partial ${symbolTex(conjugate)}}`;
    const rate = rates[i].negate
      ? math.simplify(new math.OperatorNode('-', 'unaryMinus', [rates[i].node]))
      : rates[i].node;
    return `${symbolTex(name, true)} = ${partial} = ${toTex(rate)}`;
  });
  return { hamiltonian: `H = ${toTex(hamiltonian)}`, equations };
}
