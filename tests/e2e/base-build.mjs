/**
 * The book built a second time, for a base path (`PHASEBOOK_BASE=/phasebook/`),
 * as a GitHub project site is built: the e2e tests of the book under a sub-path
 * serve it there. It is built beside the site under test (PHASEBOOK_OUT_DIR +
 * `-base`, or build/site-base/), or taken from PHASEBOOK_BASE_OUT_DIR, and
 * built again whenever the site under test is newer.
 */
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { setTimeout as sleep } from 'node:timers/promises';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchBrowser } from './browser.mjs';
import { DIST, startServer } from './server.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));

export const BASE = '/phasebook/';

export const BASE_DIST =
  process.env.PHASEBOOK_BASE_OUT_DIR ?? (process.env.PHASEBOOK_OUT_DIR ? `${process.env.PHASEBOOK_OUT_DIR.replace(/\/+$/, '')}-base` : join(ROOT, 'build', 'site-base'));

const builtAt = (dir) => (existsSync(join(dir, 'index.html')) ? statSync(join(dir, 'index.html')).mtimeMs : -Infinity);

/**
 * Builds the base-path site unless one at least as new as the site under test is there. Test files run
 * in processes of their own, and two of them building into one folder at once break each other's build:
 * the first to make the lock folder builds, the others wait for it to go and then find the build done.
 * A lock whose process has died is taken over.
 */
export async function ensureBaseBuild(log = () => {}) {
  const lock = `${BASE_DIST.replace(/\/+$/, '')}.lock`;
  for (;;) {
    if (builtAt(BASE_DIST) >= builtAt(DIST)) return;
    if (takeLock(lock)) break;
    await sleep(500);
  }
  try {
    if (builtAt(BASE_DIST) >= builtAt(DIST)) return;
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
