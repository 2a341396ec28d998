import type { MathNode } from 'mathjs';

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

/** LaTeX of an expression as the equations write it (a non-Hamiltonian term on its own, say). */
export function expressionTex(node: MathNode): string {
  return toTex(node).trim();
}

function toTex(node: MathNode): string {
  const options = {
    parenthesis: 'auto',
    implicit: 'hide',
    handler: (n: MathNode): string | undefined => {
      // The leading space keeps `\cdot` from running into the name (`\cdotp` is another command).
      if (n.type === 'SymbolNode') return ` ${symbolTex((n as unknown as { name: string }).name)}`;
      // −(ω₀² sin q) reads as −ω₀² sin q: a minus before a product needs no parentheses.
      const operand = negatedOperand(n);
      if (operand) return `-${operand.toTex(options as never)}`;
      return undefined;
    },
  };
  return node.toTex(options as never);
}

/** The operand of a unary minus that can be written without parentheses: a product, quotient, power, call, name or number. */
function negatedOperand(node: MathNode): MathNode | undefined {
  if (node.type !== 'OperatorNode') return undefined;
  const { fn, args } = node as unknown as { fn: string; args: MathNode[] };
  if (fn !== 'unaryMinus') return undefined;
  const operand = args[0];
  if (operand.type === 'OperatorNode') {
    const inner = (operand as unknown as { fn: string }).fn;
    return inner === 'multiply' || inner === 'divide' || inner === 'pow' ? operand : undefined;
  }
  return operand.type === 'FunctionNode' || operand.type === 'SymbolNode' || operand.type === 'ConstantNode' ? operand : undefined;
}

/**
 * LaTeX of H and of Hamilton's equations q̇ = ∂H/∂p, ṗ = −∂H/∂q, for the
 * chapters to typeset. The right-hand sides are the derivatives the stepper
 * integrates (`readable`: q's rates, then p's), with the minus of ṗ worked
 * in for reading. `added` holds, by component, a non-Hamiltonian term
 * added to the rate (model/non-hamiltonian.ts): it is written beside the
 * derivative, ṗ = −∂H/∂q − γp = …, so that the reader sees which part of
 * the motion is not Hamilton's; H itself is written without it.
 */
export function latexOf(
  hamiltonian: MathNode,
  readable: readonly MathNode[],
  names: readonly string[],
  dof: number,
  added: readonly (MathNode | undefined)[] = [],
): { hamiltonian: string; equations: string[] } {
  const lines = names.map((name, i) => {
    const momentum = i >= dof;
    const conjugate = momentum ? names[i - dof] : names[i + dof];
    const partial = `${momentum ? '-' : ''}\\frac{\\partial H}{\\partial ${symbolTex(conjugate)}}`;
    const term = added[i] && expressionTex(added[i]);
    // A term that starts with its own minus sign needs no plus before it.
    const withTerm = term === undefined ? partial : `${partial} ${term.startsWith('-') ? '' : '+ '}${term}`;
    return `${symbolTex(name, true)} = ${withTerm} = ${toTex(readable[i])}`;
  });
  return { hamiltonian: `H = ${toTex(hamiltonian)}`, equations: lines };
}
