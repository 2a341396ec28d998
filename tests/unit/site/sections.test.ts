import { describe, expect, it } from 'vitest';
import { sectionsOf } from '../../../site/lib/sections.ts';

describe('site/lib/sections.ts: a chapter\'s sections from its headings', () => {
  it('lists the h2 headings with the h3 headings under each, and leaves deeper ones to the text', () => {
    const sections = sectionsOf([
      { depth: 1, slug: 'title', text: 'Title' },
      { depth: 2, slug: 'a', text: 'A' },
      { depth: 3, slug: 'a1', text: 'A one' },
      { depth: 4, slug: 'a1x', text: 'Deep' },
      { depth: 2, slug: 'b', text: '  B\n  two ' },
    ]);
    expect(sections).toEqual([
      { id: 'a', title: 'A', subsections: [{ id: 'a1', title: 'A one', subsections: [] }] },
      { id: 'b', title: 'B two', subsections: [] },
    ]);
  });

  it('keeps an h3 that comes before any h2, and skips headings without a slug or text', () => {
    expect(sectionsOf([{ depth: 3, slug: 'early', text: 'Early' }, { depth: 2, slug: '', text: 'No slug' }, { depth: 2, slug: 'blank', text: ' ' }])).toEqual([
      { id: 'early', title: 'Early', subsections: [] },
    ]);
  });
});
