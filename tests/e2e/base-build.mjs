/**
 * The book built a second time, for a base path (`PHASEBOOK_BASE=/phasebook-scorm-package-root/`),
 * as a GitHub project site is built: the e2e tests of the book under a sub-path
 * serve it there. It is built beside the site under test (PHASEBOOK_OUT_DIR +
 * `-base`, or build/site-base/), or taken from PHASEBOOK_BASE_OUT_DIR, and
 * built again whenever it is not the build of the sources as they are now
 * (its fingerprint, site/lib/build-fingerprint.mjs).
 *
 * `node tests/e2e/base-build.mjs` makes it ahead of the tests: `npm test`
 * (tests/run.mjs) runs that as a stage of its own beside the site's build,
 * so that the files that serve it find it made, or wait on its lock, instead
 * of building it inside the end-to-end lane.
 */
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { setTimeout as sleep } from 'node:timers/promises';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { isUpToDate } from '../../site/lib/build-fingerprint.mjs';
import { launchBrowser } from './browser.mjs';
import { startServer } from './server.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));

/**
 * The base path: the one the SCORM packages are built under (site/scorm/chapter-files.ts's PACKAGE_BASE),
 * so that one build serves the base-path tests and the packages (tests/e2e/scorm.test.mjs), and a path
 * nothing in the book contains, so that any address that escapes it is plain.
 */
export const BASE = '/phasebook-scorm-package-root/';

export const BASE_DIST =
  process.env.PHASEBOOK_BASE_OUT_DIR ?? (process.env.PHASEBOOK_OUT_DIR ? `${process.env.PHASEBOOK_OUT_DIR.replace(/\/+$/, '')}-base` : join(ROOT, 'build', 'site-base'));

/**
 * Whether the base-path build there is the build of the sources as they are now. By content, not by time:
 * made beside the site under test, it may end before that build does, and is no less current for it.
 */
const isCurrent = () => isUpToDate(ROOT, BASE_DIST, { base: BASE });

/**
 * Builds the base-path site unless the build of the sources as they are now is there. Test files run
 * in processes of their own, and two of them building into one folder at once break each other's build:
 * the first to make the lock folder builds, the others wait for it to go and then find the build done.
 * A lock whose process has died is taken over.
 */
export async function ensureBaseBuild(log = () => {}) {
  const lock = `${BASE_DIST.replace(/\/+$/, '')}.lock`;
  for (;;) {
    if (await isCurrent()) return;
    if (takeLock(lock)) break;
    await lockReleased(lock);
  }
  try {
    if (await isCurrent()) return;
    await build(log);
  } finally {
    rmSync(lock, { recursive: true, force: true });
  }
}

/** Makes the lock folder (atomic), or takes it over from a process that is gone; whether this process holds it. */
function takeLock(lock) {
  try {
    mkdirSync(lock);
    writeFileSync(join(lock, 'pid'), String(process.pid));
    return true;
  } catch (error) {
    if (error.code !== 'EEXIST') throw error;
  }
  let holder = NaN;
  try {
    holder = Number(readFileSync(join(lock, 'pid'), 'utf8'));
  } catch {
    return false; // being made this instant: its pid is on its way
  }
  if (alive(holder)) return false;
  rmSync(lock, { recursive: true, force: true });
  return takeLock(lock);
}

/** Waits until the lock folder is gone or its process has died: the sources are hashed again only then, not at every look. */
async function lockReleased(lock) {
  for (;;) {
    let holder = NaN;
    try {
      holder = Number(readFileSync(join(lock, 'pid'), 'utf8'));
    } catch (error) {
      if (error.code === 'ENOENT' && !existsSync(lock)) return;
    }
    if (Number.isFinite(holder) && !alive(holder)) return;
    await sleep(500);
  }
}

function alive(pid) {
  try {
    process.kill(pid, 0);
    return true;
  } catch (error) {
    return error.code === 'EPERM';
  }
}

async function build(log) {
  log(`building the book for ${BASE} into ${BASE_DIST}`);
  const child = spawn('npx', ['astro', 'build'], {
    cwd: ROOT,
    env: { ...process.env, PHASEBOOK_BASE: BASE, PHASEBOOK_OUT_DIR: BASE_DIST, ASTRO_TELEMETRY_DISABLED: '1' },
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  let output = '';
  child.stdout.on('data', (chunk) => (output = (output + chunk).slice(-20_000)));
  child.stderr.on('data', (chunk) => (output = (output + chunk).slice(-20_000)));
  const code = await new Promise((done) => child.on('close', done));
  if (code !== 0) throw new Error(`the build for ${BASE} failed (exit ${code}):\n${output}`);
}

/**
 * The base-path build (made first if need be), served under its base, and a browser at 1280 × 900 to read
 * it with; `name` labels the build's log lines.
 */
export async function openBaseSite(name) {
  await ensureBaseBuild((line) => process.stderr.write(`${name}: ${line}\n`));
  const server = await startServer(BASE_DIST, { base: BASE });
  try {
    const browser = await launchBrowser({ viewport: { width: 1280, height: 900 } });
    return {
      server,
      browser,
      async close() {
        await browser.close();
        await server.close();
      },
    };
  } catch (error) {
    await server.close();
    throw error;
  }
}

// Run as a script: the base-path build made ahead of the tests that serve it.
if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  await ensureBaseBuild((line) => console.log(`base-build: ${line}`));
  console.log(`base-build: ${BASE_DIST} is the build of the sources for ${BASE}`);
}
