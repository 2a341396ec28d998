/**
 * The CLI's sinks with the file system's failures injected: what no test
 * machine can be made to do on demand (EACCES as root, a short write, a
 * planted link at the very name the random part gives).
 */
import { existsSync, lstatSync, mkdtempSync, readdirSync, readFileSync, statSync, symlinkSync, writeFileSync } from 'node:fs';
import * as fs from 'node:fs';
import * as crypto from 'node:crypto';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { InterruptGuard } from '../../../../cli/interrupt.ts';
import { fileSink } from '../../../../cli/output/sink.ts';
import { OutputError, outputError } from '../../../../cli/output/output-error.ts';

vi.mock('node:fs', async (original) => {
  const real = await original<typeof import('node:fs')>();
  return { ...real, openSync: vi.fn(real.openSync), writeSync: vi.fn(real.writeSync), renameSync: vi.fn(real.renameSync) };
});
vi.mock('node:crypto', async (original) => {
  const real = await original<typeof import('node:crypto')>();
  return { ...real, randomBytes: vi.fn(real.randomBytes) };
});

const systemError = (code: string) => Object.assign(new Error(`${code}: injected`), { code });

let dir: string;
beforeEach(() => {
  dir = mkdtempSync(join(tmpdir(), 'phasebook-sink-'));
});
afterEach(() => {
  vi.mocked(fs.openSync).mockReset();
  vi.restoreAllMocks();
});

describe('outputError(error, path)', () => {
  it.each([
    ['ENOSPC', 'no space left on the device'],
    ['EDQUOT', 'the disk quota is used up'],
    ['EACCES', 'permission denied (it takes write permission on the directory /data)'],
    ['EPERM', 'permission denied (it takes write permission on the directory /data)'],
    ['EROFS', 'the file system is read-only'],
    ['EISDIR', 'it is a directory'],
    ['ENOENT', 'the directory /data does not exist'],
    ['ENOTDIR', 'a part of the path is not a directory'],
    ['EEXIST', 'another file has taken the name of its partial file'],
    ['EIO', 'an input/output error on the device'],
    ['EBUSY', 'EBUSY: injected'],
  ])('says %s in words, on one line', (code, words) => {
    const error = outputError(systemError(code), '/data/out.csv');
    expect(error).toBeInstanceOf(OutputError);
    expect(error.message).toBe(`cannot write /data/out.csv: ${words}`);
  });

  it('names stdout when there is no path, and passes on an error that is not the system\'s', () => {
    expect(outputError(systemError('ENOSPC')).message).toBe('cannot write stdout: no space left on the device');
    const bug = new TypeError('x is undefined');
    expect(outputError(bug, '/data/out.csv')).toBe(bug);
  });

  it('tells a directory that takes no new files from a missing one', () => {
    expect(outputError(systemError('ENOENT'), join(dir, 'out.csv')).message).toMatch(/: the directory takes no new files$/);
  });
});

