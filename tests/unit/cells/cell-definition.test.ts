import { describe, expect, test } from 'vitest';
import { parseCell } from '@observablehq/parser';
import { cellBody, compileCell } from '../../../cells/cell-definition.ts';
import { describeCell, formatError, type CellSpec } from '../../../cells/spec.ts';
import { LoopGuard, LoopStopped } from '../../../cells/loop-guard.ts';

function specOf(source: string): CellSpec {
  return describeCell(parseCell(source));
}

function errorOf(run: () => unknown): string {
  try {
    run();
  } catch (error) {
    return formatError(error);
  }
  throw new Error('expected an error');
}

describe('describeCell(parseCell(source))', () => {
  test('names an expression cell and lists its inputs once each', () => {
    expect(specOf('period = 2 * PI / omega + omega')).toEqual({
      name: 'period',
      inputs: ['PI', 'omega'],
      async: false,
      generator: false,
      body: [9, 31],
      block: false,
      loops: [],
    });
  });

  test('leaves JavaScript globals such as Math out of the inputs', () => {
    expect(specOf('x = Math.sin(t)').inputs).toEqual(['t']);
  });

  test('keeps window properties such as status as inputs, so the runtime can reject them', () => {
    expect(specOf('x = status + name').inputs).toEqual(['status', 'name']);
  });

  test('flags generator and async blocks', () => {
    expect(specOf('{ yield 1 }')).toMatchObject({ name: null, generator: true, async: false, block: true });
    expect(specOf('x = { await 1; yield 2 }')).toMatchObject({ generator: true, async: true });
  });

  test('rejects viewof, mutable and import cells with a readable message', () => {
    expect(errorOf(() => specOf('viewof x = 1'))).toBe('SyntaxError: viewof cells are not supported');
    expect(errorOf(() => specOf('x = mutable y'))).toBe('SyntaxError: mutable references are not supported');
    expect(errorOf(() => specOf('import {a} from "b"'))).toBe('SyntaxError: import cells are not supported');
  });

  test('reports syntax errors with line and column', () => {
    expect(errorOf(() => specOf('omega = = 3'))).toBe('SyntaxError: Unexpected token (1:8)');
    expect(errorOf(() => specOf('x = {\n  return 1 +\n}'))).toBe('SyntaxError: Unexpected token (3:0)');
  });
});

describe('compileCell(source, spec, label)', () => {
  const run = (source: string, ...inputs: unknown[]) =>
    (compileCell(source, specOf(source), 'test') as (...values: unknown[]) => unknown)(...inputs);

  test('passes inputs as parameters in spec order', () => {
    expect(run('period = 2 * PI / omega', Math.PI, 4)).toBeCloseTo(Math.PI / 2, 12);
  });

  test('returns from a block cell', () => {
    expect(run('x = {\n  const a = 2;\n  return a * a;\n}')).toBe(4);
  });

  test('survives a trailing line comment in an expression cell', () => {
    expect(run('x = 1 + 2 // three')).toBe(3);
  });

  test('returns a generator from a generator cell', () => {
    const generator = run('x = { yield 1; yield 2 }') as Generator<number>;
    expect([...generator]).toEqual([1, 2]);
  });

  test('returns a promise from an async cell', async () => {
    await expect(run('x = await Promise.resolve(5)')).resolves.toBe(5);
  });

  test('compiles an empty cell to undefined', () => {
    expect(run('// nothing yet')).toBeUndefined();
    expect(cellBody('', specOf(''))).toBe('');
  });

  test('cannot be broken out of: the parser refuses unbalanced source first', () => {
    expect(errorOf(() => specOf('x = 1); globalThis.hacked = 1; (2'))).toMatch(/^SyntaxError: .*\(1:5\)$/);
  });
});

describe('loops in cells are guarded: a runaway loop stops with an error naming its cell', () => {
  /** A clock that moves 1 ms each time it is read, so a loop that checks it every iteration runs out in 2000 iterations. */
  const ticking = () => {
    let t = 0;
    return () => (t += 1);
  };

  test('describeCell lists every loop body, in functions too, and whether it is a block', () => {
    const source = 'x = { for (const a of b) f(a); let i = 0; do i++; while (i < 3); const g = () => { while (c) { i-- } }; return i }';
    const loops = specOf(source).loops ?? [];
    expect(loops.map(([s, e, block]) => [source.slice(s, e), block])).toEqual([
      ['f(a);', false],
      ['i++;', false],
      ['{ i-- }', true],
    ]);
  });

  test('an endless loop breaks, and the cell fails with a LoopStopped naming it', () => {
    const guard = new LoopGuard(ticking());
    const source = 'spin = { let n = 0; while (true) { n++; } return n }';
    const run = compileCell(source, specOf(source), 'spin', guard) as () => unknown;
    const error = (() => {
      try {
        run();
      } catch (e) {
        return e;
      }
    })();
    expect(error).toBeInstanceOf(LoopStopped);
    expect(formatError(error)).toMatch(/^RuntimeError: a loop in cell spin ran for more than 2 s/);
  });

  test('a loop without braces and a do-while are guarded too', () => {
    for (const source of ['a = { let n = 0; for (;;) n++; }', 'b = { let n = 0; do n++; while (true) }']) {
      const run = compileCell(source, specOf(source), 'x', new LoopGuard(ticking())) as () => unknown;
      expect(run).toThrow(LoopStopped);
    }
  });

  test('a loop that finishes in time gives its value untouched', () => {
    const source = 'sum = { let s = 0; for (let i = 1; i <= 1000; i++) s += i; return s }';
    expect((compileCell(source, specOf(source), 'sum', new LoopGuard(() => 0)) as () => unknown)()).toBe(500500);
  });

  test('a runaway loop in a function from one cell, called by another, fails the caller naming the function’s cell', () => {
    const guard = new LoopGuard(ticking());
    const a = 'forever = () => { while (true) {} }';
    const b = 'result = forever()';
    const forever = (compileCell(a, specOf(a), 'forever', guard) as () => unknown)();
    const result = compileCell(b, specOf(b), 'result', guard) as (f: unknown) => unknown;
    expect(() => result(forever)).toThrow(/a loop in cell forever/);
  });

  test('an async cell whose loop runs away after an await rejects', async () => {
    const source = 'later = { await null; while (true) {} }';
    const run = compileCell(source, specOf(source), 'later', new LoopGuard(ticking())) as () => Promise<unknown>;
    await expect(run()).rejects.toThrow(LoopStopped);
  });

  test('a generator looping around yield runs on: each frame is a new task', () => {
    const source = 'ticks = { let i = 0; while (true) { yield i++; } }';
    const frames: (() => void)[] = [];
    const guard = new LoopGuard(ticking(), 2000, (end) => frames.push(end));
    const run = compileCell(source, specOf(source), 'ticks', guard) as () => Iterator<number>;
    const generator = run();
    const values: number[] = [];
    for (let k = 0; k < 3000; k++) {
      values.push(generator.next().value as number);
      frames.splice(0).forEach((end) => end()); // the browser's turn between frames
    }
    expect(values[2999]).toBe(2999);
  });
});
