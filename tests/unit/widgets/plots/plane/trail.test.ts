import { describe, expect, it } from 'vitest';
import { ageBuckets, ageOpacity, Fader, FADE_FRAMES, FLOOR, MIN_STEP, parseTrail } from '../../../../../widgets/plots/plane/trail.ts';

describe('trail', () => {
  it('parseTrail(option) reads the four kinds of trail and rejects others', () => {
    expect(parseTrail(undefined)).toEqual({ kind: 'frames', length: FADE_FRAMES });
    expect(parseTrail('fade')).toEqual({ kind: 'frames', length: FADE_FRAMES });
    expect(parseTrail('full')).toEqual({ kind: 'full', length: Infinity });
    expect(parseTrail('none')).toEqual({ kind: 'none', length: 0 });
    expect(parseTrail(2.5)).toEqual({ kind: 'time', length: 2.5 });
    expect(() => parseTrail(-1)).toThrow(/positive number/);
    expect(() => parseTrail('long' as never)).toThrow(/trail must be/);
  });

  it('ageOpacity(age, length) falls from 1 to FLOOR over the length, then is 0', () => {
    expect(ageOpacity(0, 3)).toBe(1);
    expect(ageOpacity(1.5, 3)).toBeCloseTo(Math.sqrt(FLOOR), 12);
    expect(ageOpacity(3, 3)).toBe(0);
  });

  it('Fader.advance(dt) saves up small fades and pays them in steps of at least MIN_STEP', () => {
    const fader = new Fader(90);
    const perFrame = 1 - FLOOR ** (1 / 90);
    expect(perFrame).toBeLessThan(MIN_STEP);
    const alphas: number[] = [];
    for (let i = 0; i < 90; i++) alphas.push(fader.advance(1));
    const paid = alphas.filter((a) => a > 0);
    expect(paid.length).toBeGreaterThan(5);
    for (const a of paid) expect(a).toBeGreaterThanOrEqual(MIN_STEP);
    // what was paid, times what is still owed (less than MIN_STEP), keeps FLOOR over the trail's length
    const kept = paid.reduce((k, a) => k * (1 - a), 1);
    expect(kept).toBeGreaterThanOrEqual(FLOOR * (1 - 1e-12));
    expect(kept).toBeLessThan(FLOOR / (1 - MIN_STEP));
  });

  it('Fader.advance(dt) of a full trail (infinite length) never fades', () => {
    const fader = new Fader(Infinity);
    expect(fader.advance(1e9)).toBe(0);
  });

  it('Fader.clear() forgets the owed fade', () => {
    const fader = new Fader(10);
    expect(fader.advance(0.1)).toBe(0);
    fader.clear();
    expect(fader.advance(0.1)).toBe(0);
    expect(fader.advance(-1)).toBe(0);
  });

  it('ageBuckets(start, now, length, n) slices the last length time units into n, oldest first and faintest', () => {
    const buckets = ageBuckets(0, 10, 4, 4);
    expect(buckets.map((b) => b.t0)).toEqual([6, 7, 8, 9]);
    expect(buckets[3].t1).toBe(10);
    expect(buckets[0].opacity).toBeLessThan(buckets[3].opacity);
    expect(buckets[3].opacity).toBeCloseTo(FLOOR ** (0.5 / 4), 12);
  });

  it('ageBuckets(start, now, Infinity, n) is the whole record at full opacity', () => {
    expect(ageBuckets(2, 10, Infinity, 8)).toEqual([{ t0: 2, t1: 10, opacity: 1 }]);
  });
});
