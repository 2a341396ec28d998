import { mkdirSync, mkdtempSync, readdirSync, symlinkSync, utimesSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { beforeEach, describe, expect, it } from 'vitest';
import { partialName, partialOwner, removeStalePartials, STALE_AFTER_MS } from '../../../../cli/output/partial-file.ts';

describe('partialName(target) and partialOwner(name)', () => {
  it('names a hidden file beside the target that says whose it is, with 128 random bits', () => {
    const name = partialName('/data/run.csv', 4321, '0123abcd');
    expect(name).toMatch(/^\.run\.csv\.phasebook-0123abcd-4321-[0-9a-f]{32}\.partial$/);
    expect(partialOwner(name)).toEqual({ space: '0123abcd', pid: 4321 });
    expect(partialName('/data/run.csv', 4321, '0123abcd')).not.toBe(name);
  });

  it('keeps the name under the 255-byte limit for a long target, and still recognises it', () => {
    const name = partialName(`/data/${'x'.repeat(250)}`, 1, 'ffffffff');
    expect(Buffer.byteLength(name)).toBeLessThan(255);
    expect(partialOwner(name)).toEqual({ space: 'ffffffff', pid: 1 });
  });

  it.each([
    '.run.csv.4321.partial',
    '.run.csv.phasebook-0123abcd-4321-0123.partial',
    '.run.csv.phasebook-0123ABCD-4321-0123456789abcdef0123456789abcdef.partial',
    '.run.csv.phasebook-0123abcd-0-0123456789abcdef0123456789abcdef.partial',
    'run.csv.phasebook-0123abcd-4321-0123456789abcdef0123456789abcdef.partial',
    '.run.csv.phasebook-0123abcd-4321-0123456789abcdef0123456789abcdef.partial~',
  ])('does not take %s for a partial of its own', (name) => {
    expect(partialOwner(name)).toBeUndefined();
  });
});

describe('removeStalePartials(directory, check)', () => {
  let dir: string;
  const space = '0123abcd';
  const now = Date.now();
  const alive = (pid: number) => pid === 100;
  const file = (name: string, ageMs = 0) => {
    writeFileSync(join(dir, name), '');
    utimesSync(join(dir, name), (now - ageMs) / 1000, (now - ageMs) / 1000);
    return name;
  };
  beforeEach(() => {
    dir = mkdtempSync(join(tmpdir(), 'phasebook-stale-'));
  });

  it('removes partials of dead writers of this PID space and those untouched for a day; keeps the rest', () => {
    const dead = file(partialName('a.csv', 200, space));
    const old = file(partialName('b.csv', 100, space), STALE_AFTER_MS + 1000);
    const oldElsewhere = file(partialName('c.csv', 200, 'eeeeeeee'), STALE_AFTER_MS + 1000);
    const living = file(partialName('d.csv', 100, space), STALE_AFTER_MS - 60_000);
    const elsewhere = file(partialName('e.csv', 200, 'eeeeeeee'));
    const foreign = file('.a.csv.200.partial', 10 * STALE_AFTER_MS);
    const link = partialName('f.csv', 200, space);
    symlinkSync(join(dir, foreign), join(dir, link));
    const folder = partialName('g.csv', 200, space);
    mkdirSync(join(dir, folder));

    const removed = removeStalePartials(dir, { now, space, alive });
    expect(removed.sort()).toEqual([dead, old, oldElsewhere].sort());
    expect(readdirSync(dir).sort()).toEqual([living, elsewhere, foreign, link, folder].sort());
  });

  it('does nothing, and does not throw, for a directory it cannot read', () => {
    expect(removeStalePartials(join(dir, 'missing'), { now, space, alive })).toEqual([]);
  });
});
