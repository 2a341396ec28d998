import type { Track } from '../record-columns.ts';
import { makeMapping, transform, type Mapping, type SignedKind } from '../scale.ts';
import { MARGIN, type Rect } from '../axes.ts';
import { contains, emptyExtent, fitEqualAspect, growExtent, includePoint, isEmpty, stretchGrowth, union, type Extent } from '../extent.ts';
import { gridColumns } from '../sizes.ts';
import { makePens, type Pens } from '../trace.ts';

/** What a caller asks of one panel of a plane plot (a trajectory, or one phase portrait). */
export interface PanelSpec {
  tracks: readonly Track[];
  xLabel: string;
  yLabel: string;
  /** legend entries, one per colour group shown */
  legend: readonly { label: string; group: number }[];
  title?: string;
  xKind: SignedKind;
  yKind: SignedKind;
  /** symlog constant c: the axis is linear within about ±c */
  constant: number;
  /** one data unit as long across as up */
  equal: boolean;
  /** a fixed extent; otherwise the extent grows to fit the data */
  extent?: Extent;
  /** the largest extent growth may reach */
  limit?: Extent;
}

/** A panel's drawing state: its tracks grouped by colour, pens, extent and the mappings derived from it. */
export interface Panel {
  readonly spec: PanelSpec;
  /** track columns ordered by group; track k's pen is slot k */
  readonly xs: Int32Array;
  readonly ys: Int32Array;
  /** group g's tracks are k in [starts[i], starts[i + 1]) where groups[i] = g */
  readonly groups: readonly number[];
  readonly starts: readonly number[];
  readonly pens: Pens;
  /** every sample seen so far, unpadded (auto extents grow from this, so padding does not compound) */
  readonly data: Extent;
  /** the padded data extent (auto) or the fixed one */
  fitted: Extent;
  /** what is shown: `fitted` after the equal-aspect fit */
  shown: Extent;
  rect: Rect;
  mx: Mapping;
  my: Mapping;
  /** scratch for the extent of each frame's new samples */
  readonly fresh: Extent;
}

/** Fraction of the data span added on each side when an auto extent grows. */
export const HEADROOM = 0.08;
/** An auto extent that must grow grows at least this much on the axis that grew. */
export const GROWTH = 1.4;

export function makePanel(spec: PanelSpec): Panel {
  const ordered = [...spec.tracks].sort((a, b) => a.group - b.group);
  const groups: number[] = [];
  const starts: number[] = [];
  ordered.forEach((t, k) => {
    if (groups[groups.length - 1] !== t.group) {
      groups.push(t.group);
      starts.push(k);
    }
  });
  starts.push(ordered.length);
  const rect = { left: 0, top: 0, width: 1, height: 1 };
  const identity = makeMapping('linear', [0, 1], [0, 1]);
  return {
    spec,
    xs: Int32Array.from(ordered, (t) => t.x),
    ys: Int32Array.from(ordered, (t) => t.y),
    groups,
    starts,
    pens: makePens(ordered.length),
    data: emptyExtent(),
    fitted: spec.extent ? { ...spec.extent } : emptyExtent(),
    shown: { x0: 0, x1: 1, y0: 0, y1: 1 },
    rect,
    mx: identity,
    my: identity,
    fresh: emptyExtent(),
  };
}

/** The plotting rectangle of panel i of `count` in a width × height canvas; `margin` is its left margin (wide y labels need more). */
export function panelRect(i: number, count: number, width: number, height: number, margin = MARGIN.left): Rect {
  const columns = gridColumns(count, width);
  const rows = Math.ceil(count / columns);
  const cellWidth = width / columns;
  const cellHeight = height / rows;
  const left = (i % columns) * cellWidth + margin;
  const top = Math.floor(i / columns) * cellHeight + MARGIN.top;
  return {
    left,
    top,
    width: Math.max(10, cellWidth - margin - MARGIN.right),
    height: Math.max(10, cellHeight - MARGIN.top - MARGIN.bottom),
  };
}

/** Clamps `e` in place to `limit`. */
function clampTo(e: Extent, limit: Extent): void {
  e.x0 = Math.max(e.x0, limit.x0);
  e.x1 = Math.min(e.x1, limit.x1);
  e.y0 = Math.max(e.y0, limit.y0);
  e.y1 = Math.min(e.y1, limit.y1);
}

/**
 * Adds `panel.fresh` (the new samples' extent) to the panel's data extent and
 * regrows an auto extent when the new samples are not all shown; returns
 * whether it grew, in which case the panel must be placed again and redrawn.
 */
export function growPanel(panel: Panel): boolean {
  const { spec, fresh, data } = panel;
  if (spec.extent || isEmpty(fresh)) return false;
  if (spec.limit) clampTo(fresh, spec.limit);
  includePoint(data, fresh.x0, fresh.y0);
  includePoint(data, fresh.x1, fresh.y1);
  // `fitted` too: the aspect fit of `shown` can round a hair inside it.
  if (!isEmpty(panel.fitted) && (contains(panel.shown, fresh) || contains(panel.fitted, fresh))) return false;
  // the padded data, never less than before (what is drawn stays in view), then stretched on the side that grew
  const grown = union(panel.fitted, growExtent(data, data, HEADROOM, spec.xKind, spec.yKind, spec.constant));
  panel.fitted = stretchGrowth(panel.fitted, grown, GROWTH, spec.xKind, spec.yKind, spec.constant);
  if (spec.limit) clampTo(panel.fitted, spec.limit);
  return true;
}

/**
 * Tightens an auto extent that growth left much larger than its data (by
 * more than a fifth of its span on an axis); returns whether it did.
 */
export function settlePanel(panel: Panel): boolean {
  const { spec, data, fitted } = panel;
  if (spec.extent || isEmpty(data) || isEmpty(fitted)) return false;
  const tight = growExtent(data, data, HEADROOM, spec.xKind, spec.yKind, spec.constant);
  if (spec.limit) clampTo(tight, spec.limit);
  const span = (kind: SignedKind, lo: number, hi: number) => transform(kind, hi, spec.constant) - transform(kind, lo, spec.constant);
  const loose =
    span(spec.xKind, tight.x0, tight.x1) < 0.8 * span(spec.xKind, fitted.x0, fitted.x1) ||
    span(spec.yKind, tight.y0, tight.y1) < 0.8 * span(spec.yKind, fitted.y0, fitted.y1);
  if (loose) panel.fitted = tight;
  return loose;
}

/** Sets the panel's rectangle, shown extent and mappings for the current fitted extent. */
export function placePanel(panel: Panel, rect: Rect): void {
  const { spec } = panel;
  const data = isEmpty(panel.fitted) ? { x0: -1, x1: 1, y0: -1, y1: 1 } : panel.fitted;
  const linear = spec.xKind === 'linear' && spec.yKind === 'linear';
  const shown = spec.equal && linear ? fitEqualAspect(data, rect.width, rect.height) : { ...data };
  panel.rect = rect;
  panel.shown = shown;
  panel.mx = makeMapping(spec.xKind, [shown.x0, shown.x1], [rect.left, rect.left + rect.width], spec.constant);
  panel.my = makeMapping(spec.yKind, [shown.y0, shown.y1], [rect.top + rect.height, rect.top], spec.constant);
}
