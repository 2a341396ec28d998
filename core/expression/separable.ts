/**
 * Whether H separates as T(p) + V(q, t), read off its derivative trees:
 * every ∂H/∂p must be free of the coordinates and of time, every ∂H/∂q free
 * of the momenta. That is exactly what the splitting methods use: a drift
 * q += h·∂T/∂p at fixed p, and a kick p −= h·∂V/∂q at fixed q and t
 * (Hairer, Lubich & Wanner, *Geometric Numerical Integration*, §II.5).
 *
 * The test is on the trees, not on H's value: an H that separates only
 * after cancellation, like (p + q)² − 2pq − q², is reported as not
 * separating, with the derivative that shows it.
 */
import type { MathNode } from 'mathjs';
import { InputError } from '../errors.ts';
import { bottomUp } from './tree.ts';

export type Separability =
  | { separable: true }
  | { separable: false; /** one line saying which derivative depends on what */ reason: string };

/** The names of the state and t each node depends on, found bottom-up. */
function symbolsOf(relevant: ReadonlySet<string>): (node: MathNode) => ReadonlySet<string> {
  const memo = new Map<MathNode, ReadonlySet<string>>();
  const none: ReadonlySet<string> = new Set();
  return (node) =>
    bottomUp(node, memo, (n, children) => {
      if (n.type === 'SymbolNode') {
        const name = (n as unknown as { name: string }).name;
        return relevant.has(name) ? new Set([name]) : none;
      }
      const nonEmpty = children.filter((c) => c.size > 0);
      if (nonEmpty.length === 0) return none;
      if (nonEmpty.length === 1) return nonEmpty[0];
      const union = new Set<string>();
      nonEmpty.forEach((c) => c.forEach((s) => union.add(s)));
      return union;
    });
}

function shortText(node: MathNode, max = 60): string {
  const text = node.toString().replace(/\s+/g, ' ');
  return text.length > max ? `${text.slice(0, max - 1)}…` : text;
}

/**
 * @param names q's then p's
 * @param derivatives ∂H/∂(names[i]) for each i, in the order of `names`
 */
export function separability(names: readonly string[], derivatives: readonly MathNode[]): Separability {
  const dof = names.length / 2;
  const coordinates = new Set(names.slice(0, dof));
  const momenta = new Set(names.slice(dof));
  const symbols = symbolsOf(new Set([...names, 't']));
  for (let i = 0; i < names.length; i++) {
    const isMomentum = i >= dof;
    const found = [...symbols(derivatives[i])].filter((s) => (isMomentum ? coordinates.has(s) || s === 't' : momenta.has(s)));
    if (found.length === 0) continue;
    const d = `∂H/∂${names[i]} = ${shortText(derivatives[i])}`;
    const what = isMomentum
      ? `${d} depends on ${found.join(', ')}, so the kinetic part is not a function T(p) of the momenta alone`
      : `${d} depends on ${found.join(', ')}, so the potential part is not a function V(q, t) of the coordinates and time alone`;
    return { separable: false, reason: what };
  }
  return { separable: true };
}

/** Throws the InputError a splitting method gives for an H that does not separate. */
export function requireSeparable(method: string, names: readonly string[], derivatives: readonly MathNode[]): void {
  const result = separability(names, derivatives);
  if (!result.separable) {
    throw new InputError(`the method ${method} needs H = T(p) + V(q, t), and this H does not separate: ${result.reason}; use rk38, midpoint or adaptive`);
  }
}
