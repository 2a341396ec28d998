import { describe, expect, test } from 'vitest';
import { parseCell } from '@observablehq/parser';
import { cellBody, compileCell } from '../../../widgets/cells/compile.ts';
import { describeCell, formatError, type CellSpec } from '../../../widgets/cells/spec.ts';

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
