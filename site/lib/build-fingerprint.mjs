/**
 * Whether a build is up to date with its sources, for `npm start`
 * (bin/start.mjs), which serves the existing build when it is and builds
 * first only when it is not.
 *
 * A build records its input fingerprint beside its output folder
 * (`dist.fingerprint.json` beside `dist/`): a SHA-256 over the path and
 * content hash of every file it is built from, and over the settings that
 * change its output (the base path, the folder of chapters). Content, not
 * modification times: a checkout, a branch switch or a copy changes mtimes
 * without changing a byte, and an edit undone changes them both ways; what
 * matters is whether any byte the build reads differs. The record is
 * removed when a build starts and written when it ends well, so a failed
 * or interrupted build is never taken for an up-to-date one.
 */
import { createHash } from 'node:crypto';
import { existsSync, readFileSync } from 'node:fs';
import { readdir, readFile, rm, writeFile } from 'node:fs/promises';
import { join, relative, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

/** What the book is built from, below the project root: its code, chapters, template, config and locked dependencies. */
export const BUILD_INPUTS = ['content', 'site', 'widgets', 'cells', 'core', 'templates', 'astro.config.mjs', 'package-lock.json'];

/** Every file of `path` (a file or a folder), recursively, as absolute paths. */
async function filesOf(path) {
  if (!existsSync(path)) return [];
  const entries = await readdir(path, { withFileTypes: true, recursive: true }).catch((error) => {
    if (error.code === 'ENOTDIR') return null;
    throw error;
  });
  if (entries === null) return [path];
  return entries.filter((e) => e.isFile()).map((e) => join(e.parentPath ?? e.path, e.name));
}

/**
 * The fingerprint of the sources under `root` and of the build's settings:
 * `base` (PHASEBOOK_BASE) and `contentDir` (PHASEBOOK_CONTENT_DIR, which
 * then stands for content/).
 * @param {string} root
 * @param {{ base?: string, contentDir?: string }} [settings]
 */
export async function sourceFingerprint(root, settings = {}) {
  const inputs = BUILD_INPUTS.map((input) => (input === 'content' && settings.contentDir ? resolve(root, settings.contentDir) : join(root, input)));
  const hash = createHash('sha256');
  hash.update(JSON.stringify({ base: settings.base ?? '' }));
  for (const input of inputs) {
    const files = (await filesOf(input)).sort();
    hash.update(`\0${relative(root, input).split(sep).join('/')}\0${files.length}`);
    for (const file of files) {
      const content = createHash('sha256').update(await readFile(file)).digest('hex');
      hash.update(`\0${relative(input, file).split(sep).join('/')}\0${content}`);
    }
  }
  return hash.digest('hex');
}

/** Where the fingerprint of the build in `outDir` is kept: beside it, since a host serves whatever is inside. */
export function fingerprintFile(outDir) {
  return `${resolve(outDir).replace(/[\\/]+$/, '')}.fingerprint.json`;
}

/** The build's settings, as the environment gives them to astro.config.mjs. */
export function settingsFromEnv(env = process.env) {
  return { base: env.PHASEBOOK_BASE || undefined, contentDir: env.PHASEBOOK_CONTENT_DIR || undefined };
}

/** Is the build in `outDir` the build of the sources under `root` as they are now? */
export async function isUpToDate(root, outDir, settings = {}) {
  if (!existsSync(join(outDir, 'index.html'))) return false;
  let recorded;
  try {
    recorded = JSON.parse(readFileSync(fingerprintFile(outDir), 'utf8')).fingerprint;
  } catch {
    return false;
  }
  return recorded === (await sourceFingerprint(root, settings));
}

/** Astro integration: forgets the record when a build starts, and records the sources' fingerprint when it has ended well. */
export function recordFingerprint() {
  const root = fileURLToPath(new URL('../../', import.meta.url));
  let fingerprint = '';
  let outDir = '';
  return {
    name: 'phasebook:record-fingerprint',
    hooks: {
      'astro:config:done': ({ config }) => {
        outDir = fileURLToPath(config.outDir);
      },
      'astro:build:start': async () => {
        await rm(fingerprintFile(outDir), { force: true });
        fingerprint = await sourceFingerprint(root, settingsFromEnv());
      },
      'astro:build:done': async () => {
        await writeFile(fingerprintFile(outDir), `${JSON.stringify({ fingerprint }, null, 2)}\n`);
      },
    },
  };
}
