/**
 * The book's fonts — its text faces and KaTeX's — declared here rather than
 * by fontsource's and KaTeX's stylesheets, so that loading them never moves
 * the page and never delays a widget.
 *
 * - `font-display: optional`: a font that is not there by the first layout
 *   (about 100 ms) is not swapped in later for this page view, so text and
 *   math never reflow under the reader; it is cached for the next page.
 *   fontsource's `swap` and KaTeX's `block` moved every line of a chapter
 *   when a font arrived.
 * - The faces of the first view are preloaded: the latin subsets of the
 *   serif and the sans, and on chapters those of the code font and KaTeX's
 *   two most used faces. The rest load when a page uses them
 *   (unicode-range, KaTeX's own classes).
 * - On a slow connection (the browser's estimate is 3G or slower, or the
 *   reader asked to save data) no font is declared at all: the page reads in
 *   the system's fonts, and the bandwidth goes to the text and the widgets,
 *   where a font that would arrive too late to be used would have taken it.
 *   This is decided by a few lines in the head, before the first paint
 *   (fontLoader); without JavaScript the fonts are declared in <noscript>.
 *
 * KaTeX's @font-face rules are taken out of its stylesheet by the build
 * (astro.config.mjs) and declared here instead, with the same families.
 */
import serifLatin from '@fontsource-variable/source-serif-4/files/source-serif-4-latin-wght-normal.woff2?url';
import serifLatinExt from '@fontsource-variable/source-serif-4/files/source-serif-4-latin-ext-wght-normal.woff2?url';
import serifGreek from '@fontsource-variable/source-serif-4/files/source-serif-4-greek-wght-normal.woff2?url';
import serifItalicLatin from '@fontsource-variable/source-serif-4/files/source-serif-4-latin-wght-italic.woff2?url';
import serifItalicLatinExt from '@fontsource-variable/source-serif-4/files/source-serif-4-latin-ext-wght-italic.woff2?url';
import serifItalicGreek from '@fontsource-variable/source-serif-4/files/source-serif-4-greek-wght-italic.woff2?url';
import sansLatin from '@fontsource-variable/inter/files/inter-latin-wght-normal.woff2?url';
import sansLatinExt from '@fontsource-variable/inter/files/inter-latin-ext-wght-normal.woff2?url';
import sansGreek from '@fontsource-variable/inter/files/inter-greek-wght-normal.woff2?url';
import monoLatin from '@fontsource/jetbrains-mono/files/jetbrains-mono-latin-400-normal.woff2?url';
import monoLatinExt from '@fontsource/jetbrains-mono/files/jetbrains-mono-latin-ext-400-normal.woff2?url';
import monoGreek from '@fontsource/jetbrains-mono/files/jetbrains-mono-greek-400-normal.woff2?url';

/** The Unicode ranges of fontsource's subsets (Google Fonts' slicing). */
const LATIN =
  'U+0000-00FF,U+0131,U+0152-0153,U+02BB-02BC,U+02C6,U+02DA,U+02DC,U+0304,U+0308,U+0329,U+2000-206F,U+20AC,U+2122,U+2191,U+2193,U+2212,U+2215,U+FEFF,U+FFFD';
const LATIN_EXT =
  'U+0100-02BA,U+02BD-02C5,U+02C7-02CC,U+02CE-02D7,U+02DD-02FF,U+0304,U+0308,U+0329,U+1D00-1DBF,U+1E00-1E9F,U+1EF2-1EFF,U+2020,U+20A0-20AB,U+20AD-20C0,U+2113,U+2C60-2C7F,U+A720-A7FF';
const GREEK = 'U+0370-0377,U+037A-037F,U+0384-038A,U+038C,U+038E-03A1,U+03A3-03FF';

interface Face {
  family: string;
  style: 'normal' | 'italic';
  weight: string;
  url: string;
  range?: string;
  /** variable fonts are `woff2-variations` */
  variable?: boolean;
}

const SERIF = 'Source Serif 4 Variable';
const SANS = 'Inter Variable';
const MONO = 'JetBrains Mono';

