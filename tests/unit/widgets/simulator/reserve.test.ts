import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import {
  heightAt, heightCss, PHASE_MULTIPLE, PHASE_PANEL, SPECTRUM_PLOT, timePlotHeight, TRAJECTORY_PANEL, TWO_COLUMNS_FROM,
} from '../../../../widgets/plots/sizes.ts';
import { reserveHtml, simulatorPlan } from '../../../../widgets/simulator/reserve.ts';

/**
 * Evaluates the CSS length the reservation writes — clamp(), calc(), px and
 * cqw of a container `views` pixels wide — the way a browser does.
 */
function cssPixels(expression: string, views: number): number {
  const js = expression
    .replace(/calc\(/g, '(')
    .replace(/clamp\(/g, 'clamp(')
    .replace(/(\d+(?:\.\d+)?)cqw/g, (_, n) => String((Number(n) / 100) * views))
    .replace(/(\d+(?:\.\d+)?)px/g, '$1');
  return new Function('clamp', `return ${js};`)((lo: number, v: number, hi: number) => Math.max(lo, Math.min(v, hi)));
}

/** The CSS custom properties of the first reserved stage in `html`. */
function stageVars(html: string): Record<string, string> {
  const style = /class="pb-reserve-stage" style="([^"]*)"/.exec(html)?.[1] ?? '';
  return Object.fromEntries(style.split(';').map((part) => part.split(/:(.*)/s).map((s) => s.trim())).filter(([k]) => k));
}

const oneDof = { dof: 1, names: ['q', 'p'] };
const fourDof = { dof: 4, names: ['q0', 'q1', 'q2', 'q3', 'p0', 'p1', 'p2', 'p3'] };

describe('the box reserved for a simulator', () => {
  it('heightCss(size, width) is the height heightAt gives the canvas, at every width (to the canvas’s rounding)', () => {
    for (const size of [TRAJECTORY_PANEL, PHASE_PANEL, PHASE_MULTIPLE, SPECTRUM_PLOT]) {
      for (let width = 200; width <= 1200; width += 7) {
        expect(Math.abs(cssPixels(heightCss(size, '100cqw'), width) - heightAt(size, width))).toBeLessThanOrEqual(0.5);
      }
    }
  });

  it('a plane stage is its canvas (the views’ width less the 1 px border on each side) plus that border', () => {
    const html = reserveHtml(simulatorPlan({ views: ['trajectory'] }, oneDof));
    for (const views of [320, 656, 900]) {
      const canvas = heightAt(TRAJECTORY_PANEL, views - 2);
      expect(Math.abs(cssPixels(stageVars(html)['--pb-narrow'], views) - (canvas + 2))).toBeLessThanOrEqual(0.5);
    }
  });

  it('small multiples go two abreast from the widget’s own threshold, in rows of the half-width panel', () => {
    const plan = simulatorPlan({ views: ['phase'], phase: { layout: 'multiples' } }, fourDof);
    expect(plan.views[0]).toMatchObject({ kind: 'phase', panels: 4 });
    const vars = stageVars(reserveHtml(plan));
    // One column below the threshold: four panels of the full width.
    expect(Math.abs(cssPixels(vars['--pb-narrow'], 400) - (4 * heightAt(PHASE_MULTIPLE, 398) + 2))).toBeLessThanOrEqual(2);
    // Two columns above it: two rows of panels half as wide.
    expect(Math.abs(cssPixels(vars['--pb-wide'], 800) - (2 * heightAt(PHASE_MULTIPLE, 798 / 2) + 2))).toBeLessThanOrEqual(1);
    // The stylesheet switches at the widget's threshold, counted on the view's width (canvas + border).
    const css = readFileSync(new URL('../../../../widgets/widgets.css', import.meta.url), 'utf8');
    expect(css).toContain(`@container pb-view (min-width: ${TWO_COLUMNS_FROM + 2}px)`);
  });

  it('fixed heights are reserved as given, and the time plot’s from its plotting area', () => {
    const html = reserveHtml(simulatorPlan({ views: ['time', 'spectrum'], timePlot: { height: 150 }, spectrum: { height: 250 } }, oneDof));
    expect(html).toContain(`style="height: ${timePlotHeight(150)}px"`);
    expect(stageVars(html)['--pb-narrow']).toBe('252px');
    expect(timePlotHeight(150)).toBe(150 + 8 + 24);
  });

  it('reserves the spectrum readout’s fixed number of lines: its peaks, the comparison and the basis', () => {
    expect(reserveHtml(simulatorPlan({ views: ['spectrum'] }, oneDof))).toContain('--pb-readout-lines: 5');
    expect(reserveHtml(simulatorPlan({ views: ['spectrum'], spectrum: { peaks: 6 } }, oneDof))).toContain('--pb-readout-lines: 8');
  });

  it('names its views, in order, for the page to fetch their modules early; the default is the time plot', () => {
    expect(reserveHtml(simulatorPlan({}, oneDof))).toContain('data-reserve-views="time"');
    expect(reserveHtml(simulatorPlan({ views: ['trajectory', 'time'] }, oneDof))).toContain('data-reserve-views="trajectory time"');
  });

  it('rejects what simulator() rejects, so the build reserves nothing for a cell that will fail', () => {
    expect(() => simulatorPlan({ views: ['phases'] }, oneDof)).toThrow(/unknown view "phases"/);
    expect(() => simulatorPlan({ views: ['phase'], phase: { layout: 'multiples', pairs: [7] } }, oneDof)).toThrow(/pair 7 does not exist/);
  });
});
