/**
 * Inputs the CLI once took badly (issue 20): a CSV header quoted as RFC 4180
 * allows was refused; an --output naming the --initial-file, or a shard,
 * silently replaced it; a 100 kB H ended in "Maximum call stack size
 * exceeded". Each now runs, or is refused in one line with status 2.
 */
import { mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeAll, beforeEach, describe, expect, it } from 'vitest';
import { ensureCli } from '../../../bin/cli-bundle.mjs';
import { parseCSV } from '../../../core/tables/csv-read.ts';
import { runCli, type CliExit } from '../support/cli-harness.ts';

const RUN = ['simulate', '--dof', '1', '--t-end', '0.01', '--every', '10'];
const OSCILLATOR = [...RUN, '--hamiltonian', 'p^2/2 + q^2/2'];

let scratch: string;
beforeAll(async () => {
  await ensureCli();
});
beforeEach(() => {
  scratch = mkdtempSync(join(tmpdir(), 'phasebook-inputs-'));
});
afterEach(() => rmSync(scratch, { recursive: true, force: true }));

type Exit = CliExit;

const phasebook = (args: string[]) => runCli(args, { PHASEBOOK_CACHE_DIR: join(scratch, 'cache') });

const refused = (exit: Exit, message: RegExp) => {
  expect(exit.code).toBe(2);
  expect(exit.stderr.trim().split('\n')).toHaveLength(1);
  expect(exit.stderr).toMatch(message);
  expect(exit.stderr).not.toMatch(/internal error|Maximum call stack/);
};

describe('--initial-file as RFC 4180 CSV', () => {
  it('reads a quoted header, quoted numbers and CRLF line ends, in any column order', async () => {
    const file = join(scratch, 'initial.csv');
    writeFileSync(file, '"p","q"\r\n0,1\r\n"0.5", 2\r\n');
    const exit = await phasebook([...OSCILLATOR, '--initial-file', file]);
    expect(exit.stderr).toBe('');
    expect(exit.code).toBe(0);
    const table = parseCSV(exit.stdout);
    expect(table.columns).toEqual(['trajectory', 't', 'q', 'p', 'H']);
    // Row 0 of each trajectory is its initial state: (q, p) = (1, 0), then (2, 0.5).
    const w = table.columns.length;
    const firsts = [0, 1].map((j) => Array.from(table.data.subarray(j * 3 * w + 2, j * 3 * w + 4)));
    expect(firsts).toEqual([
      [1, 0],
      [2, 0.5],
    ]);
  });

  it('refuses what RFC 4180 does not allow, or a number outside the grammar, naming the file and the line, in one line', async () => {
    // The records and the numbers are the core's one CSV reader's (tests/unit/core/tables/readers.test.ts).
    const file = join(scratch, 'initial.csv');
    writeFileSync(file, 'q,p\n1,"0\n2,0\n');
    refused(await phasebook([...OSCILLATOR, '--initial-file', file]), /^phasebook: --initial-file initial\.csv line 2: a quoted field opens here and is never closed\n$/);
    writeFileSync(file, 'q,p\n1,0\n"2\n",0x1\n');
    refused(await phasebook([...OSCILLATOR, '--initial-file', file]), /^phasebook: --initial-file initial\.csv line 3: p is "0x1", not a finite number\n$/);
  });
});

describe('an output that is an input', () => {
  it('refuses --output naming the --initial-file, by its path or through a link, and leaves the input as it was', async () => {
    const file = join(scratch, 'initial.csv');
    const states = 'q,p\n1,0\n0.5,0\n';
    writeFileSync(file, states);
    refused(await phasebook([...OSCILLATOR, '--initial-file', file, '--output', file]), /^phasebook: --output \S+initial\.csv is the --initial-file: the output would replace it/);
    const link = join(scratch, 'link.csv');
    symlinkSync(file, link);
    refused(await phasebook([...OSCILLATOR, '--initial-file', file, '--output', link]), /is the --initial-file \(\S+link\.csv and \S+initial\.csv are one file\)/);
    refused(await phasebook([...OSCILLATOR, '--initial-file', link, '--output', join(scratch, '.', 'initial.csv')]), /is the --initial-file/);
    expect(readFileSync(file, 'utf8')).toBe(states);
  });

  it('refuses a merge whose --output is one of its shards, and leaves the shard as it was', async () => {
    const shards = [1, 2].map((i) => join(scratch, `s${i}.json`));
    for (const [i, shard] of shards.entries()) {
      const exit = await phasebook([...OSCILLATOR, '--sample', '4', '--box', 'q=-1:1,p=-1:1', '--shard', `${i + 1}/2`, '--output', shard]);
      expect(exit.code).toBe(0);
    }
    const before = readFileSync(shards[0]);
    refused(await phasebook(['merge', '--output', shards[0], ...shards]), /^phasebook: --output \S+s1\.json is the shard: the output would replace it/);
    expect(readFileSync(shards[0]).equals(before)).toBe(true);
  });
});

describe('an H too large for the compiler', () => {
  it('refuses a 100 kB H by its length, in one line', async () => {
    const h = Array.from({ length: 25_000 }, () => 'q^2').join('+');
    refused(await phasebook([...RUN, '--initial', '1,0', '--hamiltonian', h]), /^phasebook: H is 99999 characters long; phasebook takes at most 65536 \(64 KiB\)\n$/);
  });

  it('says an H within the length that nests too deep for the compiler is too deep, in one line', async () => {
    const sum = Array.from({ length: 10_000 }, () => 'q^2').join('+');
    refused(await phasebook([...RUN, '--initial', '1,0', '--hamiltonian', sum]), /^phasebook: H is too deeply nested for the compiler \(39999 characters\)/);
    const nested = `(t, x) => ${'('.repeat(20_000)}x[0]${')'.repeat(20_000)}`;
    refused(await phasebook([...RUN, '--initial', '1,0', '--hamiltonian', nested]), /^phasebook: H nests too deeply for the parser/);
  });
});
