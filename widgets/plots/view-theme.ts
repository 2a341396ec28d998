import { resolveTheme } from './colors.ts';

/**
 * The colours a plane or spectrum plot draws with, from the page's custom
 * properties: --text (or --fg), --bg, --muted, --accent, each with a
 * fallback so a bare page still reads. The site writes them as
 * light-dark() pairs, which a canvas cannot parse, so each goes through a
 * probe element and arrives as the rgb() the theme currently resolves to.
 * Series colours are the time plot's palette (colors.ts, overridable with
 * --pb-series-1 … 8), so one series looks the same in every plot.
 */
export interface Theme {
  fg: string;
  bg: string;
  muted: string;
  accent: string;
  /** series colours, as colors.ts's palette */
  series: readonly string[];
  font: string;
  dark: boolean;
}

const FALLBACK = { fg: '#1d1c1a', bg: '#fbfaf6', muted: '#5e5b55', accent: '#1c5aa6' };

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
  const bg = color(`var(--bg, ${FALLBACK.bg})`, FALLBACK.bg);
  const theme = {
    fg: color(`var(--text, var(--fg, ${FALLBACK.fg}))`, FALLBACK.fg),
    bg,
    muted: color(`var(--muted, ${FALLBACK.muted})`, FALLBACK.muted),
    accent: color(`var(--accent, ${FALLBACK.accent})`, FALLBACK.accent),
    series: resolveTheme(el).series,
    font: getComputedStyle(el).getPropertyValue('--sans').trim() || 'system-ui, -apple-system, "Segoe UI", sans-serif',
    dark: luminance(bg) < 0.2,
  };
  probe.remove();
  return theme;
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
  return a.fg === b.fg && a.bg === b.bg && a.muted === b.muted && a.accent === b.accent && a.series.join() === b.series.join();
}

/** Colour i of the series palette, cycling. */
export function seriesColor(theme: Theme, i: number): string {
  return theme.series[i % theme.series.length];
}
