/**
 * The build itself: a chapter whose cell fails fails the build, with a line
 * naming the file, the cell, the line and the message; a cell marked as
 * failing on purpose passes, and the build then prints no warning; and what
 * the build leaves to publish is only what a static host serves.
 *
 * The fixture chapters (tests/e2e/fixtures/) are built on their own, through
 * PHASEBOOK_CONTENT_DIR, into a temporary folder in build/; the book's own build is the
 * one under test (PHASEBOOK_OUT_DIR or dist/).
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync } from 'node:fs';
import { mkdir, mkdtemp, readdir, rm } from 'node:fs/promises';
import { join, relative, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import { DIST } from './server.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const FIXTURES = fileURLToPath(new URL('./fixtures/', import.meta.url));

/**
 * Builds the chapters of `contentDir` into a fresh folder: the exit status, everything printed, and the files written.
 * The folder is inside the project: Astro renders the pages of a build whose output lies outside the folder it runs
 * in from a bundle it writes to that folder's .astro/, which every such build shares, so that a build running at
 * the same time (the base-path build beside the e2e files, tests/run.mjs) would render the other's chapters.
 */
async function buildChapters(contentDir) {
  await mkdir(join(ROOT, 'build'), { recursive: true });
  const out = await mkdtemp(join(ROOT, 'build', 'build-test-'));
  try {
    // Astro itself, not through npx, whose own notices are not the build's.
    const child = spawn(process.execPath, [join(ROOT, 'node_modules', 'astro', 'astro.js'), 'build'], {
      cwd: ROOT,
      env: { ...process.env, PHASEBOOK_CONTENT_DIR: contentDir, PHASEBOOK_OUT_DIR: out, ASTRO_TELEMETRY_DISABLED: '1', NO_COLOR: '1', FORCE_COLOR: '0' },
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (chunk) => (stdout += chunk));
    child.stderr.on('data', (chunk) => (stderr += chunk));
    const status = await new Promise((done) => child.on('close', done));
    return { status, stdout, stderr, files: existsSync(out) ? await filesUnder(out) : [] };
  } finally {
    await rm(out, { recursive: true, force: true });
    await rm(`${out}.astro-cache`, { recursive: true, force: true });
    await rm(`${out}.fingerprint.json`, { force: true });
  }
}

/** Every file under `dir`, by its path from there with forward slashes. */
async function filesUnder(dir) {
  const entries = await readdir(dir, { withFileTypes: true, recursive: true });
  return entries.filter((e) => e.isFile()).map((e) => relative(dir, join(e.parentPath ?? e.path, e.name)).split(sep).join('/'));
}

/** The kinds of file a static host serves for the book: its pages, their scripts, styles and fonts, and the search index. */
const STATIC_KINDS = [
  // chapters are kebab-case, and embeds are /embed/<chapter>/<cell>/, a cell's name in camelCase
  /^(?:[A-Za-z0-9-]+\/)*index\.html$/,
  /^404\.html$/,
  /^_astro\/[^/]+\.(?:js|css|woff2?|ttf|svg|png|webp)$/,
  /^pagefind\/(?:[^/]+\/)*[^/]+\.(?:js|css|json|pf_fragment|pf_index|pf_meta|pagefind)$/,
  /^favicon\.(?:svg|ico)$/,
];

const isStatic = (path) => STATIC_KINDS.some((kind) => kind.test(path));

/** Lines of a build's output that are warnings, whoever printed them (Astro's logger, Vite, Rollup, npm). */
const warnings = (output) => output.split('\n').filter((line) => /\[WARN\]|\bwarn(?:ing)?\b|\(!\)|empty chunk/i.test(line));

test('a chapter whose cells fail fails the build, with a line per failing cell naming file, cell, line and message', async () => {
  const { status, stdout, stderr, files } = await buildChapters(join(FIXTURES, 'chapters-broken'));
  const output = `${stdout}\n${stderr}`;
  assert.notEqual(status, 0, output.slice(-3000));
  const file = relative(ROOT, join(FIXTURES, 'chapters-broken', 'crossed-fields.mdx'));
  const lines = stderr.split('\n');
  assert.ok(
    lines.includes(`${file}:13: cell model: InputError: E is Euler's number, 2.71828…; name the parameter something else, e.g. E0`),
    stderr.slice(-3000),
  );
  assert.ok(lines.includes(`${file}:21: cell half: RuntimeError: undefinedName is not defined`), stderr.slice(-3000));
  // Failing before the pages are written: nothing to publish by mistake.
  assert.deepEqual(files.filter((f) => f.endsWith('.html')), []);
});

test('a cell marked "fails" that fails passes the build, which prints no warning and writes only static files', async () => {
  const { status, stdout, stderr, files } = await buildChapters(join(FIXTURES, 'chapters-lesson'));
  const output = `${stdout}\n${stderr}`;
  assert.equal(status, 0, output.slice(-3000));
  assert.deepEqual(warnings(output), []);
  assert.ok(files.includes('reserved-names/index.html'), files.join('\n'));
  assert.deepEqual(files.filter((f) => !isStatic(f)), []);
});

test("the book's build holds only what a static host serves", async () => {
  const files = await filesUnder(DIST);
  assert.ok(files.includes('index.html') && files.includes('introduction/index.html'), `no book built in ${DIST}`);
  assert.deepEqual(files.filter((f) => !isStatic(f)), []);
});
