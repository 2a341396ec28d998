import { InputError } from '../errors.ts';

/**
 * Naming of the state and of parameters. A state is `[q…, p…]`; by default the
 * coordinates are `q0 … q(n−1)` and the momenta `p0 … p(n−1)`, or plain `q`
 * and `p` for one degree of freedom. `t` is always time.
 */

/** The constants an expression may use without declaring them: the code of each value, and what it means. */
const CONSTANT_TABLE: Readonly<Record<string, { readonly code: string; readonly meaning: string }>> = {
  pi: { code: 'Math.PI', meaning: 'π, 3.14159…' },
  PI: { code: 'Math.PI', meaning: 'π, 3.14159…' },
  e: { code: 'Math.E', meaning: "Euler's number, 2.71828…" },
  E: { code: 'Math.E', meaning: "Euler's number, 2.71828…" },
  tau: { code: '(2 * Math.PI)', meaning: 'τ = 2π, 6.28318…' },
};

/** Names (with their values) an expression may use without declaring them. */
export const CONSTANTS: Readonly<Record<string, string>> = Object.fromEntries(
  Object.entries(CONSTANT_TABLE).map(([name, { code }]) => [name, code]),
);

/**
 * The words of JavaScript a name may not be: the compiler writes names
 * straight into generated code (compile-expression.ts, function-source.ts),
 * where these would be syntax or would mean something else.
 */
const JAVASCRIPT_WORDS =
  'break case catch class const continue debugger default delete do else enum export extends false finally for ' +
  'function if import in instanceof new null return super switch this throw true try typeof var void while with ' +
  'yield let static implements interface package private protected public await arguments eval undefined NaN Infinity';

/** A name that cannot be a coordinate, a momentum or a parameter, with what it already means. */
export interface ReservedName {
  readonly name: string;
  readonly meaning: string;
}

/**
 * Every reserved name, in the order the teachers' page lists them: the
 * constants an expression may use, time, JavaScript's Math, and its words.
 * The one source of the rule: checkName refuses exactly these.
 */
export const RESERVED_NAMES: readonly ReservedName[] = [
  ...Object.entries(CONSTANT_TABLE).map(([name, { meaning }]) => ({ name, meaning })),
  { name: 't', meaning: 'time' },
  { name: 'Math', meaning: "JavaScript's Math object" },
  ...JAVASCRIPT_WORDS.split(' ').map((name) => ({ name, meaning: 'a word of JavaScript' })),
];

const MEANING_OF = new Map(RESERVED_NAMES.map(({ name, meaning }) => [name, meaning]));

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
  q.forEach((name) => checkName(name, 'coordinate'));
  p.forEach((name) => checkName(name, 'momentum'));
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

/**
 * Throws unless `name` can be a coordinate or parameter name in generated code.
 * A reserved name is refused with what it means, since the author meant
 * something else by it (E for an electric field, say) and needs a new name.
 */
export function checkName(name: string, role: 'parameter' | 'coordinate' | 'momentum' | 'variable' = 'variable'): void {
  if (!/^[A-Za-z_][A-Za-z0-9_]*$/.test(name)) throw new InputError(`"${name}" is not a valid name`);
  const meaning = MEANING_OF.get(name);
  if (meaning !== undefined) throw new InputError(`${name} is ${meaning}; name the ${role} something else, e.g. ${name}0`);
}

export function range(n: number): number[] {
  return Array.from({ length: n }, (_, i) => i);
}