describe('fileSink(path, guard)', () => {
  it('writes through a partial that appears under the target only on commit, holding the guard meanwhile', () => {
    const out = join(dir, 'out.csv');
    const guard = new InterruptGuard();
    const before = process.listenerCount('SIGINT');
    const sink = fileSink(out, guard);
    expect(process.listenerCount('SIGINT')).toBe(before + 1);
    sink.write('t,q\n');
    const [partial] = readdirSync(dir);
    expect(partial).toMatch(/^\.out\.csv\.phasebook-[0-9a-f]{8}-\d+-[0-9a-f]{32}\.partial$/);
    expect(existsSync(out)).toBe(false);
    sink.commit();
    expect(readdirSync(dir)).toEqual(['out.csv']);
    expect(readFileSync(out, 'utf8')).toBe('t,q\n');
    expect(process.listenerCount('SIGINT')).toBe(before);
  });

  it('renews its partial\'s modification time hourly while the run lives, so no other run takes it for abandoned', () => {
    const days = 5 * 86_400_000;
    vi.useFakeTimers({ now: Date.now() + days, toFake: ['setInterval', 'clearInterval', 'Date'] });
    try {
      const sink = fileSink(join(dir, 'out.csv'));
      const [partial] = readdirSync(dir);
      expect(statSync(join(dir, partial)).mtimeMs).toBeLessThan(Date.now() - days / 2);
      vi.advanceTimersByTime(3_600_000);
      expect(Math.abs(statSync(join(dir, partial)).mtimeMs - Date.now())).toBeLessThan(2000);
      sink.abandon();
      expect(vi.getTimerCount()).toBe(0);
    } finally {
      vi.useRealTimers();
    }
  });

  it('reports EACCES at creation in words and releases the guard', () => {
    vi.mocked(fs.openSync).mockImplementationOnce(() => {
      throw systemError('EACCES');
    });
    const guard = new InterruptGuard();
    const before = process.listenerCount('SIGTERM');
    expect(() => fileSink(join(dir, 'out.csv'), guard)).toThrow(
      new OutputError(`cannot write ${join(dir, 'out.csv')}: permission denied (it takes write permission on the directory ${dir})`),
    );
    expect(process.listenerCount('SIGTERM')).toBe(before);
    expect(readdirSync(dir)).toEqual([]);
  });

  it('reports ENOSPC mid-run in words, and abandon leaves nothing', () => {
    const sink = fileSink(join(dir, 'out.csv'));
    sink.write('t,q\n');
    vi.mocked(fs.writeSync).mockImplementationOnce(() => {
      throw systemError('ENOSPC');
    });
    expect(() => sink.write('0,1\n')).toThrow(/^cannot write .*out\.csv: no space left on the device$/);
    sink.abandon();
    expect(readdirSync(dir)).toEqual([]);
  });

  it('finishes a short write instead of losing its tail', () => {
    const out = join(dir, 'out.csv');
    const sink = fileSink(out);
    const real = vi.mocked(fs.writeSync).getMockImplementation() as unknown as (fd: number, buffer: Uint8Array, offset?: number, length?: number) => number;
    // A disk nearly full takes part of a buffer and returns the count taken.
    vi.mocked(fs.writeSync).mockImplementationOnce(((fd: number, buffer: Uint8Array, offset: number) => real(fd, buffer, offset, 3)) as typeof fs.writeSync);
    sink.write('t,q\n0,1\n');
    sink.commit();
    expect(readFileSync(out, 'utf8')).toBe('t,q\n0,1\n');
  });

  it('reports a failed rename in words and removes its partial', () => {
    const out = join(dir, 'out.csv');
    const sink = fileSink(out);
    sink.write('t,q\n');
    vi.mocked(fs.renameSync).mockImplementationOnce(() => {
      throw systemError('EROFS');
    });
    expect(() => sink.commit()).toThrow(/: the file system is read-only$/);
    sink.abandon();
    expect(readdirSync(dir)).toEqual([]);
  });

  it('never opens a link planted at the exact name its random part gives', () => {
    const victim = join(dir, 'victim.txt');
    writeFileSync(victim, 'precious\n');
    const zeros = Buffer.alloc(16);
    vi.mocked(crypto.randomBytes).mockImplementation((() => zeros) as unknown as typeof crypto.randomBytes);
    const probe = fileSink(join(dir, 'probe.csv'));
    const [predicted] = readdirSync(dir).filter((name) => name.endsWith('.partial'));
    probe.abandon();
    const planted = join(dir, predicted.replace('probe.csv', 'out.csv'));
    symlinkSync(victim, planted);
    expect(() => fileSink(join(dir, 'out.csv'))).toThrow(/: another file has taken the name of its partial file$/);
    expect(readFileSync(victim, 'utf8')).toBe('precious\n');
    expect(lstatSync(planted).isSymbolicLink()).toBe(true);
  });

  it('publishes nothing, and removes nothing, when its partial was replaced by another file', () => {
    const out = join(dir, 'out.csv');
    const sink = fileSink(out);
    sink.write('t,q\n');
    const [partial] = readdirSync(dir);
    fs.rmSync(join(dir, partial));
    writeFileSync(join(dir, partial), 'not phasebook\'s\n');
    expect(() => sink.commit()).toThrow(/its partial file was replaced or removed by another process$/);
    sink.abandon();
    expect(existsSync(out)).toBe(false);
    expect(readFileSync(join(dir, partial), 'utf8')).toBe('not phasebook\'s\n');
  });

  it('writes a character device as it is, without a partial beside it', (context) => {
    if (!existsSync('/dev/null')) context.skip('no /dev/null on this system');
    // Through a link in a scratch folder: a partial would show there, and a rename would only replace the link.
    const device = join(dir, 'null');
    symlinkSync('/dev/null', device);
    const sink = fileSink(device);
    sink.write('t,q\n');
    sink.commit();
    expect(readdirSync(dir)).toEqual(['null']);
    expect(lstatSync(device).isSymbolicLink()).toBe(true);
  });
});
