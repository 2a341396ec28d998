/**
 * Plot axes as drawn, read through each plot element's `axes` property (the
 * labels as drawn: text, position and measured width in CSS px, and the font
 * size), and what makes them hard to read: used by plots-read.test.mjs and by
 * the sweep of every page (every-page.mjs).
 */

export const PLOTS = '[data-widget="time-plot"], [data-widget="phase-portrait"], [data-widget="trajectory"], [data-widget="spectrum"]';

/** Every plot in `root` (a selector) with its axes as drawn. */
export async function plotAxes(page, root) {
  return page.evaluate(
    ([root, selector]) =>
      [...document.querySelectorAll(root)].flatMap((r) =>
        [...r.querySelectorAll(selector)].map((el) => ({ kind: el.dataset.widget, axes: JSON.parse(JSON.stringify(el.axes ?? [])) })),
      ),
    [root, PLOTS],
  );
}

/**
 * Problems with one axis as drawn: labels closer than their widths (x) or
 * their height (y), y labels wider than the room beside the plot, text
 * under 11 px, or labels written out to more than 10 characters.
 */
export function axisProblems(name, axis, along) {
  const out = [];
  if (axis.font < 11) out.push(`${name}: ${axis.font} px text`);
  const labels = [...axis.labels].sort((a, b) => a.at - b.at);
  for (let i = 1; i < labels.length; i++) {
    const gap = labels[i].at - labels[i - 1].at;
    const needed = along === 'x' ? (labels[i].width + labels[i - 1].width) / 2 + 2 : axis.font;
    if (gap < needed) out.push(`${name}: “${labels[i - 1].text}” and “${labels[i].text}” ${gap.toFixed(1)} px apart, need ${needed.toFixed(1)}`);
  }
  for (const l of labels) {
    if (along === 'y' && axis.room !== undefined && l.width > axis.room + 0.5) out.push(`${name}: “${l.text}” is ${l.width.toFixed(1)} px wide, room ${axis.room}`);
    if (l.text.length > 10) out.push(`${name}: “${l.text}” is long`);
  }
  if (labels.length < 2) out.push(`${name}: ${labels.length} labels`);
  return out;
}

export function plotProblems(plots) {
  return plots.flatMap((p, i) => p.axes.flatMap((a, j) => [...axisProblems(`${p.kind} ${i}.${j} x`, a.x, 'x'), ...axisProblems(`${p.kind} ${i}.${j} y`, a.y, 'y')]));
}
