/**
 * The colours a canvas plot draws with, read from the page's CSS custom
 * properties (--fg, --bg, --muted, --accent, and optionally --series-2 …
 * --series-8) so that plots follow the light and dark themes. Canvas pixels
 * do not restyle themselves, so a view re-reads the theme and redraws when
 * it changes.
 */
export interface Theme {
  fg: string;
  bg: string;
  muted: string;
  accent: string;
  /** series colours, accent first */
  series: readonly string[];
  font: string;
  dark: boolean;
}

const LIGHT = {
  fg: '#1b1d21',
  bg: '#ffffff',
  muted: '#6b7280',
  accent: '#2563eb',
  series: ['#d9480f', '#2b8a3e', '#862e9c', '#0b7285', '#c2255c', '#b35c00', '#5c940d'],
};

const DARK = {
  fg: '#e6e7ea',
  bg: '#16181c',
  muted: '#9aa0a8',
  accent: '#74a7ff',
  series: ['#ff922b', '#69db7c', '#da77f2', '#3bc9db', '#f783ac', '#ffd43b', '#a9e34b'],
};

let probe: CanvasRenderingContext2D | null = null;

/** Relative luminance of a CSS colour (0 black … 1 white), via a canvas that normalises any syntax to #rrggbb. */
export function luminance(color: string): number {
  probe ??= document.createElement('canvas').getContext('2d');
  if (!probe) return 1;
  probe.fillStyle = '#000';
  probe.fillStyle = color;
  const hex = /^#([0-9a-f]{6})$/i.exec(String(probe.fillStyle));
  const channels = hex ? [0, 2, 4].map((i) => parseInt(hex[1].slice(i, i + 2), 16) / 255) : rgbChannels(String(probe.fillStyle));
  const [r, g, b] = channels.map((v) => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4));
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

function rgbChannels(css: string): number[] {
  const m = /rgba?\(([^)]+)\)/.exec(css);
  if (!m) return [1, 1, 1];
  const [r, g, b, a = '1'] = m[1].split(',').map((s) => s.trim());
  return Number(a) === 0 ? [1, 1, 1] : [r, g, b].map((v) => Number(v) / 255);
}

/** The first non-transparent background colour at or above `el`. */
function backgroundOf(el: Element): string | undefined {
  for (let e: Element | null = el; e; e = e.parentElement) {
    const bg = getComputedStyle(e).backgroundColor;
    if (bg && bg !== 'transparent' && !/rgba\([^)]*,\s*0\)$/.test(bg)) return bg;
  }
  return undefined;
}

/** Reads the theme in effect at `el` (which should be in the document for the page's values to apply). */
export function readTheme(el: Element): Theme {
  const style = getComputedStyle(el);
  const read = (name: string): string | undefined => style.getPropertyValue(name).trim() || undefined;
  const bgGuess = read('--bg') ?? (el.isConnected ? backgroundOf(el) : undefined);
  const prefersDark = typeof matchMedia === 'function' && matchMedia('(prefers-color-scheme: dark)').matches;
  const dark = bgGuess ? luminance(bgGuess) < 0.2 : prefersDark;
  const base = dark ? DARK : LIGHT;
  const series = base.series.map((c, i) => read(`--series-${i + 2}`) ?? c);
  return {
    fg: read('--fg') ?? (el.isConnected && style.color ? style.color : base.fg),
    bg: bgGuess ?? base.bg,
    muted: read('--muted') ?? base.muted,
    accent: read('--accent') ?? base.accent,
    series: [read('--accent') ?? base.accent, ...series],
    font: read('--font-sans') ?? 'system-ui, -apple-system, "Segoe UI", sans-serif',
    dark,
  };
}

export function sameTheme(a: Theme, b: Theme): boolean {
  return a.fg === b.fg && a.bg === b.bg && a.muted === b.muted && a.accent === b.accent && a.series.join() === b.series.join();
}

/** Colour i of the series palette, cycling. */
export function seriesColor(theme: Theme, i: number): string {
  return theme.series[i % theme.series.length];
}
