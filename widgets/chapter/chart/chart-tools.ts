/**
 * The tools under a chart: its buttons, and the data-table view that shows
 * the numbers drawn to a reader who cannot see the canvas, or who wants
 * them.
 */
import { namedCurves, tableRows, TABLE_ROWS } from './chart-data.ts';
import type { SettledChart } from './chart-scale.ts';
import { table } from '../table/table.ts';

/** A button of the tools row, its tooltip saying what it does. */
export function button(text: string, title: string, onClick: () => void): HTMLButtonElement {
  const b = document.createElement('button');
  b.type = 'button';
  b.className = 'pb-chart-button';
  b.textContent = text;
  b.title = title;
  b.addEventListener('click', onClick);
  return b;
}

/**
 * The data-table view: a table per curve, built when the reader opens it
 * from the chart as it is then (`current`). `stale()` says the chart
 * changed: an open view is built again, at most once a second, so that a
 * chart updated on every frame does not rebuild its tables on every frame.
 */
export function dataView(current: () => SettledChart): { element: HTMLDetailsElement; stale: () => void } {
  const details = document.createElement('details');
  details.className = 'pb-chart-data';
  const summary = document.createElement('summary');
  summary.textContent = 'Data table';
  details.append(summary);
  let builtAt = -Infinity;
  let later: ReturnType<typeof setTimeout> | undefined;
  const build = () => {
    later = undefined;
    builtAt = performance.now();
    details.dataset.built = '';
    details.replaceChildren(summary);
    appendCurveTables(details, current());
  };
  details.addEventListener('toggle', () => {
    if (details.open && details.dataset.built === undefined) build();
  });
  const stale = () => {
    if (details.dataset.built === undefined) return;
    if (!details.open) {
      delete details.dataset.built;
      return;
    }
    later ??= setTimeout(build, Math.max(0, builtAt + 1000 - performance.now()));
  };
  return { element: details, stale };
}

/** A table per curve of the chart, captioned with its name, after the view's summary. */
function appendCurveTables(details: HTMLDetailsElement, chart: SettledChart): void {
  const curves = chart.series.flatMap((s, i) => namedCurves(s, i));
  // Many curves (a beam of trajectories) get fewer rows each; the CSV has every point.
  const limit = Math.max(20, Math.min(TABLE_ROWS, Math.floor(4000 / Math.max(1, curves.length))));
  for (const { name, curve } of curves) {
    const { rows, omitted } = tableRows(curve, limit);
    const note = omitted ? `: ${rows.length} of ${curve.x.length} points, evenly spaced (the CSV has all)` : '';
    details.append(table({ caption: `${name}${note}`, columns: [chart.x.label, chart.y.label], rows }));
  }
}
