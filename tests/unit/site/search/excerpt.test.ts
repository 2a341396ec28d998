import { describe, expect, it } from 'vitest';
import { excerptPieces } from '../../../../site/search/excerpt.ts';

describe('site/search/excerpt.ts: Pagefind\'s excerpts as text', () => {
  it('reads the marked words and unescapes what Pagefind escaped', () => {
    expect(excerptPieces('its largest <mark>Lyapunov</mark> exponent, &lt;x&gt; &amp;')).toEqual([
      { text: 'its largest ', marked: false },
      { text: 'Lyapunov', marked: true },
      { text: ' exponent, <x> &amp;', marked: false },
    ]);
  });

  it('joins neighbouring pieces alike and drops empty ones', () => {
    expect(excerptPieces('<mark>\\partial</mark><mark>H</mark>')).toEqual([{ text: '\\partialH', marked: true }]);
    expect(excerptPieces('')).toEqual([]);
  });

  it('never yields markup, whatever the excerpt holds', () => {
    const pieces = excerptPieces('<mark>a</mark></mark><script>alert(1)</script><mark>b');
    expect(pieces).toEqual([
      { text: 'a', marked: true },
      { text: '<script>alert(1)</script>', marked: false },
      { text: 'b', marked: true },
    ]);
  });
});
