/**
 * The book's text fonts, declared here rather than through fontsource's
 * stylesheets so that loading them never moves the page.
 *
 * - `font-display: optional`: a font that is not there by the first layout
 *   (about 100 ms) is not swapped in later for this page view, so text never
 *   reflows under the reader; it is cached for the next page. fontsource's
 *   `swap` moved every line of a chapter when the serif arrived.
 * - The latin subsets of the serif and of the sans (and on chapters, of the
 *   code font, with KaTeX's two most used faces) are preloaded, so that on any reasonable connection they
 *   are there in time. The other subsets load only when a page uses one of
 *   their characters (unicode-range), as before.
 *
 * KaTeX's own stylesheet declares its faces with `font-display: block`; its
 * layout is fixed by the build's typesetting, so a late math font changes
 * glyph shapes within their boxes rather than the lines around them.
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
import katexMain from 'katex/dist/fonts/KaTeX_Main-Regular.woff2?url';
import katexMath from 'katex/dist/fonts/KaTeX_Math-Italic.woff2?url';

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
  range: string;
  /** variable fonts are `woff2-variations` */
  variable: boolean;
}

const SERIF = 'Source Serif 4 Variable';
const SANS = 'Inter Variable';
const MONO = 'JetBrains Mono';

const FACES: readonly Face[] = [
  { family: SERIF, style: 'normal', weight: '200 900', url: serifLatin, range: LATIN, variable: true },
  { family: SERIF, style: 'normal', weight: '200 900', url: serifLatinExt, range: LATIN_EXT, variable: true },
  { family: SERIF, style: 'normal', weight: '200 900', url: serifGreek, range: GREEK, variable: true },
  { family: SERIF, style: 'italic', weight: '200 900', url: serifItalicLatin, range: LATIN, variable: true },
  { family: SERIF, style: 'italic', weight: '200 900', url: serifItalicLatinExt, range: LATIN_EXT, variable: true },
  { family: SERIF, style: 'italic', weight: '200 900', url: serifItalicGreek, range: GREEK, variable: true },
  { family: SANS, style: 'normal', weight: '100 900', url: sansLatin, range: LATIN, variable: true },
  { family: SANS, style: 'normal', weight: '100 900', url: sansLatinExt, range: LATIN_EXT, variable: true },
  { family: SANS, style: 'normal', weight: '100 900', url: sansGreek, range: GREEK, variable: true },
  { family: MONO, style: 'normal', weight: '400', url: monoLatin, range: LATIN, variable: false },
  { family: MONO, style: 'normal', weight: '400', url: monoLatinExt, range: LATIN_EXT, variable: false },
  { family: MONO, style: 'normal', weight: '400', url: monoGreek, range: GREEK, variable: false },
];

/** The @font-face rules, for an inline <style> in the page's head. */
export const fontFaceCss = FACES.map(
  (f) =>
    `@font-face{font-family:'${f.family}';font-style:${f.style};font-weight:${f.weight};font-display:optional;` +
    `src:url(${f.url}) format('${f.variable ? 'woff2-variations' : 'woff2'}');unicode-range:${f.range}}`,
).join('\n');

/** Fonts every page's first view uses: the body text and the headings. */
export const textFonts: readonly string[] = [serifLatin, sansLatin];

/** What a chapter's first view adds: its math and its code cells. */
export const chapterFonts: readonly string[] = [katexMain, katexMath, monoLatin];
