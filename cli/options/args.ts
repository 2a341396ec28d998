import { InputError } from '../../core/index.ts';

/** How an option is read: a flag takes no value, a list option may repeat. */
export type OptionKind = 'value' | 'list' | 'flag';

/**
 * One option, declared once: what the parser reads, and what the synopsis
 * and `--help` say of it (usage.ts writes them from this).
 */
export interface OptionDeclaration {
  name: string;
  kind: OptionKind;
  /** the value as the synopsis writes it: a placeholder (H, FILE), a default (5e-4) or the choices (long|wide); none for a flag */
  value?: string;
  /** the synopsis line it is written on; lines come in the order of their first option */
  line: string;
  /** written without brackets: the command needs it, or one of its alternatives on another line */
  required?: boolean;
  /** written inside another option's brackets: as its alternative (or), beside it (and), or in brackets of its own (nested) */
  joins?: { option: string; as: 'or' | 'and' | 'nested' };
  /** one line for --help */
  help: string;
}

/** A command's arguments: its options, and the operands (file names) it takes besides. */
export interface CommandSpec {
  name: string;
  /** what the command does, in a line, for --help */
  summary: string;
  options: readonly OptionDeclaration[];
  /** operands, as the synopsis writes them (FILE, SHARD…), before or after the options; `many` takes any number */
  operands?: { text: string; at: 'start' | 'end'; many: boolean };
  /** a heading shown above a synopsis line, for the lines that offer an alternative to the first */
  headings?: Readonly<Record<string, string>>;
}

export interface ParsedArgs {
  values: Map<string, string>;
  lists: Map<string, string[]>;
  flags: Set<string>;
  /** the arguments that are not options, in order */
  operands: string[];
}

/**
 * Reads `--name value`, `--name=value`, repeated list options, flags and
 * the command's operands. The value after an option is taken as it is, so
 * negative numbers work as a separate argument (`--initial -10,-10`). An
 * option given twice is refused rather than the last one winning, since the
 * two were probably meant for different things.
 */
export function parseArgs(argv: readonly string[], command: CommandSpec): ParsedArgs {
  const parsed: ParsedArgs = { values: new Map(), lists: new Map(), flags: new Set(), operands: [] };
  const kinds = new Map(command.options.map((o) => [o.name, o.kind]));
  for (let i = 0; i < argv.length; i++) {
    const arg = argv[i];
    if (!arg.startsWith('--')) {
      const room = command.operands && (command.operands.many || parsed.operands.length === 0);
      if (!room) throw new InputError(`unexpected argument "${arg}"`);
      parsed.operands.push(arg);
      continue;
    }
    const eq = arg.indexOf('=');
    const name = arg.slice(2, eq < 0 ? undefined : eq);
    const kind = kinds.get(name);
    if (!kind) throw new InputError(`unknown option --${name} (phasebook ${command.name} --help lists them)`);
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
