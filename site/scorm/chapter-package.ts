/**
 * The files of one chapter's SCORM 1.2 package, from the book built under
 * the package base (chapter-files.ts): the chapter's page and what it
 * needs, every address made relative (relative-urls.ts), the adapter that
 * reports to the LMS (site/scorm/adapter.ts, bundled), and the manifest
 * listing them all (manifest.ts). Writing them into a ZIP is the caller's.
 */
import { type BuiltSite, chapterFiles, chapterPage, isText, PACKAGE_BASE } from './chapter-files.ts';
import { scormManifest } from './manifest.ts';
import { depthOf, prunePage, relativeUrls, withAdapter, withScriptHashes } from './relative-urls.ts';

/** Where the adapter's script sits in every package. */
export const ADAPTER_PATH = 'phasebook-scorm.js';

export interface PackageFile {
  readonly path: string;
  readonly bytes: Uint8Array;
}

export interface PackageOptions {
  /** Where the whole book is published, for links to its other pages; null keeps them as text. */
  readonly site: string | null;
  /** The adapter's bundled script. */
  readonly adapter: Uint8Array;
}

/** The chapter's title, from its page's <title>, with HTML's character references read. */
export function pageTitle(html: string, slug: string): string {
  const raw = /<title>([^<]*)<\/title>/.exec(html)?.[1]?.trim();
  if (!raw) return slug;
  return raw.replace(/&(#x[0-9a-f]+|#[0-9]+|amp|lt|gt|quot|apos);/gi, (_all, ref: string) => {
    const r = ref.toLowerCase();
    if (r.startsWith('#x')) return String.fromCodePoint(parseInt(r.slice(2), 16));
    if (r.startsWith('#')) return String.fromCodePoint(parseInt(r.slice(1), 10));
    return ({ amp: '&', lt: '<', gt: '>', quot: '"', apos: "'" } as Record<string, string>)[r];
  });
}

/** Every file of the chapter's package, `imsmanifest.xml` last. */
export function chapterPackage(site: BuiltSite, slug: string, { site: published, adapter }: PackageOptions): PackageFile[] {
  const page = chapterPage(slug);
  const encoder = new TextEncoder();
  const decoder = new TextDecoder();
  const pruned = prunePage(decoder.decode(site.read(page)), { slug, site: published });
  const pageDepth = depthOf(page);
  const selected = chapterFiles({ paths: site.paths, read: (path) => (path === page ? encoder.encode(pruned) : site.read(path)) }, slug);
  const files: PackageFile[] = selected.map((path) => {
    if (path === page) {
      const html = withAdapter(withScriptHashes(relativeUrls(pruned, page, pageDepth)), `${'../'.repeat(pageDepth)}${ADAPTER_PATH}`);
      return { path, bytes: encoder.encode(html) };
    }
    const bytes = site.read(path);
    return isText(path) ? { path, bytes: encoder.encode(relativeUrls(decoder.decode(bytes), path, pageDepth)) } : { path, bytes };
  });
  files.push({ path: ADAPTER_PATH, bytes: adapter });
  for (const file of files) {
    if (isText(file.path) && decoder.decode(file.bytes).includes(PACKAGE_BASE)) throw new Error(`${file.path} still names the package base`);
  }
  const manifest = scormManifest({ slug, title: pageTitle(pruned, slug), launch: page, files: files.map((f) => f.path) });
  return [...files, { path: 'imsmanifest.xml', bytes: encoder.encode(manifest) }];
}
