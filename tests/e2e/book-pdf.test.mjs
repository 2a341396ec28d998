/**
 * `npm run pdf` (bin/book-pdf.mjs): the whole book as one PDF, read back with
 * poppler (pdfinfo, pdftotext, pdfimages) and, for its links, which poppler
 * does not show, with pdf-links.mjs. What is expected comes from the
 * chapters' own sources in content/: their titles and order, a sentence of
 * the introduction, and the simulators their cells make.
 *
 * Heavy (every chapter is opened and every cell run once, about a minute on
 * a quiet machine): the book is made once, in `before`, and every test reads
 * that one file.
 */
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { mkdtemp, readdir, readFile, rm } from 'node:fs/promises';
import { readdirSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { fileURLToPath } from 'node:url';
import { promisify } from 'node:util';
import { readLinks } from './pdf-links.mjs';

const run = promisify(execFile);
const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const SITE = 'https://example.org/course/';

/** The chapters, from their sources: slug, title, order, and the simulators their cells make (by name, when named). */
const CHAPTERS = readdirSync(join(ROOT, 'content'))
  .filter((file) => file.endsWith('.mdx'))
  .map((file) => {
    const source = readFileSync(join(ROOT, 'content', file), 'utf8');
    const front = source.match(/^---\n([\s\S]*?)\n---/)[1];
    const field = (name) => front.match(new RegExp(`^${name}:\\s*(.*)$`, 'm'))[1].replace(/^"(.*)"$/, '$1');
    const cells = [...source.matchAll(/```js cell\n([\s\S]*?)```/g)].map((m) => m[1]);
    return {
      slug: file.replace(/\.mdx$/, ''),
      title: field('title'),
      order: Number(field('order')),
      simulators: cells.filter((code) => /\bsimulator\(/.test(code)).map((code) => code.match(/^(\w+)\s*=\s*simulator\(/)?.[1] ?? null),
    };
  })
  .sort((a, b) => a.order - b.order);

/** pdftotext's apostrophes and dashes as the sources write them, and no line breaks inside words' runs. */
const plain = (text) => text.replace(/[’‘]/g, "'");

const escapeRegExp = (text) => text.replace(/[.*+?^$()|[\]\\{}]/g, '\\$&');

/**
 * Text with its line breaks and runs of spaces as single spaces, and none after a dash that ends a line: a long
 * title may wrap, on its page or in the contents, between words or after the dash of "action–angle".
 */
const squashed = (text) => plain(text).replace(/([-–—])\s*\n\s*/g, '$1').replace(/\s+/g, ' ');

/** A pattern for `title` that lets it wrap where `squashed` lets it. */
const wrapping = (title) => plain(title).split(/\s+/).map((word) => escapeRegExp(word).replace(/([-–—])/g, '$1\\s*')).join('\\s+');

let folder;
let pdf;
/** The whole text, and each page's (pdftotext marks a new page with a form feed). */
let text;
let pages;

before(async () => {
  folder = await mkdtemp(join(tmpdir(), 'phasebook-pdf-'));
  pdf = join(folder, 'book.pdf');
  await run(process.execPath, [join(ROOT, 'bin/book-pdf.mjs'), '--output', pdf, '--site', SITE], { cwd: ROOT, maxBuffer: 1 << 24 });
  text = plain((await run('pdftotext', ['-enc', 'UTF-8', pdf, '-'], { maxBuffer: 1 << 26 })).stdout);
  pages = text.split('\f');
});
after(() => folder && rm(folder, { recursive: true, force: true }));

test('the PDF is the only file written, A4, with a plausible number of pages', async () => {
  assert.deepEqual(await readdir(folder), ['book.pdf'], 'a partial file was left behind');
  const info = (await run('pdfinfo', [pdf])).stdout;
  const count = Number(info.match(/^Pages:\s+(\d+)/m)[1]);
  assert.match(info, /^Page size:.*\(A4\)/m);
  // A title page, the contents, and every chapter from a new page: at least one page each, and not the pages a
  // chapter split into a page per paragraph would take.
  assert.ok(count >= CHAPTERS.length + 2 && count <= CHAPTERS.length * 25, `${count} pages for ${CHAPTERS.length} chapters`);
});

test("the contents page lists every chapter, in order, with the page it starts on, and links to that page", async () => {
  const contents = pages.findIndex((page) => /^Contents$/m.test(page));
  assert.ok(contents >= 0, 'no contents page');
  let from = 0;
  for (const { title } of CHAPTERS) {
    const at = squashed(pages[contents]).indexOf(squashed(title), from);
    assert.ok(at >= from, `the contents do not list "${title}" after the chapters before it`);
    from = at;
  }
  const { destinations, links } = readLinks(await readFile(pdf));
  const page = String(contents + 1);
  const laidOut = plain((await run('pdftotext', ['-layout', '-enc', 'UTF-8', '-f', page, '-l', page, pdf, '-'])).stdout);
  for (const { slug, title } of CHAPTERS) {
    const link = links.find((l) => l.page === contents + 1 && l.destination === `chapter-${slug}`);
    assert.ok(link, `no link to ${slug} on the contents page`);
    const start = destinations.get(link.destination);
    assert.ok(start, `the destination ${link.destination} is not in the PDF`);
    assert.ok(squashed(pages[start - 1]).includes(squashed(title)), `the link to "${title}" leads to page ${start}, which does not show it`);
    const listed = laidOut.match(new RegExp(`${wrapping(title)}\\s+(\\d+)\\s*$`, 'm'));
    assert.equal(Number(listed?.[1]), start, `the contents give "${title}" page ${listed?.[1]}; it starts on page ${start}`);
  }
});

test("links between chapters and to their sections are links inside the PDF, every one to a place it has", async () => {
  const { destinations, links } = readLinks(await readFile(pdf));
  const internal = links.filter((l) => l.destination);
  const inText = internal.filter((l) => pages[l.page - 1] && !/^Contents$/m.test(pages[l.page - 1]));
  assert.ok(inText.length > 0, 'no link inside the chapters leads anywhere inside the PDF');
  const dangling = internal.filter((l) => !destinations.get(l.destination)).map((l) => `page ${l.page} → ${l.destination}`);
  assert.deepEqual(dangling, []);
  // Nothing points back at the local server the book was printed from.
  assert.deepEqual(links.filter((l) => l.uri && /127\.0\.0\.1|localhost/.test(l.uri)), []);
});

test('the text is extractable: every chapter title, a sentence of the introduction, a formula, page numbers', () => {
  for (const { title } of CHAPTERS) assert.ok(squashed(text).includes(squashed(title)), `"${title}" is not in the text`);
  assert.match(text.replace(/\s+/g, ' '), /Hamilton describes it by a single function, the energy H\(q, p, t\)/);
  // Hamilton's equations, as KaTeX set them: q̇ and ∂H.
  assert.match(text, /q̇/);
  assert.match(text, /∂H/);
  const total = pages.filter((page) => page.trim()).length;
  assert.match(pages[2], new RegExp(`^\\s*3 / ${total}\\s*$`, 'm'), 'page 3 has no page number');
});

test('no toolbar, control or editor prints', () => {
  const controls = /^\s*(Run|Reset|Pause|Play|Step|\+ Cell|CSV|JSON|PNG|Share your edits|Print handout)\s*$/m;
  const found = pages.map((page, i) => [i + 1, page.match(controls)?.[1]]).filter(([, word]) => word);
  assert.deepEqual(found, []);
  // The toolbars' own texts (the prose names the buttons, as the teachers' page does, and that may print).
  for (const words of ['Shift+Enter runs', 'Edit, then tap Run', 'Reset Run', 'Cell Reset', 'of this chapter as a link; nothing is sent to any server']) {
    assert.ok(!text.includes(words), `"${words}" printed`);
  }
});

test('every simulator is a figure: an image, captioned with the address of its live cell on the published site', async () => {
  const simulators = CHAPTERS.flatMap((c) => c.simulators.map((name) => ({ slug: c.slug, name })));
  assert.ok(simulators.length > 0);
  const images = (await run('pdfimages', ['-list', pdf], { maxBuffer: 1 << 24 })).stdout.split('\n').filter((line) => /^\s*\d+\s+\d+\s+image\b/.test(line));
  assert.ok(images.length >= simulators.length, `${images.length} images for ${simulators.length} simulators`);
  // A long address may break across lines: read the text without them.
  const joined = text.replace(/\s+/g, '');
  for (const { slug, name } of simulators.filter((s) => s.name)) {
    const live = `${SITE}${slug}/#cell-${name}`;
    assert.ok(joined.includes(live), `no caption gives ${live}`);
  }
  const captions = joined.match(/Figure\d+\./g) ?? [];
  assert.ok(captions.length >= simulators.length, `${captions.length} captions for ${simulators.length} simulators`);
});
