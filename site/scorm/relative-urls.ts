/**
 * A chapter's files made to work from wherever an LMS serves its package.
 *
 * An LMS unpacks a package under a path of its choosing
 * (`/pluginfile.php/71/mod_scorm/content/3/`), so no address may start at
 * the host's root. The book for packages is built under {@link PACKAGE_BASE}
 * (chapter-files.ts), and every address the build wrote starts with it; here
 * each becomes relative to the package's root, `../` from a file one folder
 * down. The page is `<slug>/index.html` and the scripts are in `_astro/`,
 * both one folder down, so one prefix is right for both readings a script's
 * address gets: against the page (a preload, a fetch) and against the
 * script itself (`new URL(…, import.meta.url)`, a worker). A script
 * elsewhere would read it two ways, so it is refused rather than guessed.
 *
 * The page itself loses what only the whole book can serve (the search box,
 * whose index spans every chapter), its links to other pages point to the
 * published book or, without one, are kept as text, and its
 * Content-Security-Policy is given the hashes of its inline scripts as they
 * now read.
 */
import { scriptHash } from '../lib/csp.ts';
import { PACKAGE_BASE } from './chapter-files.ts';

/** How many folders down from the package's root a path is (`introduction/index.html`: 1). */
export function depthOf(path: string): number {
  return path.split('/').length - 1;
}

/** `text` of the file at `path` with every address under the package base made relative to that file's folder. */
export function relativeUrls(text: string, path: string, pageDepth: number): string {
  if (!text.includes(PACKAGE_BASE)) return text;
  const depth = depthOf(path);
  if (/\.m?js$/.test(path) && depth !== pageDepth) {
    throw new Error(`${path} holds addresses of the book but is not as deep as the page: they would resolve one way against the page and another against the script`);
  }
  return text.replaceAll(PACKAGE_BASE, depth === 0 ? './' : '../'.repeat(depth));
}

export interface PageOptions {
  readonly slug: string;
  /** Where the whole book is published (`https://you.github.io/course/`), for links to its other pages; null keeps them as text. */
  readonly site: string | null;
}

/**
 * The chapter's page without what the package cannot serve: its search box
 * (and so the search code, which nothing else names), and links to other
 * pages of the book, pointed at the published book or made plain text.
 * Addresses of files are left to {@link relativeUrls}.
 */
export function prunePage(html: string, { slug, site }: PageOptions): string {
  const withoutSearch = html.replace(/<form class="site-search"[\s\S]*?<\/form>/, '');
  const base = PACKAGE_BASE.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
  const pageLink = new RegExp(`<a([^>]*?) href="${base}((?:[^"#?/]+/)*)([#?][^"]*)?"`, 'g');
  return withoutSearch.replace(pageLink, (_all, before: string, page: string, rest = '') => {
    if (page === `${slug}/`) return `<a${before} href="${PACKAGE_BASE}${slug}/index.html${rest}"`;
    if (site) return `<a${before} href="${site}${page}${rest}"`;
    return `<a${before} data-book-page="${page}${rest}"`;
  });
}

/** The page's inline scripts, as the browser hashes them for the Content-Security-Policy. */
export function inlineScripts(html: string): string[] {
  const scripts: string[] = [];
  for (const m of html.matchAll(/<script\b([^>]*)>([\s\S]*?)<\/script>/g)) {
    const attributes = m[1];
    if (/\ssrc=/.test(attributes)) continue;
    const type = /\stype="([^"]*)"/.exec(attributes)?.[1];
    if (type === undefined || type === 'module' || type === 'text/javascript') scripts.push(m[2]);
  }
  return scripts;
}

/** The page with its policy's script hashes replaced by those of the inline scripts it has now. */
export function withScriptHashes(html: string): string {
  const hashes = inlineScripts(html).map(scriptHash).join(' ');
  let found = false;
  const out = html.replace(/(<meta http-equiv="Content-Security-Policy" content=")([^"]*)"/, (_all, head: string, policy: string) => {
    found = true;
    const directives = policy.split(/;\s*/).map((directive) =>
      directive.startsWith('script-src ') ? `${directive.replace(/\s'sha256-[^']*'/g, '')} ${hashes}`.trimEnd() : directive);
    return `${head}${directives.join('; ')}"`;
  });
  if (!found) throw new Error('the page has no Content-Security-Policy to update');
  return out;
}

/** The page with the adapter's script, `src` relative to the page, loaded after the page is parsed. */
export function withAdapter(html: string, src: string): string {
  if (!html.includes('</head>')) throw new Error('the page has no </head>');
  return html.replace('</head>', `<script defer src="${src}"></script></head>`);
}
