#!/usr/bin/env node
/**
 * `npm run pdf [-- --output FILE] [--site URL]`: the whole book as one PDF,
 * from the built site (dist/, or PHASEBOOK_OUT_DIR; under PHASEBOOK_BASE
 * when it was built so), in Debian's Chromium, offline.
 *
 * Each chapter is opened as a reader would, and its Print handout is
 * prepared (cells/handout.ts: every cell run, every simulator's frame
 * drawn, every figure captioned with the address of its live cell). Its
 * text is then taken, with each canvas as the image it shows, into one
 * HTML document built for print: a title page, a contents page, the
 * chapters, each from a new page. One document, so that a link from one
 * chapter to another, or to a section or a cell, is a link inside the PDF.
 * Chromium prints it with a running title and page numbers.
 *
 * --site URL is where the book is published (https://you.github.io/course/):
 * the figures' captions print their live cells' addresses under it. Without
 * it they name http://localhost:4321/ and the base path, where `npm start`
 * serves the book.
 *
 * Bad arguments, or a chapter whose cells do not finish, end in one line on
 * stderr and exit status 2; the PDF is written beside its name and renamed
 * onto it only when complete, so no partial file is left behind.
 */
import { mkdir, rename, rm, writeFile } from 'node:fs/promises';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { DIST, startServer } from '../tests/e2e/server.mjs';
import { readLinks } from '../tests/e2e/pdf-links.mjs';
import { siteAddress, UsageError } from './book-options.mjs';

const ROOT = fileURLToPath(new URL('..', import.meta.url));
/** How long one chapter may take to run every cell and draw, ms: generous, for a loaded machine. */
const CHAPTER_LIMIT_MS = 300_000;
/** The layout width the chapters are drawn at, CSS px: about the printed text's width on A4, so figures scale little. */
const PRINT_WIDTH = 760;

/** @param {string[]} argv */
function parseArguments(argv) {
  const options = { output: join(ROOT, 'build/phasebook.pdf'), site: null };
  for (let i = 0; i < argv.length; i++) {
    const [flag, inline] = argv[i].split(/=(.*)/s, 2);
    const value = () => {
      const v = inline ?? argv[++i];
      if (v === undefined || v === '') throw new UsageError(`${flag} needs a value`);
      return v;
    };
    if (flag === '--output') options.output = resolve(value());
    else if (flag === '--site') options.site = siteAddress(value());
    else if (flag === '--help') {
      process.stdout.write('npm run pdf -- [--output FILE (build/phasebook.pdf)] [--site URL where the book is published]\n');
      process.exit(0);
    } else throw new UsageError(`unknown option ${argv[i]}; the options are --output FILE and --site URL`);
  }
  if (!options.output.endsWith('.pdf')) throw new UsageError(`--output must name a .pdf file, not ${options.output}`);
  return options;
}

/** The site's base path, as astro.config.mjs reads it: `/` or `/course/`. */
function basePath() {
  const base = process.env.PHASEBOOK_BASE ?? '/';
  return `/${base.replace(/^\/+|\/+$/g, '')}/`.replace(/^\/\/$/, '/');
}

/**
 * In the page: the chapters the home page lists, in its order, as paths.
 * @param {string} base
 */
function listChapters(base) {
  const paths = [...document.querySelectorAll('main a[href]')]
    .map((a) => new URL(a.getAttribute('href'), location.href))
    .filter((url) => url.origin === location.origin && url.pathname.startsWith(base) && /^[\w-]+\/$/.test(url.pathname.slice(base.length)))
    .map((url) => url.pathname);
  return [...new Set(paths)];
}

/**
 * In the page, once its handout is ready: the chapter as a fragment of the book. Canvases become images of what
 * they show; ids get the chapter's slug in front, so that they stay unique in one document; links into the book
 * become links inside it, and links elsewhere absolute addresses on the published site.
 * @param {{ slug: string, base: string, site: string, chapters: string[] }} book
 */
