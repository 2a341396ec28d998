import { describe, expect, it } from 'vitest';
import { multiples, TimeAxisStrips, timeTicks } from '../../../../../widgets/plots/time/time-axis.ts';
import type { Theme } from '../../../../../widgets/plots/theme.ts';
import { fakeFactory } from '../../../support/fake-canvas.ts';

const style: Theme = { fg: '#111', bg: '#fff', muted: '#333', accent: '#00f', axis: '#666', grid: '#ccc', series: ['red'], font: 'sans-serif', dark: false };

describe('plots/time-axis', () => {
  it('timeTicks(window, width) picks one step for the whole trace', () => {
    expect(timeTicks(10, 640).step).toBe(2);
    expect(timeTicks(50, 640).step).toBe(10);
    expect(timeTicks(1, 640).format(0.4)).toBe('0.4');
  });

  it('multiples(t0, t1, step) lists the ticks in [t0, t1) without rounding drift', () => {
    expect(multiples(0, 10, 2)).toEqual([0, 2, 4, 6, 8]);
    expect(Object.is(multiples(-1e-12, 1, 1)[0], 0)).toBe(true);
    expect(multiples(1.1, 2.05, 0.2)).toEqual([1.2000000000000002, 1.4000000000000001, 1.6, 1.8, 2]);
    expect(multiples(-3, 1, 1)).toEqual([-3, -2, -1, 0]);
  });

  it('TimeAxisStrips.place(end, …) draws each tile’s ticks once and moves the strips with the tiles', () => {
    const { create, made } = fakeFactory();
    const strips = new TimeAxisStrips(create);
    const mapping = { origin: 0, window: 10, width: 600, scaleX: 60 };
    strips.resize(600, 24, 1, mapping);
    const positions: number[][] = [];
    for (const end of [300, 600, 900, 905, 1500]) {
      const xs: number[] = [];
      strips.place(end, mapping, style, (_slot, _strip, x) => xs.push(x));
      positions.push(xs);
    }
    // each tile's labels are drawn once, however often it is placed: tiles 0, 1, 2
    const labels = made.flatMap((s) => s.context.named('fillText').map((c) => c[1]));
    expect(labels.sort()).toEqual(['0', '10', '12', '14', '16', '18', '2', '20', '22', '24', '26', '28', '4', '6', '8']);
    expect(positions[0]).toEqual([0, NaN, NaN]); // tile 0 at the plot's left
    expect(positions[2]).toEqual([-300, 300, NaN]); // like the data tiles: k·w − left
    expect(positions[4]).toEqual([NaN, -300, 300]);
  });

  it('TimeAxisStrips draw labels at their time’s column, offset by the spill', () => {
    const { create, made } = fakeFactory();
    const strips = new TimeAxisStrips(create);
    const mapping = { origin: 0, window: 10, width: 600, scaleX: 60 };
    strips.resize(600, 24, 1, mapping);
    strips.place(600, mapping, style, () => {});
    const label = made[0].context.named('fillText').find((c) => c[1] === '4')!;
    expect(label[2]).toBe(strips.spill + 4 * 60 + 0.5);
    expect(made[0].width).toBe(600 + 2 * strips.spill);
  });
});
