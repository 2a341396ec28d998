/**
 * The command line's options, declared once (commands.ts): the parser reads
 * by the declarations, and the synopsis in `--help` and in the README is
 * written from them, so the README cannot lack an option the CLI takes.
 */
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { ROOT } from '../../../../bin/cli-bundle.mjs';
import { parseArgs } from '../../../../cli/options/args.ts';
import { COMMANDS, MERGE, REPRODUCE, SIMULATE, SPECTRUM } from '../../../../cli/options/commands.ts';
import { main } from '../../../../cli/main.ts';
import { commandHelp, synopsis, usageLine } from '../../../../cli/options/usage.ts';
import { captureWrites } from '../../support/cli-harness.ts';

let stdout: string[];
let stderr: string[];
beforeEach(() => {
  stdout = captureWrites(process.stdout);
  stderr = captureWrites(process.stderr);
});
afterEach(() => vi.restoreAllMocks());

describe('the synopsis, written from the declarations', () => {
  it("is the README's synopsis, exactly (the sh block under \"## The command line\")", () => {
    const readme = readFileSync(join(ROOT, 'README.md'), 'utf8');
    const section = readme.slice(readme.indexOf('\n## The command line\n'));
    const block = /```sh\n([\s\S]*?)```/.exec(section)![1];
    expect(block).toBe(COMMANDS.flatMap(synopsis).join('\n') + '\n');
  });

  it('names every option each command declares, and each once', () => {
    for (const command of COMMANDS) {
      // Headings (four spaces in) may name an option; the options' own lines name each once.
      const text = synopsis(command).filter((line) => !/^ {4}\S/.test(line)).join('\n');
      for (const option of command.options) expect(text.match(new RegExp(`--${option.name}(?![\\w-])`, 'g')), `--${option.name} of ${command.name}`).toHaveLength(1);
    }
    expect(synopsis(SIMULATE).join('\n')).toContain("--vector-field '(t, x, dxdt) => { … }'");
  });

  it('brackets what is optional and writes what joins an option inside its brackets', () => {
    const lines = synopsis(SIMULATE);
    expect(lines[0]).toBe('phasebook simulate --hamiltonian H --dof N --initial v1,…,v2N [--param name=value]…');
    expect(lines.join('\n')).toContain('[--every 1 | --times t1,t2,…]');
    expect(lines.join('\n')).toContain('[--method rk38|verlet|yoshida4|midpoint|adaptive [--rtol R --atol A]]');
    expect(lines.join('\n')).toContain('--sample N [--seed S] --box q=lo:hi,p=lo:hi [--energy E [--solve-for p]]');
    expect(synopsis(MERGE)).toEqual(['phasebook merge --output FILE SHARD…']);
    expect(synopsis(REPRODUCE)).toEqual(['phasebook reproduce FILE [--workers K] [--no-cache] [--trust-code]']);
    expect(usageLine(SPECTRUM)).toBe('phasebook spectrum --input FILE --column NAME [--trajectory J] [--from T0] [--to T1] …');
  });

  it('phasebook --help lists every synopsis; phasebook COMMAND --help a line per option, status 0', async () => {
    expect(await main(['--help'])).toBe(0);
    for (const line of COMMANDS.flatMap(synopsis)) expect(stdout.join('')).toContain(`  ${line}\n`);
    stdout.length = 0;
    expect(await main(['simulate', '--help'])).toBe(0);
    expect(stdout.join('')).toBe(commandHelp(SIMULATE));
    for (const option of SIMULATE.options) expect(stdout.join('')).toMatch(new RegExp(`\\n  --${option.name}\\b.*\\s+${option.help.slice(0, 20).replace(/[.*+?^${}()|[\]\\]/g, '\\$&')}`));
    expect(stderr).toEqual([]);
  });
});

describe('the parser, by the declarations', () => {
  it('reads values, lists, flags and operands', () => {
    const args = parseArgs(['--dof', '1', '--param=a=1', '--param', 'b=2', '--derivatives', '--initial', '-10,-10'], SIMULATE);
    expect(args.values).toEqual(new Map([['dof', '1'], ['initial', '-10,-10']]));
    expect(args.lists.get('param')).toEqual(['a=1', 'b=2']);
    expect(args.flags).toEqual(new Set(['derivatives']));
    expect(parseArgs(['a.npz', '--output', 'm.npz', 'b.npz'], MERGE).operands).toEqual(['a.npz', 'b.npz']);
  });

  const byName = (name: string) => COMMANDS.find((c) => c.name === name)!;

  it.each([
    ['simulate', ['--dt', '1e-3', '--dt', '2e-3'], '--dt is given twice'],
    ['simulate', ['--output=a.csv', '--output', 'b.csv'], '--output is given twice'],
    ['merge', ['--output', 'm.npz', 'a.npz', '--output', 'n.npz'], '--output is given twice'],
    ['spectrum', ['--column', 'q', '--column', 'p'], '--column is given twice'],
    ['reproduce', ['f.json', '--workers', '1', '--workers=2'], '--workers is given twice'],
  ])('%s refuses an option given twice: %j', (command, argv, message) => {
    expect(() => parseArgs(argv, byName(command))).toThrow(message);
  });

  it.each([
    ['simulate', ['--speed', '2'], 'unknown option --speed (phasebook simulate --help lists them)'],
    ['simulate', ['stray'], 'unexpected argument "stray"'],
    ['reproduce', ['a.json', 'b.json'], 'unexpected argument "b.json"'],
    ['simulate', ['--derivatives=yes'], '--derivatives takes no value'],
    ['simulate', ['--dof'], '--dof needs a value'],
  ])('%s refuses what its declarations do not allow: %j', (command, argv, message) => {
    expect(() => parseArgs(argv, byName(command))).toThrow(message);
  });

  it('the repeated option ends the command in one line, status 2', async () => {
    expect(await main(['simulate', '--hamiltonian', 'p^2/2', '--hamiltonian', 'q^2/2', '--dof', '1', '--initial', '1,0'])).toBe(2);
    expect(stderr.join('')).toBe('phasebook: --hamiltonian is given twice\n');
  });
});
