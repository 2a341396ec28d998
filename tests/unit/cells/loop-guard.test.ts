/**
 * The loop guard's accounting (cells/loop-guard.ts): time is charged
 * to a cell across microtasks, until the task ends, and cell by cell.
 * Clocks and task ends are driven by hand, so nothing here depends on how
 * fast the machine is.
 */
import { parseCell } from '@observablehq/parser';
import { describe, expect, test } from 'vitest';
import { compileCell } from '../../../cells/cell-definition.ts';
import { LoopGuard, LoopStopped, type AfterTask } from '../../../cells/loop-guard.ts';
import { describeCell } from '../../../cells/spec.ts';

/** A clock that moves `step` ms each time it is read. */
function ticking(step = 1) {
  let t = 0;
  return { now: () => (t += step), jump: (ms: number) => (t += ms) };
}

/** Task ends delivered only when the test says the task is over. */
function tasks() {
  const waiting: (() => void)[] = [];
  const afterTask: AfterTask = (end) => waiting.push(end);
  return { afterTask, end: () => waiting.splice(0).forEach((f) => f()) };
}

const compile = (source: string, id: string, guard: LoopGuard) => compileCell(source, describeCell(parseCell(source)), id, guard) as () => unknown;

describe('LoopGuard', () => {
  test('an async loop that awaits between iterations is charged across the microtasks and stopped', async () => {
    const clock = ticking();
    const { afterTask } = tasks();
    const guard = new LoopGuard(clock.now, 2000, afterTask);
    const spin = compile('spin = (async () => { let n = 0; while (true) { n++; await 0 } })()', 'spin', guard);
    const stop = await (spin() as Promise<unknown>).catch((e: unknown) => e);
    expect(stop).toBeInstanceOf(LoopStopped);
    expect((stop as LoopStopped).label).toBe('cell spin');
  });

  test('an endless async loop started by a cell that already returned is stopped, and the guard says whose it was', async () => {
    const { afterTask } = tasks();
    const guard = new LoopGuard(ticking().now, 2000, afterTask);
    const stops: string[] = [];
    guard.onStop((stop) => stops.push(stop.cell));
    const cell = compile('H0 = { (async () => { while (true) await 0 })(); return 1 }', 'H0', guard);
    expect(cell()).toBe(1);
    await new Promise((done) => setTimeout(done, 0));
    expect(stops).toEqual(['H0']);
  });

  test('a new task starts every cell afresh', () => {
    const clock = ticking();
    const { afterTask, end } = tasks();
    const guard = new LoopGuard(clock.now, 2000, afterTask);
    const check = guard.forCell('a');
    for (let i = 0; i < 1500; i++) expect(check()).toBe(false);
    end();
    for (let i = 0; i < 1500; i++) expect(check()).toBe(false);
    expect(guard.count).toBe(0);
  });

  test('two cells computed in one task are each charged their own loop, not the other’s', () => {
    const clock = ticking();
    const { afterTask } = tasks();
    const guard = new LoopGuard(clock.now, 2000, afterTask);
    const a = guard.forCell('a');
    const b = guard.forCell('b');
    for (let i = 0; i < 1500; i++) expect(a()).toBe(false);
    // The page did other work in between: not b's.
    clock.jump(5000);
    for (let i = 0; i < 1500; i++) expect(b()).toBe(false);
    expect(guard.count).toBe(0);
  });

  test('two endless loops taking turns are both charged, and both stop', () => {
    const clock = ticking();
    const { afterTask } = tasks();
    const guard = new LoopGuard(clock.now, 2000, afterTask);
    const a = guard.forCell('a');
    const b = guard.forCell('b');
    let aBroke = false;
    let bBroke = false;
    for (let i = 0; i < 10_000 && !(aBroke && bBroke); i++) {
      aBroke ||= a();
      bBroke ||= b();
    }
    expect(aBroke && bBroke).toBe(true);
  });

  test('a cell that ran out of time has its later loops broken until the task ends, and is announced once', async () => {
    const { afterTask, end } = tasks();
    const guard = new LoopGuard(ticking().now, 2000, afterTask);
    const stops: LoopStopped[] = [];
    guard.onStop((stop) => stops.push(stop));
    const check = guard.forCell('x', 'cell x');
    while (!check());
    await Promise.resolve();
    const before = guard.count;
    expect(check()).toBe(true);
    expect(guard.stoppedSince(before)?.label).toBe('cell x');
    expect(stops.map((s) => s.message)).toEqual(['a loop in cell x ran for more than 2 s without finishing and was stopped, so the page would not freeze']);
    end();
    expect(check()).toBe(false);
  });

  test('a stop breaks every guarded loop of the same stretch, another cell’s too', async () => {
    const { afterTask } = tasks();
    const guard = new LoopGuard(ticking().now, 2000, afterTask);
    const inner = guard.forCell('inner');
    const outer = guard.forCell('outer');
    while (!inner());
    expect(outer()).toBe(true);
    // From the next microtask on, the other cell's loops run again.
    await Promise.resolve();
    expect(outer()).toBe(false);
  });
});
