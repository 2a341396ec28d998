/**
 * The space a simulator will take, as markup the build puts where the widget
 * will appear (site/lib/precompile.ts). The page shows it until the widget
 * replaces it, so a simulator that appears while the reader looks moves
 * nothing under it.
 *
 * The box is built from the widget's own classes — `.pb-simulator`,
 * `.pb-bar`, `.pb-views`, `.pb-plot-bar`, `.pb-data` — so it gets the
 * widget's padding, gaps and the rows' heights from the one stylesheet
 * (widgets/widgets.css), and the views' columns (one, or two abreast on a
 * wide simulator); each plot's height is the view's own rule
 * (plots/sizes.ts) written in CSS on the width of its `.pb-plot`, a size
 * container. No DOM here: the build runs it in Node.
 */
import type { Model } from '../../core/index.ts';
import { phasePairs } from '../plots/record-columns.ts';
import { heightCss, PHASE_MULTIPLE, PHASE_PANEL, spanningViews, SPECTRUM_PLOT, timePlotHeight, TRAJECTORY_PANEL, type Proportional } from '../plots/sizes.ts';
import { readoutLines } from '../plots/spectrum/spectrum-readout.ts';
import { viewNames, type ViewName } from './options.ts';

/** What a view's options say about its height: fixed pixels, or a function (which CSS cannot follow). */
type HeightOption = number | ((width: number) => number) | undefined;

/** What decides a simulator's height, from its options and its model. */
export interface SimulatorPlan {
  readonly views: readonly ReservedView[];
}

export type ReservedView =
  | { readonly kind: 'time'; readonly area: number | undefined }
  | { readonly kind: 'trajectory' | 'phase'; readonly panel: Proportional; readonly panels: number; readonly height: HeightOption }
  | { readonly kind: 'spectrum'; readonly height: HeightOption; readonly controls: boolean; readonly peaks: number };

/** The options of simulator() that shape it. */
export interface ReserveOptions {
  views?: unknown;
  timePlot?: { height?: number };
  trajectory?: { height?: HeightOption };
  phase?: { height?: HeightOption; layout?: 'overlay' | 'multiples'; pairs?: readonly (number | readonly [string, string])[] };
  spectrum?: { height?: HeightOption; controls?: boolean; peaks?: number };
}

/** The plan of a simulator with these options and this model; throws, like simulator(), on options it would reject. */
export function simulatorPlan(options: ReserveOptions, model: Pick<Model, 'dof' | 'names'>): SimulatorPlan {
  return { views: viewNames(options.views).map((name) => reservedView(name, options, model)) };
}

function reservedView(name: ViewName, options: ReserveOptions, model: Pick<Model, 'dof' | 'names'>): ReservedView {
  switch (name) {
    case 'time':
      return { kind: 'time', area: options.timePlot?.height };
    case 'trajectory':
      return { kind: 'trajectory', panel: TRAJECTORY_PANEL, panels: 1, height: options.trajectory?.height };
    case 'phase': {
      const multiples = options.phase?.layout === 'multiples';
      const panels = multiples ? phasePairs(model.names, model.dof, options.phase?.pairs).length : 1;
      return { kind: 'phase', panel: multiples ? PHASE_MULTIPLE : PHASE_PANEL, panels, height: options.phase?.height };
    }
    case 'spectrum':
      return { kind: 'spectrum', height: options.spectrum?.height, controls: options.spectrum?.controls !== false, peaks: options.spectrum?.peaks ?? 3 };
  }
}

/** The canvas width of a view: the view's width inside the stage's 1 px border. */
const CANVAS_WIDTH = '100cqw - 2px';

/**
 * A plane or spectrum stage's height: its canvas, by the view's rule, plus
 * the border. `--pb-wide` applies from the width at which plane panels go
 * two abreast (widgets.css).
 */
function stageStyle(panel: Proportional, panels: number, height: HeightOption): string {
  // A function of the width is the author's own and cannot be written in CSS: its default is reserved.
  if (typeof height === 'number') return `--pb-narrow: ${height + 2}px`;
  const narrow = `calc(${panels} * ${heightCss(panel, CANVAS_WIDTH)} + 2px)`;
  if (panels === 1) return `--pb-narrow: ${narrow}`;
  const rows = Math.ceil(panels / 2);
  const wide = `calc(${rows} * ${heightCss(panel, `(${CANVAS_WIDTH}) / 2`)} + 2px)`;
  return `--pb-narrow: ${narrow}; --pb-wide: ${wide}`;
}

/** A view's box; `span` when it takes the whole width where views go two abreast. */
function viewHtml(view: ReservedView, span: boolean): string {
  const plot = span ? 'pb-plot pb-span' : 'pb-plot';
  switch (view.kind) {
    case 'time':
      return `<div class="${plot} pb-time-plot"><div class="pb-plot-bar"></div>`
        + `<div class="pb-stage" style="height: ${timePlotHeight(view.area)}px"></div><div class="pb-scrub-row"></div></div>`;
    case 'trajectory':
    case 'phase':
      return `<div class="${plot}"><div class="pb-reserve-stage" style="${stageStyle(view.panel, view.panels, view.height)}"></div></div>`;
    case 'spectrum':
      return `<div class="${plot} pb-plot-spectrum">${view.controls ? '<div class="pb-plot-bar"></div>' : ''}`
        + `<div class="pb-reserve-stage" style="${stageStyle(SPECTRUM_PLOT, 1, view.height)}"></div>`
        + `<div class="pb-spectrum-readout" style="--pb-readout-lines: ${readoutLines(view.peaks)}"></div></div>`;
  }
}

/**
 * The reserved box: the simulator's frame with its rows and plots, empty,
 * and a word on what is coming. It names the views, so that the page can
 * fetch their modules with the simulator's (catalogue.ts, prefetchWidgets).
 */
export function reserveHtml(plan: SimulatorPlan): string {
  const views = plan.views.map((v) => v.kind).join(' ');
  const spans = spanningViews(plan.views.map((v) => v.kind === 'spectrum'));
  return `<div class="pb-simulator pb-reserve" aria-hidden="true" data-reserve="simulator" data-reserve-views="${views}">`
    + `<div class="pb-bar"><span class="pb-reserve-label">Simulator: starting…</span></div>`
    + `<div class="pb-views">${plan.views.map((v, i) => viewHtml(v, spans[i])).join('')}</div>`
    + `<div class="pb-data"></div></div>`;
}

