import { describe, expect, test } from 'vitest';
import { lineAtOffset, offsetOfLine } from '../../src/preview/scroll-map.ts';

const blocks = [
  { line: 0, endLine: 4, top: 0, height: 50 },
  { line: 6, endLine: 6, top: 60, height: 20 },
  { line: 8, endLine: 17, top: 100, height: 300 },
];

describe('scroll map', () => {
  test('offsetOfLine(blocks, line) spreads a block\'s lines over its height', () => {
    expect(offsetOfLine(blocks, 0)).toBe(0);
    expect(offsetOfLine(blocks, 6)).toBe(60);
    expect(offsetOfLine(blocks, 13)).toBe(100 + 0.5 * 300);
    // A blank line between blocks shows the end of the block before it.
    expect(offsetOfLine(blocks, 7)).toBe(80);
    expect(offsetOfLine([], 3)).toBe(0);
  });

  test('lineAtOffset(blocks, y) is its inverse inside blocks', () => {
    expect(lineAtOffset(blocks, 250)).toBe(13);
    expect(lineAtOffset(blocks, 60)).toBe(6);
    for (const line of [0, 2, 6, 9, 15]) expect(lineAtOffset(blocks, offsetOfLine(blocks, line))).toBeCloseTo(line, 10);
    expect(lineAtOffset([], 10)).toBeNull();
  });
});
