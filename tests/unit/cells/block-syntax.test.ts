import { describe, expect, test } from 'vitest';
import { asParsableBlock, blockAssignmentAt } from '../../../cells/block-syntax.ts';

describe('blockAssignmentAt(source)', () => {
  test('finds the = of a named block cell', () => {
    expect(blockAssignmentAt('phase = {\n  yield 1;\n}')).toBe(6);
    expect(blockAssignmentAt('// note\nx={ return 1 }')).toBe(9);
  });

  test('ignores expression cells, anonymous blocks, comparisons and arrows', () => {
    expect(blockAssignmentAt('x = 1')).toBe(-1);
    expect(blockAssignmentAt('{ return 1 }')).toBe(-1);
    expect(blockAssignmentAt('x == {}')).toBe(-1);
    expect(blockAssignmentAt('f = () => {}')).toBe(-1);
  });
});

describe('asParsableBlock(source)', () => {
  test('reads the = as ; and keeps the length', () => {
    expect(asParsableBlock('x = { return 1 }')).toBe('x ; { return 1 }');
    expect(asParsableBlock('x = 1')).toBe('x = 1');
  });
});