function chapterFragment({ slug, base, site, chapters }) {
  const article = document.querySelector('article[data-chapter]');
  const copy = article.cloneNode(true);
  const canvases = [...article.querySelectorAll('canvas')];
  [...copy.querySelectorAll('canvas')].forEach((canvas, i) => {
    const original = canvases[i];
    const image = document.createElement('img');
    const box = original.getBoundingClientRect();
    image.src = original.width > 0 && original.height > 0 ? original.toDataURL('image/png') : '';
    image.alt = original.getAttribute('aria-label') ?? '';
    image.className = `${original.className} book-figure`.trim();
    image.style.cssText = original.style.cssText;
    if (box.width > 0) image.style.width = `${box.width}px`;
    if (box.height > 0) image.style.height = `${box.height}px`;
    canvas.replaceWith(image);
  });
  copy.querySelectorAll('script, template, noscript, .print-handout, .share-edits, .on-this-page').forEach((node) => node.remove());
  const idIn = (chapter, id) => (id ? `${chapter}--${id}` : `chapter-${chapter}`);
  copy.querySelectorAll('[id]').forEach((node) => (node.id = idIn(slug, node.id)));
  copy.querySelectorAll('[aria-labelledby], [aria-describedby], label[for]').forEach((node) => {
    for (const name of ['aria-labelledby', 'aria-describedby', 'for']) {
      const ids = node.getAttribute(name);
      if (ids) node.setAttribute(name, ids.split(/\s+/).map((id) => idIn(slug, id)).join(' '));
    }
  });
  const published = (url) => new URL(url.pathname.slice(base.length) + url.search + url.hash, site).href;
  copy.querySelectorAll('a[href]').forEach((a) => {
    const url = new URL(a.getAttribute('href'), location.href);
    if (url.origin !== location.origin) return;
    // A figure's caption names its live cell, on the web, in full.
    if (a.closest('.cell-print-caption')) {
      a.href = a.textContent = published(url);
      return;
    }
    const target = chapters.find((path) => path === url.pathname);
    const hash = decodeURIComponent(url.hash.slice(1));
    if (target) a.setAttribute('href', `#${idIn(target.slice(base.length, -1), hash)}`);
    else a.href = published(url);
  });
  return { title: article.querySelector('h1')?.textContent?.trim() ?? slug, html: copy.outerHTML };
}

/** In the page: its stylesheets' text, fonts declared to be waited for (a printout has no first paint to keep). */
function pageStyles() {
  const sheets = [...document.styleSheets].map((sheet) => {
    try {
      return [...sheet.cssRules].map((rule) => rule.cssText).join('\n');
    } catch {
      return '';
    }
  });
  return sheets.join('\n').replace(/font-display:\s*optional/g, 'font-display: block');
}

/** The book's own layout on paper: title page, contents, a chapter from a new page. */
const BOOK_CSS = `
@page { size: A4; margin: 18mm 16mm 20mm; @top-center { content: none; } @bottom-center { content: none; } }
.book-title { break-after: page; padding-top: 30vh; text-align: center; }
.book-title h1 { font-size: 32pt; margin: 0 0 0.4em; }
.book-contents { break-after: page; }
.book-contents ol { list-style: none; padding: 0; }
.book-contents li { display: flex; gap: 0.5em; margin: 0.35em 0; font-size: 12pt; }
.book-contents li a { flex: 1; text-decoration: none; color: inherit; }
.book-contents .book-page { min-width: 3em; text-align: right; font-variant-numeric: tabular-nums; }
.book-chapter { break-before: page; }
img.book-figure { max-width: 100%; height: auto !important; object-fit: contain; }
`;

/** @param {string} text */
const escapeHtml = (text) => text.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

/**
 * @param {{ styles: string, site: string, chapters: { slug: string, title: string, html: string }[], startPages?: Map<string, number> }} book
 *   `startPages`: each chapter's first page, by its destination's name, once a first printing has told
 */
function bookDocument({ styles, site, chapters, startPages = new Map() }) {
  const contents = chapters
    .map((c) => `<li><a href="#chapter-${c.slug}">${escapeHtml(c.title)}</a><span class="book-page">${startPages.get(`chapter-${c.slug}`) ?? ''}</span></li>`)
    .join('\n');
  const body = chapters.map((c) => `<section class="book-chapter" id="chapter-${c.slug}">${c.html}</section>`).join('\n');
  return `<!doctype html>
<html lang="en" data-theme="light">
<head><meta charset="utf-8"><title>Phasebook</title><style>${styles}</style><style>${BOOK_CSS}</style></head>
<body class="chapter-body"><main class="page chapter-page">
<section class="book-title"><h1>Phasebook</h1><p>An interactive textbook of Hamiltonian mechanics</p>
<p>Every figure is a live simulation at the address printed under it: <a href="${escapeHtml(site)}">${escapeHtml(site)}</a></p></section>
<nav class="book-contents" aria-labelledby="book-contents-title"><h2 id="book-contents-title">Contents</h2><ol>
${contents}
</ol></nav>
${body}
</main></body></html>`;
}

