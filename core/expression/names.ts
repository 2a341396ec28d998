import { InputError } from '../errors.ts';

/**
 * Naming of the state and of parameters. A state is `[q…, p…]`; by default the
 * coordinates are `q0 … q(n−1)` and the momenta `p0 … p(n−1)`, or plain `q`
 * and `p` for one degree of freedom. `t` is always time.
 */

/** Names (with their values) an expression may use without declaring them. */
export const CONSTANTS: Readonly<Record<string, string>> = {
  pi: 'Math.PI',
  PI: 'Math.PI',
  e: 'Math.E',
  E: 'Math.E',
  tau: '(2 * Math.PI)',
};

const RESERVED = new Set(
  (
    'break case catch class const continue debugger default delete do else enum export extends false finally for ' +
    'function if import in instanceof new null return super switch this throw true try typeof var void while with ' +
    'yield let static implements interface package private protected public await arguments eval undefined NaN ' +
    'Infinity Math t'
  ).split(' '),
);

export interface StateNames {
  /** q's then p's */
  names: string[];
  /** alternative spellings accepted in expressions, e.g. q0 for q when dof is 1 */
  aliases: Map<string, string>;
}

export function stateNames(dof: number, coordinates?: readonly string[], momenta?: readonly string[]): StateNames {
  if (!Number.isInteger(dof) || dof < 1) throw new InputError(`dof must be a positive integer, not ${dof}`);
  const q = coordinates ?? (dof === 1 ? ['q'] : range(dof).map((i) => `q${i}`));
  const p = momenta ?? (dof === 1 ? ['p'] : range(dof).map((i) => `p${i}`));
  if (q.length !== dof) throw new InputError(`${q.length} coordinate names given for ${dof} degrees of freedom`);
  if (p.length !== dof) throw new InputError(`${p.length} momentum names given for ${dof} degrees of freedom`);
  const names = [...q, ...p];
  names.forEach(checkName);
  const seen = new Set<string>();
  for (const n of names) {
    if (seen.has(n)) throw new InputError(`the name ${n} is used twice`);
    seen.add(n);
  }
  const aliases = new Map<string, string>();
  if (dof === 1 && !coordinates && !momenta) {
    aliases.set('q0', 'q');
    aliases.set('p0', 'p');
  }
  return { names, aliases };
}

/** Throws unless `name` can be a coordinate or parameter name in generated code. */
export function checkName(name: string): void {
  if (!/^[A-Za-z_][A-Za-z0-9_]*$/.test(name)) throw new InputError(`"${name}" is not a valid name`);
  if (RESERVED.has(name) || name in CONSTANTS) throw new InputError(`"${name}" is reserved and cannot name a variable`);
}

export function range(n: number): number[] {
  return Array.from({ length: n }, (_, i) => i);
}
