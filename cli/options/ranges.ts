/**
 * `--box q=lo:hi,p=lo:hi` and `--grid q=lo:hi:n,p=v`: a range (or a grid
 * axis) for every component of the state, by name. A bare value holds the
 * component fixed. Bounds may be arithmetic with the parameters (`q=-pi:pi`).
 */
import { InputError } from '../../core/index.ts';
import { evaluateParameter } from './param-expression.ts';
import { wholeNumber } from './args.ts';

/** The state names a user may write: the model's, and q0/p0 for a lone q/p. */
export function resolveName(name: string, names: readonly string[]): string | undefined {
  if (names.includes(name)) return name;
  if (names.length === 2 && names[0] === 'q' && names[1] === 'p') return name === 'q0' ? 'q' : name === 'p0' ? 'p' : undefined;
  return undefined;
}

function entries(text: string, option: string, names: readonly string[]): Map<string, string[]> {
  const out = new Map<string, string[]>();
  for (const part of text.split(',')) {
    const eq = part.indexOf('=');
    if (eq <= 0) throw new InputError(`${option} takes name=lo:hi pairs separated by commas, not "${part}"`);
    const given = part.slice(0, eq).trim();
    const name = resolveName(given, names);
    if (!name) throw new InputError(`${option}: ${given} is not a component of the state (${names.join(', ')})`);
    if (out.has(name)) throw new InputError(`${option}: ${name} is given twice`);
    out.set(name, part.slice(eq + 1).split(':'));
  }
  return out;
}

function bound(text: string, option: string, name: string, params: Readonly<Record<string, number>>): number {
  const value = evaluateParameter(text, params, `${option} ${name}`);
  if (!Number.isFinite(value)) throw new InputError(`${option} ${name}: ${text} is not a finite number`);
  return value;
}

function missing(option: string, names: readonly string[], given: Map<string, unknown>): void {
  const absent = names.filter((n) => !given.has(n));
  if (absent.length) throw new InputError(`${option} gives no range for ${absent.join(', ')}; every component of the state needs one (a single value holds it fixed)`);
}

/** --box: [lo, hi] for every state name, in the state's order. */
export function parseBox(text: string, names: readonly string[], params: Readonly<Record<string, number>>): Record<string, [number, number]> {
  const given = entries(text, '--box', names);
  missing('--box', names, given);
  const box: Record<string, [number, number]> = {};
  for (const name of names) {
    const parts = given.get(name)!;
    if (parts.length > 2) throw new InputError(`--box ${name} takes lo:hi or one value, not "${parts.join(':')}"`);
    const lo = bound(parts[0], '--box', name, params);
    const hi = parts.length === 2 ? bound(parts[1], '--box', name, params) : lo;
    if (hi < lo) throw new InputError(`--box ${name}: the upper bound ${hi} is below the lower ${lo}`);
    box[name] = [lo, hi];
  }
  return box;
}

/** --grid: [lo, hi, n] for every state name, in the state's order. */
export function parseGrid(text: string, names: readonly string[], params: Readonly<Record<string, number>>): Record<string, [number, number, number]> {
  const given = entries(text, '--grid', names);
  missing('--grid', names, given);
  const axes: Record<string, [number, number, number]> = {};
  for (const name of names) {
    const parts = given.get(name)!;
    if (parts.length !== 1 && parts.length !== 3) throw new InputError(`--grid ${name} takes lo:hi:n or one value, not "${parts.join(':')}"`);
    const lo = bound(parts[0], '--grid', name, params);
    if (parts.length === 1) {
      axes[name] = [lo, lo, 1];
      continue;
    }
    const hi = bound(parts[1], '--grid', name, params);
    const n = wholeNumber(parts[2], `--grid ${name}'s number of points`);
    if (hi < lo) throw new InputError(`--grid ${name}: the upper bound ${hi} is below the lower ${lo}`);
    axes[name] = [lo, hi, n];
  }
  return axes;
}