const HEADER = `<div style="width:100%;font:8px sans-serif;color:#555;text-align:center;">Phasebook — Hamiltonian mechanics</div>`;
const FOOTER = `<div style="width:100%;font:8px sans-serif;color:#555;text-align:center;"><span class="pageNumber"></span> / <span class="totalPages"></span></div>`;

/** A4, the running title and page numbers in the margins, and an outline of chapters and sections. */
const PDF_OPTIONS = {
  format: 'A4',
  printBackground: true,
  displayHeaderFooter: true,
  headerTemplate: HEADER,
  footerTemplate: FOOTER,
  margin: { top: '18mm', bottom: '20mm', left: '16mm', right: '16mm' },
  outline: true,
  tagged: true,
};

/**
 * Opens a chapter, runs its handout's preparation (its Print handout button; the dialog it would open is
 * replaced by the `beforeprint` the browser sends, which draws each simulator's frame and captions the figures).
 * @param {import('playwright-core').BrowserContext} context
 */
async function prepareChapter(context, url) {
  const page = await context.newPage();
  page.setDefaultTimeout(CHAPTER_LIMIT_MS);
  await page.addInitScript(() => {
    window.print = () => {
      dispatchEvent(new Event('beforeprint'));
      document.documentElement.dataset.printed = '';
    };
  });
  await page.goto(url);
  const button = page.locator('[data-print-button]');
  if ((await button.count()) > 0) {
    await page.waitForFunction(() => document.body.hasAttribute('data-cells-ready'));
    await button.click();
    await page.waitForFunction(() => document.documentElement.hasAttribute('data-printed'));
  }
  return page;
}

async function main() {
  const options = parseArguments(process.argv.slice(2));
  const base = basePath();
  const server = await startServer(DIST, { base }).catch((error) => {
    throw new UsageError(error.message);
  });
  const site = options.site ?? `http://localhost:4321${base}`;
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking'],
  });
  const partial = join(dirname(options.output), `.${Date.now()}-${process.pid}.phasebook-pdf.partial`);
  try {
    const context = await browser.newContext({ viewport: { width: PRINT_WIDTH, height: 1000 }, deviceScaleFactor: 2, colorScheme: 'light', reducedMotion: 'reduce' });
    const home = await context.newPage();
    await home.goto(`${server.origin}${base}`);
    const paths = await home.evaluate(listChapters, base);
    if (paths.length === 0) throw new UsageError(`the built site's home page lists no chapters (${DIST})`);
    const chapters = [];
    let styles = '';
    for (const path of paths) {
      const slug = path.slice(base.length, -1);
      process.stderr.write(`pdf: ${slug}\n`);
      const page = await prepareChapter(context, `${server.origin}${path}`).catch((error) => {
        throw new UsageError(`the chapter ${slug} did not finish running its cells: ${error.message.split('\n')[0]}`);
      });
      if (!styles) styles = await page.evaluate(pageStyles);
      chapters.push({ slug, ...(await page.evaluate(chapterFragment, { slug, base, site, chapters: paths })) });
      await page.close();
    }
    // The book is served beside the site, so that the fonts' addresses resolve as on its pages.
    const bookUrl = `${server.origin}${base}phasebook-book.html`;
    let html = bookDocument({ styles, site, chapters });
    await context.route(bookUrl, (route) => route.fulfill({ contentType: 'text/html; charset=utf-8', body: html }));
    const print = async () => {
      await home.goto(bookUrl);
      await home.evaluate(() => document.fonts.ready.then(() => undefined));
      return home.pdf(PDF_OPTIONS);
    };
    // Printed twice: the first printing says where each chapter starts, which the contents then give. The
    // numbers take a column the contents keep for them either way, so the pages do not move.
    html = bookDocument({ styles, site, chapters, startPages: readLinks(await print()).destinations });
    await mkdir(dirname(options.output), { recursive: true });
    await writeFile(partial, await print());
    await rename(partial, options.output);
    process.stderr.write(`pdf: ${options.output}, ${chapters.length} chapters\n`);
  } finally {
    await rm(partial, { force: true });
    await browser.close();
    await server.close();
  }
}

main().catch((error) => {
  process.stderr.write(`phasebook pdf: ${error instanceof UsageError ? error.message : (error?.stack ?? error)}\n`.replace(/\n(?!$)/g, ' '));
  process.exit(2);
});
