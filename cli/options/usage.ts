/**
 * The synopsis and `--help` of a command, written from its declarations
 * (commands.ts): an option on its line, in brackets unless required, with
 * the options that join it inside those brackets (`[--every 1 | --times
 * t1,t2,…]`, `[--method … [--rtol R --atol A]]`); continuation lines under
 * the first option, headings four spaces in.
 */
import type { CommandSpec, OptionDeclaration } from './args.ts';

/** `--name value`, followed by the options that join it. */
function written(option: OptionDeclaration, joined: ReadonlyMap<string, OptionDeclaration[]>): string {
  let text = option.value === undefined ? `--${option.name}` : `--${option.name} ${option.value}`;
  for (const other of joined.get(option.name) ?? []) {
    const inner = written(other, joined);
    const as = other.joins!.as;
    text += as === 'or' ? ` | ${inner}` : as === 'and' ? ` ${inner}` : ` [${inner}]`;
  }
  return text;
}

/** The command's synopsis, a line per declared line (and heading), without indentation before `phasebook`. */
export function synopsis(command: CommandSpec): string[] {
  const joined = new Map<string, OptionDeclaration[]>();
  const lines = new Map<string, string[]>();
  for (const option of command.options) {
    if (option.joins) joined.set(option.joins.option, [...(joined.get(option.joins.option) ?? []), option]);
    if (!lines.has(option.line)) lines.set(option.line, []);
  }
  for (const option of command.options) {
    if (option.joins) continue;
    const text = written(option, joined);
    const item = option.required ? text : `[${text}]${option.kind === 'list' ? '…' : ''}`;
    lines.get(option.line)!.push(item);
  }
  const start = `phasebook ${command.name} `;
  const indent = ' '.repeat(start.length);
  const { operands } = command;
  const out: string[] = [];
  [...lines].forEach(([line, items], i) => {
    if (i === 0) {
      const parts = [operands?.at === 'start' ? operands.text : '', ...items, operands?.at === 'end' ? operands.text : ''];
      out.push(start + parts.filter((p) => p !== '').join(' '));
      return;
    }
    const heading = command.headings?.[line];
    if (heading !== undefined) out.push(`    ${heading}`);
    out.push(indent + items.join(' '));
  });
  return out;
}

/** The first line of the synopsis, cut with "…" if more follows: for an error message that quotes the usage. */
export function usageLine(command: CommandSpec): string {
  const lines = synopsis(command);
  return lines.length > 1 ? `${lines[0]} …` : lines[0];
}

/** Help columns: option and value, then the help from this column on (a longer one pushes its help to the next line). */
const HELP_COLUMN = 30;

/** `phasebook COMMAND --help`: what the command does, its synopsis, and a line per option. */
export function commandHelp(command: CommandSpec): string {
  const rows = command.options.map((o) => {
    const head = `  --${o.name}${o.value === undefined ? '' : ` ${o.value}`}`;
    return head.length < HELP_COLUMN ? head.padEnd(HELP_COLUMN) + o.help : `${head}\n${' '.repeat(HELP_COLUMN)}${o.help}`;
  });
  return `phasebook ${command.name}: ${command.summary}\n\n${synopsis(command).join('\n')}\n\n${rows.join('\n')}\n`;
}
