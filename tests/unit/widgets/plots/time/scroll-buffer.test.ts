import { describe, expect, it } from 'vitest';
import { ScrollBuffer, SLOTS, slotOf, tileOf, tileSpan, tileX, viewLeft } from '../../../../../widgets/plots/time/scroll-buffer.ts';
import { fakeFactory } from '../../../support/fake-canvas.ts';

describe('plots/scroll-buffer', () => {
  it('tileOf(c, w) and slotOf(k) place column c in tile ⌊c/w⌋ and slot k mod 3', () => {
    expect([0, 99, 100, 250, -1].map((c) => tileOf(c, 100))).toEqual([0, 0, 1, 2, -1]);
    expect([0, 1, 2, 3, 4, -1].map(slotOf)).toEqual([0, 1, 2, 0, 1, 2]);
  });

  it('viewLeft(end, w) keeps the trace at the left until it fills the view, then scrolls', () => {
    expect(viewLeft(30, 100)).toBe(0);
    expect(viewLeft(100, 100)).toBe(0);
    expect(viewLeft(130, 100)).toBe(30);
  });

  it('tileX(k, w, left) reproduces the paper’s sprite positions −(m mod w) and w − (m mod w)', () => {
    const w = 1024;
    for (const end of [1500, 2047, 2048, 5000]) {
      const left = viewLeft(end, w);
      const m = left; // the paper's m_t(t) of the view's left edge
      const k = tileOf(left, w);
      expect(tileX(k, w, left) + 0).toBe(-(m % w) + 0);
      expect(tileX(k + 1, w, left)).toBe(w - (m % w));
    }
  });

  it('tileSpan(c0, c1, w, pad) includes neighbours within pad of a boundary, never more than one tile back', () => {
    expect(tileSpan(10, 50, 100, 4)).toEqual([0, 0]);
    expect(tileSpan(97, 99, 100, 4)).toEqual([0, 1]);
    expect(tileSpan(101, 120, 100, 4)).toEqual([0, 1]);
    expect(tileSpan(0, 950, 100, 4)).toEqual([8, 9]);
  });

  it('ScrollBuffer.claim(k) clears a slot only when it changes tile', () => {
    const { create, made } = fakeFactory();
    const buffer = new ScrollBuffer(100, 50, create);
    expect(made).toHaveLength(SLOTS);
    buffer.claim(0);
    buffer.claim(0);
    expect(made[0].context.named('clearRect')).toHaveLength(1);
    buffer.claim(3);
    expect(made[0].context.named('clearRect')).toHaveLength(2);
    expect(buffer.holds(3)).toBe(true);
    expect(buffer.holds(0)).toBe(false);
  });

  it('ScrollBuffer.paint(…) never recycles a slot that is visible, for any drawing pace', () => {
    const { create } = fakeFactory();
    const w = 100;
    const buffer = new ScrollBuffer(w, 10, create);
    let end = 0;
    let seed = 7;
    for (let frame = 0; frame < 2000; frame++) {
      seed = (seed * 16807) % 2147483647;
      const step = 1 + (seed % 60);
      const c0 = end;
      const c1 = end + step - 1;
      buffer.paint(c0, c1, 4, () => {});
      end = c1 + 1;
      // every tile intersecting the view [left, end) is still held by its slot
      const left = viewLeft(end, w);
      for (let k = tileOf(left, w); k <= tileOf(end - 1, w); k++) expect(buffer.holds(k)).toBe(true);
    }
  });

  it('ScrollBuffer.placement(slot, end) positions the visible tiles and hides the rest', () => {
    const { create } = fakeFactory();
    const buffer = new ScrollBuffer(100, 10, create);
    buffer.paint(0, 249, 4, () => {}); // tiles 0, 1, 2 (and 3 for the pad? no: 249 + 4 < 300)
    const xs = [0, 1, 2].map((slot) => buffer.placement(slot, 250));
    expect(xs[1]).toBe(-50); // tile 1 starts 50 columns left of the view
    expect(xs[2]).toBe(50);
    expect(xs[0]).toBeNaN(); // tile 0 has scrolled out
  });

  it('ScrollBuffer.composite(target, end) blits the visible tiles at their places', () => {
    const { create, made } = fakeFactory();
    const buffer = new ScrollBuffer(100, 10, create);
    buffer.paint(0, 249, 4, () => {});
    const target = fakeFactory().create(100, 10);
    buffer.composite((target as never as { getContext(): never }).getContext(), 250, 5, 7);
    const blits = (target as unknown as { context: { named(n: string): unknown[][] } }).context.named('drawImage');
    expect(blits.map((b) => [made.indexOf(b[1] as never), b[2], b[3]])).toEqual([[1, -45, 7], [2, 55, 7]]);
  });
});