const TEXT_FACES: readonly Face[] = [
  { family: SERIF, style: 'normal', weight: '200 900', url: serifLatin, range: LATIN, variable: true },
  { family: SERIF, style: 'normal', weight: '200 900', url: serifLatinExt, range: LATIN_EXT, variable: true },
  { family: SERIF, style: 'normal', weight: '200 900', url: serifGreek, range: GREEK, variable: true },
  { family: SERIF, style: 'italic', weight: '200 900', url: serifItalicLatin, range: LATIN, variable: true },
  { family: SERIF, style: 'italic', weight: '200 900', url: serifItalicLatinExt, range: LATIN_EXT, variable: true },
  { family: SERIF, style: 'italic', weight: '200 900', url: serifItalicGreek, range: GREEK, variable: true },
  { family: SANS, style: 'normal', weight: '100 900', url: sansLatin, range: LATIN, variable: true },
  { family: SANS, style: 'normal', weight: '100 900', url: sansLatinExt, range: LATIN_EXT, variable: true },
  { family: SANS, style: 'normal', weight: '100 900', url: sansGreek, range: GREEK, variable: true },
  { family: MONO, style: 'normal', weight: '400', url: monoLatin, range: LATIN },
  { family: MONO, style: 'normal', weight: '400', url: monoLatinExt, range: LATIN_EXT },
  { family: MONO, style: 'normal', weight: '400', url: monoGreek, range: GREEK },
];

/** KaTeX's woff2 files by path; each name says its face, e.g. KaTeX_Main-BoldItalic.woff2. */
const KATEX_FILES = import.meta.glob<string>('../../node_modules/katex/dist/fonts/*.woff2', { query: '?url', import: 'default', eager: true });

/** KaTeX's faces as its stylesheet declares them: the family before the dash, bold 700, italic. */
export function katexFace(path: string, url: string): Face {
  const match = /(KaTeX_\w+)-(Regular|Bold|Italic|BoldItalic)\.woff2$/.exec(path);
  if (!match) throw new Error(`not a KaTeX font file: ${path}`);
  const [, family, variant] = match;
  return { family, style: variant.endsWith('Italic') ? 'italic' : 'normal', weight: variant.startsWith('Bold') ? '700' : '400', url };
}

const KATEX_FACES = Object.entries(KATEX_FILES).map(([path, url]) => katexFace(path, url));
if (KATEX_FACES.length < 20) throw new Error(`found ${KATEX_FACES.length} KaTeX fonts, expected 20: has katex moved its fonts?`);
const katexUrl = (name: string) => KATEX_FACES.find((f) => f.url.includes(`/${name}.`))?.url ?? '';

function faceRule(f: Face): string {
  return `@font-face{font-family:'${f.family}';font-style:${f.style};font-weight:${f.weight};font-display:optional;` +
    `src:url(${f.url}) format('${f.variable ? 'woff2-variations' : 'woff2'}')${f.range ? `;unicode-range:${f.range}` : ''}}`;
}

/** Every @font-face rule of the book. */
export const fontFaceCss = [...TEXT_FACES, ...KATEX_FACES].map(faceRule).join('\n');

/** Fonts the first view of every page uses: the body text and the headings. */
const TEXT_PRELOADS = [serifLatin, sansLatin];
/** What a chapter's first view adds: its code and its math. */
const CHAPTER_PRELOADS = [monoLatin, katexUrl('KaTeX_Main-Regular'), katexUrl('KaTeX_Math-Italic')];

/**
 * The inline script that declares the fonts and preloads the first view's,
 * unless the connection is slow (see the module comment).
 */
export function fontLoader(chapter: boolean): string {
  const preloads = chapter ? [...TEXT_PRELOADS, ...CHAPTER_PRELOADS] : TEXT_PRELOADS;
  return `(() => {
  const c = navigator.connection;
  if (c && (c.saveData || /^(slow-2g|2g|3g)$/.test(c.effectiveType))) return;
  for (const href of ${JSON.stringify(preloads)}) {
    const link = document.createElement('link');
    Object.assign(link, { rel: 'preload', as: 'font', type: 'font/woff2', href, crossOrigin: 'anonymous' });
    document.head.append(link);
  }
  const style = document.createElement('style');
  style.textContent = ${JSON.stringify(fontFaceCss)};
  document.head.append(style);
})();`;
}
