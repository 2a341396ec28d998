import { describe, expect, it } from 'vitest';
import { spanningViews } from '../../../../widgets/plots/sizes.ts';

describe('spanningViews(spectrum)', () => {
  const kinds = (...views: string[]) => spanningViews(views.map((v) => v === 'spectrum'));

  it('pairs the views in order and gives the spectrum the whole width', () => {
    expect(kinds('time', 'phase', 'spectrum')).toEqual([false, false, true]);
    expect(kinds('trajectory', 'time')).toEqual([false, false]);
    expect(kinds('time', 'phase', 'trajectory', 'spectrum')).toEqual([false, false, true, true]);
  });

  it('lets a view with no neighbour to pair with take the whole width', () => {
    expect(kinds('time')).toEqual([true]);
    expect(kinds('spectrum')).toEqual([true]);
    expect(kinds('time', 'spectrum')).toEqual([true, true]);
    expect(kinds('time', 'spectrum', 'phase')).toEqual([true, true, true]);
    expect(kinds('time', 'phase', 'trajectory')).toEqual([false, false, true]);
    expect(kinds()).toEqual([]);
  });
});
