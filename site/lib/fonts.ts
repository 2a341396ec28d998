/**
 * The book's fonts — its text faces and KaTeX's — declared here rather than
 * by fontsource's and KaTeX's stylesheets, so that loading them never delays
 * a widget, text never reflows, and math is never drawn in the wrong face.
 *
 * Text and math are loaded by different rules, because a late font costs
 * them different things:
 *
 * - Text faces are `font-display: optional`: a face that is not there by the
 *   first layout (about 100 ms) is not swapped in later for this page view,
 *   so prose never reflows under the reader; it is cached for the next page.
 *   fontsource's `swap` moved every line of a chapter when a font arrived.
 *   On a slow connection (the browser's estimate is 3G or slower, or the
 *   reader asked to save data) no text face is declared at all: the prose
 *   reads in the system's fonts, and the bandwidth goes to the text, the
 *   math and the widgets. This is decided by a few lines in the head, before
 *   the first paint (fontLoader); without JavaScript the faces are declared
 *   in <noscript>.
 * - KaTeX's faces are `font-display: block`, always declared, on every
 *   connection. KaTeX measures its layout in its own fonts' metrics: in a
 *   system serif a formula is merely ugly, but a stretchy delimiter is built
 *   from KaTeX_Size1–4 glyphs, and without them a matrix such as the
 *   introduction's J = (0 I; −I 0) keeps small, unstretched parentheses.
 *   `optional` let that happen on every fresh visit over Slow 4G (the face
 *   missed its 100 ms), and the slow-connection rule declared no math face
 *   at all. So math waits for its faces, for at most the browser's block
 *   period (3 s), and swaps them in whenever they come after that.
 * - The faces of the first view are preloaded. For every page, the latin
 *   subsets of the serif and the sans (by the script, not on a slow
 *   connection); for a chapter, the code font's (likewise), and by <link>
 *   in the page's head, on every connection, the two math faces every
 *   chapter's first view draws, KaTeX_Main and KaTeX_Math italic (42 KB).
 *   KaTeX_Size3, which the introduction's matrix is built from, is under
 *   Vite's inlining limit and comes as data in the rule itself. The other
 *   faces (Size1, 2 and 4, bold, AMS…) load when a formula uses them:
 *   preloaded on a page that does not draw them, they would take bandwidth
 *   from the first view, and Chromium warns of a preload left unused.
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
/** The URL of one KaTeX font file by its name (`KaTeX_Main-Regular`): a file of the site, or a data: URL for one small enough to inline. */
function katexUrl(name: string): string {
  const entry = Object.entries(KATEX_FILES).find(([path]) => path.endsWith(`/${name}.woff2`));
  if (!entry) throw new Error(`no KaTeX font ${name}`);
  return entry[1];
}

function faceRule(f: Face, display: 'optional' | 'block'): string {
  return `@font-face{font-family:'${f.family}';font-style:${f.style};font-weight:${f.weight};font-display:${display};` +
    `src:url(${f.url}) format('${f.variable ? 'woff2-variations' : 'woff2'}')${f.range ? `;unicode-range:${f.range}` : ''}}`;
}

/** The text faces' @font-face rules: declared by fontLoader, or in <noscript>. */
export const textFaceCss = TEXT_FACES.map((f) => faceRule(f, 'optional')).join('\n');

/** KaTeX's @font-face rules, in every page's head as they are: math never falls back (see the module comment). */
export const mathFaceCss = KATEX_FACES.map((f) => faceRule(f, 'block')).join('\n');

/**
 * The math faces a chapter's first view draws, preloaded by <link> in its head on every connection: the
 * letters, digits and operators (Main) and the variables (Math italic).
 */
export const mathPreloads: readonly string[] = [katexUrl('KaTeX_Main-Regular'), katexUrl('KaTeX_Math-Italic')];

/** Text fonts the first view of every page uses: the body text and the headings. */
const TEXT_PRELOADS = [serifLatin, sansLatin];
/** What a chapter's first view adds: its code. */
const CHAPTER_PRELOADS = [monoLatin];

/**
 * The inline script that declares the text faces and preloads the first view's,
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
  style.textContent = ${JSON.stringify(textFaceCss)};
  document.head.append(style);
})();`;
}
