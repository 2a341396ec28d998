import { describe, expect, it, vi } from 'vitest';
import { progressBar } from '../../../cli/progress.ts';

function fakeStream(isTTY: boolean) {
  const writes: string[] = [];
  return { stream: { isTTY, write: (s: string) => writes.push(s) } as unknown as NodeJS.WriteStream, writes };
}

describe('progressBar(stream, delayMs)', () => {
  it('stays silent during the first second, then draws a bar and clears it when done', () => {
    vi.useFakeTimers({ toFake: ['performance'] });
    const { stream, writes } = fakeStream(true);
    const bar = progressBar(stream, 1000);
    bar.update(0.1, 't = 1');
    expect(writes).toEqual([]);
    vi.advanceTimersByTime(1500);
    bar.update(0.5, 't = 5');
    expect(writes).toHaveLength(1);
    expect(writes[0]).toMatch(/^\r█{15}░{15}  50%  t = 5/);
    bar.done();
    expect(writes[1]).toBe('\r\x1b[K');
    vi.useRealTimers();
  });

  it('writes nothing when stderr is not a terminal (a pipe or a file)', () => {
    vi.useFakeTimers({ toFake: ['performance'] });
    const { stream, writes } = fakeStream(false);
    const bar = progressBar(stream, 0);
    vi.advanceTimersByTime(5000);
    bar.update(0.5, '');
    bar.done();
    expect(writes).toEqual([]);
    vi.useRealTimers();
  });

  it('estimates the time left from the pace so far', () => {
    vi.useFakeTimers({ toFake: ['performance'] });
    const { stream, writes } = fakeStream(true);
    const bar = progressBar(stream, 0);
    vi.advanceTimersByTime(10_000);
    bar.update(0.25, '250/1000 trajectories');
    // A quarter in 10 s: three quarters more take 30 s.
    expect(writes[0]).toMatch(/25%  250\/1000 trajectories  ETA 30 s/);
    vi.advanceTimersByTime(90_000);
    bar.update(0.5, '500/1000 trajectories');
    expect(writes[1]).toMatch(/ETA 1 min 40 s/);
    vi.useRealTimers();
  });
});
