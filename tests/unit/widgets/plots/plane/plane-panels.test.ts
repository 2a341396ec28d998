import { describe, expect, it } from 'vitest';
import { toPixel } from '../../../../../widgets/plots/scale.ts';
import { MARGIN } from '../../../../../widgets/plots/axes.ts';
import { contains } from '../../../../../widgets/plots/extent.ts';
import { growPanel, makePanel, panelRect, placePanel, settlePanel, type PanelSpec } from '../../../../../widgets/plots/plane/plane-panels.ts';
import { gridColumns } from '../../../../../widgets/plots/sizes.ts';

function spec(overrides: Partial<PanelSpec> = {}): PanelSpec {
  return {
    tracks: [
      { x: 3, y: 4, group: 1 },
      { x: 1, y: 2, group: 0 },
      { x: 5, y: 6, group: 1 },
    ],
    xLabel: 'x',
    yLabel: 'y',
    legend: [],
    xKind: 'linear',
    yKind: 'linear',
    constant: 1,
    equal: true,
    ...overrides,
  };
}

describe('plane-panels', () => {
  it('makePanel(spec) orders tracks by colour group so each group is one path', () => {
    const p = makePanel(spec());
    expect(Array.from(p.xs)).toEqual([1, 3, 5]);
    expect(p.groups).toEqual([0, 1]);
    expect(p.starts).toEqual([0, 1, 3]);
    expect(p.pens.x.length).toBe(3);
  });

  it('gridColumns(count, width) and panelRect(i, count, w, h) lay small multiples two abreast when there is room', () => {
    expect(gridColumns(1, 700)).toBe(1);
    expect(gridColumns(4, 700)).toBe(2);
    expect(gridColumns(4, 400)).toBe(1);
    const r = panelRect(3, 4, 700, 600);
    expect(r.left).toBe(350 + MARGIN.left);
    expect(r.top).toBe(300 + MARGIN.top);
    expect(r.width).toBe(350 - MARGIN.left - MARGIN.right);
  });

  it('growPanel(panel) grows an auto extent to show new samples, padded, and reports it', () => {
    const p = makePanel(spec());
    Object.assign(p.fresh, { x0: 0, x1: 10, y0: 0, y1: 5 });
    expect(growPanel(p)).toBe(true);
    expect(contains(p.fitted, { x0: 0, x1: 10, y0: 0, y1: 5 })).toBe(true);
    placePanel(p, { left: 0, top: 0, width: 200, height: 100 });
    Object.assign(p.fresh, { x0: 1, x1: 9, y0: 1, y1: 4 });
    expect(growPanel(p)).toBe(false);
  });

  it('growPanel(panel) leaves a fixed extent alone and keeps growth within the limit', () => {
    const fixed = makePanel(spec({ extent: { x0: -1, x1: 1, y0: -1, y1: 1 } }));
    Object.assign(fixed.fresh, { x0: -5, x1: 5, y0: 0, y1: 0 });
    expect(growPanel(fixed)).toBe(false);
    const limited = makePanel(spec({ limit: { x0: -10, x1: 10, y0: -10, y1: 10 } }));
    Object.assign(limited.fresh, { x0: -50, x1: 50, y0: -1, y1: 1 });
    expect(growPanel(limited)).toBe(true);
    expect(limited.fitted.x0).toBe(-10);
    expect(limited.fitted.x1).toBe(10);
    placePanel(limited, { left: 0, top: 0, width: 100, height: 100 });
    Object.assign(limited.fresh, { x0: -80, x1: 80, y0: -1, y1: 1 });
    expect(growPanel(limited)).toBe(false);
  });

  it('placePanel(panel, rect) maps the shown extent onto the rectangle with equal units per pixel', () => {
    const p = makePanel(spec());
    p.fitted = { x0: -1, x1: 1, y0: -1, y1: 1 };
    placePanel(p, { left: 50, top: 20, width: 400, height: 200 });
    const perX = (p.shown.x1 - p.shown.x0) / 400;
    const perY = (p.shown.y1 - p.shown.y0) / 200;
    expect(perX).toBeCloseTo(perY, 12);
    expect(toPixel(p.mx, 0)).toBeCloseTo(250, 9);
    expect(toPixel(p.my, 0)).toBeCloseTo(120, 9);
    expect(toPixel(p.my, p.shown.y1)).toBeCloseTo(20, 9);
  });

  it('settlePanel(panel) tightens an extent that growth left too large, and only then', () => {
    const p = makePanel(spec({ equal: false }));
    Object.assign(p.fresh, { x0: -1, x1: 1, y0: -1, y1: 1 });
    growPanel(p);
    p.fitted = { x0: -10, x1: 10, y0: -1.2, y1: 1.2 };
    expect(settlePanel(p)).toBe(true);
    expect(p.fitted.x1).toBeLessThan(2);
    expect(settlePanel(p)).toBe(false);
  });
});

describe('plane-panels growth', () => {
  it('growPanel(panel) never drops what was shown, and each growth is at least GROWTH× on the side that grew', () => {
    const p = makePanel(spec({ equal: false }));
    Object.assign(p.fresh, { x0: -4.5, x1: 4.5, y0: -1, y1: 1 });
    growPanel(p);
    placePanel(p, { left: 0, top: 0, width: 300, height: 200 });
    let previous = { ...p.fitted };
    // particles fly off to the right, a little further each frame
    for (let x = 5; x <= 60; x += 0.5) {
      Object.assign(p.fresh, { x0: x - 1, x1: x, y0: -1, y1: 1 });
      if (growPanel(p)) {
        expect(p.fitted.x0).toBeLessThanOrEqual(previous.x0);
        expect(p.fitted.x1 - p.fitted.x0).toBeGreaterThanOrEqual(1.4 * (previous.x1 - previous.x0) - 1e-9);
        placePanel(p, p.rect);
        previous = { ...p.fitted };
      }
    }
    expect(p.fitted.x1).toBeGreaterThanOrEqual(60);
    expect(p.fitted.x1).toBeLessThan(60 * 1.4 + 10);
  });
});
