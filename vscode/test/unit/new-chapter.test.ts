import { describe, expect, test } from 'vitest';
import { analyzeChapter } from '../../src/analyzer/analyze.ts';
import { chapterFromTemplate, fileNameFor, nextFreeOrder } from '../../src/analyzer/new-chapter.ts';
import { readBook, realBuiltins } from './support.ts';

describe('a new chapter from the template', () => {
  test('nextFreeOrder(orders) is the smallest whole number no chapter uses', () => {
    expect(nextFreeOrder([1, 2, 3, 4, 5, 6, 7, 90, 98, 99])).toBe(8);
    expect(nextFreeOrder([2, 3])).toBe(1);
    expect(nextFreeOrder([])).toBe(1);
  });

  test('fileNameFor(title) makes a plain file name', () => {
    expect(fileNameFor('The driven pendulum')).toBe('the-driven-pendulum.mdx');
    expect(fileNameFor('Poincaré sections: a first look!')).toBe('poincare-sections-a-first-look.mdx');
    expect(fileNameFor('???')).toBe('chapter.mdx');
  });

  test("chapterFromTemplate(template, title, order) is the template with the author's title and order, and a valid chapter", () => {
    const text = chapterFromTemplate(readBook('templates/chapter.mdx'), 'Waves: a first look', 8);
    expect(text).toMatch(/^title: "Waves: a first look"$/m);
    expect(text).toMatch(/^order: 8$/m);
    const analysis = analyzeChapter(text, realBuiltins());
    expect(analysis.frontMatter).toMatchObject({ title: 'Waves: a first look', order: { value: 8 }, problems: [] });
    expect(analysis.problems).toEqual([]);
  });

  test('a template without an order line is refused', () => {
    expect(() => chapterFromTemplate('---\ntitle: x\n---\n', 'T', 1)).toThrow(/no `order:` line/);
  });
});
