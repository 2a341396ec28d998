import { describe, expect, it } from 'vitest';
import { clampEnd, wheelColumns } from '../../../../../widgets/plots/time/time-scroll.ts';

describe('plots/history', () => {
  it('clampEnd(end, first, liveEnd, w) keeps a scrolled window inside the record', () => {
    expect(clampEnd(5000, 0, 3000, 1000)).toBe(3000); // not past the live end
    expect(clampEnd(200, 0, 3000, 1000)).toBe(1000); // not before the first full window
    expect(clampEnd(200, 1500, 3000, 1000)).toBe(2500); // the record dropped its oldest rows
    expect(clampEnd(1800.4, 0, 3000, 1000)).toBe(1800);
    expect(clampEnd(-Infinity, 0, 600, 1000)).toBe(600); // shorter than a window: nothing to scroll
  });

  it('wheelColumns(event, page, ratio) scrolls on a horizontal wheel or a modified vertical one; a plain wheel is the page’s, paused or not', () => {
    const wheel = (deltaX: number, deltaY: number, keys: { shiftKey?: boolean; ctrlKey?: boolean; altKey?: boolean } = {}, deltaMode = 0) =>
      ({ deltaX, deltaY, deltaMode, shiftKey: false, ctrlKey: false, altKey: false, ...keys });
    expect(wheelColumns(wheel(0, 100), 1000, 2)).toBe(0); // the page scrolls
    expect(wheelColumns(wheel(3, 100), 1000, 2)).toBe(0); // mostly vertical: still the page's
    expect(wheelColumns(wheel(-30, 5), 1000, 2)).toBe(-60); // a sideways swipe
    expect(wheelColumns(wheel(0, 100, { shiftKey: true }), 1000, 2)).toBe(200);
    expect(wheelColumns(wheel(0, -100, { ctrlKey: true }), 1000, 2)).toBe(-200);
    expect(wheelColumns(wheel(0, 100, { altKey: true }), 1000, 2)).toBe(200);
    expect(wheelColumns(wheel(0, 3, { shiftKey: true }, 1), 1000, 1)).toBe(48); // lines of 16 px
    expect(wheelColumns(wheel(1, 0, {}, 2), 1000, 2)).toBe(1000); // a page
  });
});
