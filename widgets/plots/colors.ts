/**
 * Series colours and theme colours for canvas drawing. Canvas cannot use CSS
 * variables directly, so plots resolve them from computed style and redraw
 * when the theme changes (watchTheme).
 *
 * The palette is of medium lightness (each colour has a contrast ratio of at
 * least 3.2 against both white and #111, by the WCAG formula), so one set reads in light and dark
 * themes; a theme may override any entry with --pb-series-1 … --pb-series-8.
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

/** The palette colour of series i, cycling. */
export function seriesColor(i: number): string {
  return PALETTE[((i % PALETTE.length) + PALETTE.length) % PALETTE.length];
}

/** Colours a plot draws with, resolved against the element's theme. */
export interface Theme {
  /** tick labels and axis titles */
  text: string;
  /** axis lines and ticks */
  axis: string;
  /** grid lines */
  grid: string;
  /** the plot's background, used when a PNG must be opaque */
  background: string;
  series: string[];
  font: string;
}

/**
 * Reads the theme from computed style. Colours go through a probe element so
 * that whatever the site writes (var(), light-dark(), color-mix()) arrives
 * as a plain rgb() string the canvas understands; custom properties fall back
 * to the values above.
 */
export function resolveTheme(element: Element): Theme {
  const style = getComputedStyle(element);
  const probe = document.createElement('span');
  probe.style.display = 'none';
  element.append(probe);
  const color = (value: string, fallback: string): string => {
    probe.style.color = fallback;
    probe.style.color = value;
    return getComputedStyle(probe).color || fallback;
  };
  const text = color('var(--muted, var(--text, var(--fg)))', '#6b7280');
  const theme: Theme = {
    text,
    axis: color(`var(--pb-axis, ${text})`, text),
    grid: color('var(--pb-grid, var(--rule, rgba(128, 128, 128, 0.25)))', 'rgba(128, 128, 128, 0.25)'),
    background: color(`var(--bg, ${opaqueBackground(element)})`, '#ffffff'),
    series: PALETTE.map((c, i) => color(`var(--pb-series-${i + 1}, ${c})`, c)),
    font: `11px ${style.getPropertyValue('--pb-plot-font').trim() || style.fontFamily || 'system-ui, sans-serif'}`,
  };
  probe.remove();
  return theme;
}

/** The first non-transparent background colour up the tree, or white. */
function opaqueBackground(element: Element): string {
  for (let e: Element | null = element; e; e = e.parentElement) {
    const bg = getComputedStyle(e).backgroundColor;
    if (bg && bg !== 'transparent' && !/rgba\(.*,\s*0\)$/.test(bg)) return bg;
  }
  return '#ffffff';
}

/**
 * Calls `onChange` when the page theme may have changed: the OS colour scheme,
 * or a class / data attribute on <html> or <body>. Returns the unsubscribe.
 */
export function watchTheme(onChange: () => void): () => void {
  if (typeof window === 'undefined') return () => {};
  const media = window.matchMedia?.('(prefers-color-scheme: dark)');
  media?.addEventListener('change', onChange);
  const observer = new MutationObserver(onChange);
  const options = { attributes: true, attributeFilter: ['class', 'data-theme', 'style'] };
  observer.observe(document.documentElement, options);
  if (document.body) observer.observe(document.body, options);
  return () => {
    media?.removeEventListener('change', onChange);
    observer.disconnect();
  };
}
