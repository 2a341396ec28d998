/**
 * The colours and font every plot draws with, read from the page's custom
 * properties. A canvas cannot use CSS variables, and the site writes its
 * colours as light-dark() pairs that a canvas cannot parse either, so each
 * goes through a probe element and arrives as the rgb() the theme currently
 * resolves to; plots read the theme again and redraw when it changes
 * (watchTheme).
 *
 * The series palette is of medium lightness (each colour has a contrast
 * ratio of at least 3.2 against both white and #111, by the WCAG formula),
 * so one set reads in light and dark themes; a theme may override any entry
 * with --pb-series-1 … --pb-series-8. One series looks the same in every plot.
 */
export const PALETTE: readonly string[] = [
  '#2f7de1', // blue
  '#e8590c', // orange
  '#0f9e8e', // teal
  '#d6336c', // raspberry
  '#7c5cf0', // violet
  '#b8860b', // ochre
  '#2f9e44', // green
  '#708090', // slate
];

export interface Theme {
  /** titles and legend text */
  fg: string;
  /** the plot's background, used when a PNG must be opaque */
  bg: string;
  /** tick labels, frames and grid lines */
  muted: string;
  /** the highlighted series (a launched orbit, a spectrum's magnitude) */
  accent: string;
  /** axis lines and ticks (--pb-axis, else muted) */
  axis: string;
  /** grid lines (--pb-grid, else the page's rule colour) */
  grid: string;
  series: readonly string[];
  /** the font family; sizes are the plot's own (axes.ts fontOf) */
  font: string;
  dark: boolean;
}

const FALLBACK = { fg: '#1d1c1a', bg: '#fbfaf6', muted: '#5e5b55', accent: '#1c5aa6', grid: 'rgba(128, 128, 128, 0.25)' };

/** Reads the theme in effect at `el` (which should be in the document for the page's values to apply). */
export function readTheme(el: Element): Theme {
  const probe = document.createElement('span');
  probe.style.display = 'none';
  el.append(probe);
  const color = (value: string, fallback: string): string => {
    probe.style.color = fallback;
    probe.style.color = value;
    return getComputedStyle(probe).color || fallback;
  };
  const bg = color(`var(--bg, ${opaqueBackground(el)})`, FALLBACK.bg);
  const muted = color(`var(--muted, ${FALLBACK.muted})`, FALLBACK.muted);
  const style = getComputedStyle(el);
  const theme: Theme = {
    fg: color(`var(--text, var(--fg, ${FALLBACK.fg}))`, FALLBACK.fg),
    bg,
    muted,
    accent: color(`var(--accent, ${FALLBACK.accent})`, FALLBACK.accent),
    axis: color(`var(--pb-axis, ${muted})`, muted),
    grid: color(`var(--pb-grid, var(--rule, ${FALLBACK.grid}))`, FALLBACK.grid),
    series: PALETTE.map((c, i) => color(`var(--pb-series-${i + 1}, ${c})`, c)),
    font: style.getPropertyValue('--pb-plot-font').trim() || style.getPropertyValue('--sans').trim() || 'system-ui, -apple-system, "Segoe UI", sans-serif',
    dark: luminance(bg) < 0.2,
  };
  probe.remove();
  return theme;
}

/** The first non-transparent background colour up the tree, or the light theme's paper. */
function opaqueBackground(element: Element): string {
  for (let e: Element | null = element; e; e = e.parentElement) {
    const bg = getComputedStyle(e).backgroundColor;
    if (bg && bg !== 'transparent' && !/rgba\(.*,\s*0\)$/.test(bg)) return bg;
  }
  return FALLBACK.bg;
}

/** Relative luminance (0 black … 1 white) of a computed rgb()/rgba() colour; transparent counts as white. */
export function luminance(rgb: string): number {
  const m = /rgba?\(([^)]+)\)/.exec(rgb);
  if (!m) return 1;
  const [r, g, b, a = '1'] = m[1].split(/[\s,/]+/).filter(Boolean);
  if (Number(a) === 0) return 1;
  const [lr, lg, lb] = [r, g, b].map((v) => {
    const c = Number(v) / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  });
  return 0.2126 * lr + 0.7152 * lg + 0.0722 * lb;
}

export function sameTheme(a: Theme, b: Theme): boolean {
  return (
    a.fg === b.fg && a.bg === b.bg && a.muted === b.muted && a.accent === b.accent && a.axis === b.axis && a.grid === b.grid && a.font === b.font && a.series.join() === b.series.join()
  );
}

/** Colour i of the theme's series palette, cycling (negative i from the end). */
export function seriesColor(theme: Pick<Theme, 'series'>, i: number): string {
  const n = theme.series.length;
  return theme.series[((i % n) + n) % n];
}

/**
 * Calls `onChange` when the page theme may have changed: the OS colour scheme,
 * or a class / data attribute on <html> or <body>. Returns the unsubscribe.
 */
export function watchTheme(onChange: () => void): () => void {
  if (typeof window === 'undefined') return () => {};
  const media = window.matchMedia?.('(prefers-color-scheme: dark)');
  media?.addEventListener?.('change', onChange);
  const observer = new MutationObserver(onChange);
  const options = { attributes: true, attributeFilter: ['class', 'data-theme', 'style'] };
  observer.observe(document.documentElement, options);
  if (document.body) observer.observe(document.body, options);
  return () => {
    media?.removeEventListener?.('change', onChange);
    observer.disconnect();
  };
}
