/**
 * Which files of the built book a chapter needs, and nothing else: its page,
 * then every file that a needed text file (HTML, JS, CSS, JSON) names, and
 * so on until nothing new is named.
 *
 * The book for a package is built under a base path no other text contains,
 * {@link PACKAGE_BASE}, so that every address the build wrote is found by
 * that prefix. Two kinds of name are followed:
 *
 * - `<base>path`, for any file of the build (fonts in the inline styles,
 *   scripts in the page, workers in the chunks);
 * - a file of `_astro/` by its own name, without the prefix: Vite writes
 *   chunk imports as `./name.js` and its preload list as `_astro/name.js`.
 *   Every name there carries a hash of its content, so a name found in a
 *   text means that file.
 */

/** The base path the book is built under for packages: an address no text of the book has otherwise. */
export const PACKAGE_BASE = '/phasebook-scorm-package-root/';

/** Vite's output folder, where every file's name carries its content's hash. */
const HASHED = '_astro/';

const TEXT = /\.(html|js|mjs|css|json|svg|webmanifest)$/;

export interface BuiltSite {
  /** Every file of the build, as paths relative to its root (`introduction/index.html`). */
  readonly paths: readonly string[];
  read(path: string): Uint8Array;
}

export function isText(path: string): boolean {
  return TEXT.test(path);
}

/** The page of a chapter in the build. */
export function chapterPage(slug: string): string {
  return `${slug}/index.html`;
}

/** The paths of `site` that `text` names, as {@link PACKAGE_BASE} paths or (for `_astro/`) by their file names. */
export function namedFiles(text: string, site: readonly string[]): string[] {
  return site.filter((path) => {
    if (text.includes(PACKAGE_BASE + path)) return true;
    return path.startsWith(HASHED) && !path.slice(HASHED.length).includes('/') && text.includes(path.slice(HASHED.length));
  });
}

/** The files the chapter `slug` needs, its page first; throws if the build has no such page. */
export function chapterFiles(site: BuiltSite, slug: string): string[] {
  const page = chapterPage(slug);
  if (!site.paths.includes(page)) throw new Error(`the build has no chapter “${slug}” (no ${page})`);
  const needed = new Set([page]);
  const decoder = new TextDecoder();
  for (const path of needed) {
    if (!isText(path)) continue;
    for (const named of namedFiles(decoder.decode(site.read(path)), site.paths)) needed.add(named);
  }
  return [...needed];
}
