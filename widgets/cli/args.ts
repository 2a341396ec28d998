import { InputError } from '../core/index.ts';

/** How an option is read: a flag takes no value, a list option may repeat. */
export interface OptionSpec {
  [name: string]: 'value' | 'list' | 'flag';
}

export interface ParsedArgs {
  values: Map<string, string>;
  lists: Map<string, string[]>;
  flags: Set<string>;
}

/**
 * Reads `--name value`, `--name=value`, repeated list options and flags.
 * The value after an option is taken as it is, so negative numbers work as a
 * separate argument (`--initial -10,-10`).
 */
export function parseArgs(argv: readonly string[], spec: OptionSpec): ParsedArgs {
  const parsed: ParsedArgs = { values: new Map(), lists: new Map(), flags: new Set() };
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (!arg.startsWith('--')) throw new InputError(`unexpected argument "${arg}"`);
    const eq = arg.indexOf('=');
    const name = arg.slice(2, eq < 0 ? undefined : eq);
    const kind = spec[name];
    if (!kind) throw new InputError(`unknown option --${name}`);
    if (kind === 'flag') {
      if (eq >= 0) throw new InputError(`--${name} takes no value`);
      parsed.flags.add(name);
      continue;
    }
    let value: string;
    if (eq >= 0) value = arg.slice(eq + 1);
    else {
      if (i + 1 >= argv.length) throw new InputError(`--${name} needs a value`);
      value = argv[++i];
    }
    if (kind === 'list') parsed.lists.set(name, [...(parsed.lists.get(name) ?? []), value]);
    else {
      if (parsed.values.has(name)) throw new InputError(`--${name} is given twice`);
      parsed.values.set(name, value);
    }
  }
  return parsed;
}

/** A finite number, or an error naming the option and the text. */
export function number(text: string, what: string): number {
  const trimmed = text.trim();
  const value = Number(trimmed);
  if (trimmed === '' || !Number.isFinite(value)) throw new InputError(`${what} must be a number, not "${text}"`);
  return value;
}

export function positive(text: string, what: string): number {
  const value = number(text, what);
  if (!(value > 0)) throw new InputError(`${what} must be positive, not ${text}`);
  return value;
}

export function wholeNumber(text: string, what: string, least = 1): number {
  const value = number(text, what);
  if (!Number.isInteger(value) || value < least) throw new InputError(`${what} must be a whole number ≥ ${least}, not ${text}`);
  return value;
}

/** `1,-2.5,3e-4` → numbers, naming the position of a bad one. */
export function numberList(text: string, what: string): number[] {
  return text.split(',').map((part, i) => number(part, `${what} value ${i + 1}`));
}

/** `name=value` pairs into an object, in the order given. */
export function params(pairs: readonly string[]): Record<string, number> {
  const out: Record<string, number> = {};
  for (const pair of pairs) {
    const eq = pair.indexOf('=');
    if (eq <= 0) throw new InputError(`--param takes name=value, not "${pair}"`);
    const name = pair.slice(0, eq).trim();
    if (name in out) throw new InputError(`the parameter ${name} is given twice`);
    out[name] = number(pair.slice(eq + 1), `the parameter ${name}`);
  }
  return out;
}
