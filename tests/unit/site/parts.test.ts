/**
 * The contents page's parts (site/lib/parts.ts): runs of one part in reading
 * order, pages outside the parts left where they stand; the numerals.
 */
import { describe, expect, test } from 'vitest';
import { romanPart, runsOfParts } from '../../../site/lib/parts.ts';

const chapter = (id: string, part?: number) => ({ id, data: { part } });

describe('runsOfParts', () => {
  test('cuts the reading order where the part changes, and keeps the pages outside the parts after them', () => {
    const runs = runsOfParts([chapter('intro', 1), chapter('kepler', 1), chapter('three-body', 2), chapter('playground'), chapter('about')]);
    expect(runs.map((r) => [r.part, r.chapters.map((c) => c.id)])).toEqual([
      [1, ['intro', 'kepler']],
      [2, ['three-body']],
      [undefined, ['playground', 'about']],
    ]);
  });

  test('an empty book has no runs; a book without parts has one run under no heading', () => {
    expect(runsOfParts([])).toEqual([]);
    expect(runsOfParts([chapter('a'), chapter('b')]).map((r) => r.part)).toEqual([undefined]);
  });
});

test('romanPart gives the numerals of the parts', () => {
  expect([1, 2, 3, 4, 9, 14].map(romanPart)).toEqual(['I', 'II', 'III', 'IV', 'IX', 'XIV']);
});
