#!/usr/bin/env node
/**
 * `npm start`: serves the built book at http://localhost:4321 with Astro's
 * preview server, building it first only when the build is missing or its
 * sources have changed since (site/lib/build-fingerprint.mjs compares their
 * content). `npm run dev` is the server to write with.
 */
import { spawn } from 'node:child_process';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { isUpToDate, settingsFromEnv } from '../site/lib/build-fingerprint.mjs';

const ROOT = fileURLToPath(new URL('../', import.meta.url));
const OUT_DIR = process.env.PHASEBOOK_OUT_DIR || join(ROOT, 'dist');
const ASTRO = join(ROOT, 'node_modules', 'astro', 'astro.js');

/** Runs Astro with `args` in the project root; resolves to its exit status. */
function astro(args) {
  const child = spawn(process.execPath, [ASTRO, ...args], { cwd: ROOT, stdio: 'inherit' });
  for (const signal of ['SIGINT', 'SIGTERM']) process.on(signal, () => child.kill(signal));
  return new Promise((done) => child.on('close', (code, signal) => done(code ?? (signal === 'SIGINT' ? 130 : 143))));
}

if (await isUpToDate(ROOT, OUT_DIR, settingsFromEnv())) {
  console.log(`${OUT_DIR} is up to date with the sources: serving it without a build`);
} else {
  console.log(`${OUT_DIR} is missing or older than the sources: building it first`);
  const status = await astro(['build']);
  if (status !== 0) process.exit(status);
}
process.exit(await astro(['preview', '--port', '4321']));
