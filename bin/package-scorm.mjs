#!/usr/bin/env node
/**
 * `npm run package:scorm [-- CHAPTER…] [--output DIR] [--site URL]`: one
 * SCORM 1.2 package (a .zip an LMS imports) per chapter, or per chapter
 * named, into DIR (build/scorm/ by default), which it names on stdout.
 *
 * The book is built for packages first, under a base path of its own
 * (site/scorm/chapter-files.ts), into build/scorm-site/ (or
 * PHASEBOOK_SCORM_SITE_DIR), unless the build there is of the sources as
 * they are now (site/lib/build-fingerprint.mjs). What goes into each
 * package is site/scorm/chapter-package.ts's; this file reads the build,
 * bundles the adapter (site/scorm/adapter.ts) and writes the ZIPs with the
 * CLI's writer (cli/formats/zip-writer.ts).
 *
 * --site URL is where the whole book is published: a chapter's links to
 * its other pages go there. Without it they are kept as text.
 *
 * Bad arguments, an unknown chapter or a failed build end in one line on
 * stderr and exit status 2; each package is written beside its name and
 * renamed onto it only when complete, so no partial file is left behind.
 */
import { spawn } from 'node:child_process';
import { closeSync, openSync, readdirSync, readFileSync, renameSync, rmSync, writeSync, mkdirSync } from 'node:fs';
import { basename, join, relative, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build as bundle } from 'esbuild';
import { ZipWriter } from '../cli/formats/zip-writer.ts';
import { isUpToDate } from '../site/lib/build-fingerprint.mjs';
import { PACKAGE_BASE } from '../site/scorm/chapter-files.ts';
import { chapterPackage } from '../site/scorm/chapter-package.ts';
import { siteAddress, UsageError } from './book-options.mjs';

const ROOT = fileURLToPath(new URL('..', import.meta.url));

/** @param {string[]} argv */
function parseArguments(argv) {
  const options = { output: join(ROOT, 'build/scorm'), site: null, chapters: /** @type {string[]} */ ([]) };
  for (let i = 0; i < argv.length; i++) {
    const [flag, inline] = argv[i].split(/=(.*)/s, 2);
    const value = () => {
      const v = inline ?? argv[++i];
      if (v === undefined || v === '') throw new UsageError(`${flag} needs a value`);
      return v;
    };
    if (flag === '--output') options.output = resolve(value());
    else if (flag === '--site') options.site = siteAddress(value());
    else if (flag.startsWith('-')) throw new UsageError(`unknown option ${flag} (options: --output DIR, --site URL)`);
    else options.chapters.push(argv[i]);
  }
  return options;
}

/** Every chapter of the book: one per MDX file of content/. */
function bookChapters() {
  return readdirSync(join(ROOT, 'content')).filter((name) => name.endsWith('.mdx')).map((name) => basename(name, '.mdx')).sort();
}

/** Builds the book under the package base into `dir`, unless it is there already; the build's output goes to stderr. */
async function ensureBuild(dir) {
  if (await isUpToDate(ROOT, dir, { base: PACKAGE_BASE })) return;
  process.stderr.write(`Building the book for packages into ${relative(process.cwd(), dir) || dir} …\n`);
  const child = spawn('npx', ['astro', 'build'], {
    cwd: ROOT,
    env: { ...process.env, PHASEBOOK_BASE: PACKAGE_BASE, PHASEBOOK_OUT_DIR: dir, ASTRO_TELEMETRY_DISABLED: '1' },
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let output = '';
  const keep = (chunk) => (output = (output + chunk).slice(-4000));
  child.stdout.on('data', keep);
  child.stderr.on('data', keep);
  const code = await new Promise((done) => child.on('close', done));
  if (code !== 0) {
    const last = output.split('\n').map((line) => line.trim()).filter(Boolean).pop() ?? '';
    throw new UsageError(`the book's build failed (exit ${code}): ${last}`);
  }
}

/**
 * The adapter as one script. The book's own modules are marked free of side effects, as they are, so
 * that the adapter carries the one constant it takes from cells/ and not the modules beside it.
 */
async function adapterScript() {
  const pure = {
    name: 'phasebook:pure-modules',
    setup(build) {
      build.onResolve({ filter: /^\.\.?\/.*\.ts$/ }, (args) =>
        args.resolveDir.includes('node_modules') ? undefined : { path: resolve(args.resolveDir, args.path), sideEffects: false });
    },
  };
  const result = await bundle({
    entryPoints: [join(ROOT, 'site/scorm/adapter.ts')],
    bundle: true,
    format: 'iife',
    minify: true,
    target: 'es2022',
    write: false,
    plugins: [pure],
    logLevel: 'silent',
  });
  return result.outputFiles[0].contents;
}

/** Every file under `dir`, as paths relative to it with '/'. */
function filesUnder(dir) {
  return readdirSync(dir, { recursive: true, withFileTypes: true })
    .filter((entry) => entry.isFile())
    .map((entry) => relative(dir, join(entry.parentPath ?? entry.path, entry.name)).split('\\').join('/'));
}

/** Writes `files` as a ZIP at `target`, through a partial file renamed onto it when complete. */
function writeZip(target, files) {
  const partial = join(resolve(target, '..'), `.${basename(target)}.partial-${process.pid}`);
  const fd = openSync(partial, 'w', 0o644);
  try {
    const zip = new ZipWriter((bytes) => writeSync(fd, bytes));
    for (const file of files) zip.add(file.path, file.bytes);
    zip.finish();
    closeSync(fd);
    renameSync(partial, target);
  } catch (error) {
    try {
      closeSync(fd);
    } catch {
      // already closed
    }
    rmSync(partial, { force: true });
    throw error;
  }
}

async function main() {
  const options = parseArguments(process.argv.slice(2));
  const known = bookChapters();
  const unknown = options.chapters.filter((name) => !known.includes(name));
  if (unknown.length) throw new UsageError(`no chapter named ${unknown.join(', ')} (chapters: ${known.join(', ')})`);
  const chapters = options.chapters.length ? [...new Set(options.chapters)] : known;
  const siteDir = resolve(process.env.PHASEBOOK_SCORM_SITE_DIR ?? join(ROOT, 'build/scorm-site'));
  await ensureBuild(siteDir);
  const site = { paths: filesUnder(siteDir), read: (path) => readFileSync(join(siteDir, path)) };
  const adapter = await adapterScript();
  try {
    mkdirSync(options.output, { recursive: true });
  } catch (error) {
    throw new UsageError(`cannot make the folder ${options.output}: ${error.message}`);
  }
  process.stdout.write(`${options.output}\n`);
  for (const slug of chapters) {
    const files = chapterPackage(site, slug, { site: options.site, adapter });
    const target = join(options.output, `${slug}.zip`);
    writeZip(target, files);
    const bytes = files.reduce((sum, file) => sum + file.bytes.length, 0);
    process.stderr.write(`${slug}.zip: ${files.length} files, ${(bytes / 1e6).toFixed(2)} MB\n`);
  }
}

main().catch((error) => {
  const message = error instanceof UsageError ? error.message : error?.message ?? String(error);
  process.stderr.write(`package:scorm: ${message.split('\n')[0]}\n`);
  process.exit(2);
});
