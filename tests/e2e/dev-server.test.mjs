/**
 * The authoring loop: `npm run dev` serves the book with Astro's dev server,
 * and an edit to a chapter shows in the open page without a restart. The
 * chapter is a copy of the introduction in a temporary folder of chapters
 * (PHASEBOOK_CONTENT_DIR), so the real content/ is never touched.
 */
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { copyFile, mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { launchBrowser } from './browser.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));

/** A port nothing listens on now. */
function freePort() {
  return new Promise((done, fail) => {
    const server = createServer().once('error', fail).listen(0, '127.0.0.1', () => {
      const { port } = server.address();
      server.close(() => done(port));
    });
  });
}

/** Resolves once `url` answers 200, polling; rejects if `child` exits first. */
async function answered(url, child, output) {
  let exited = null;
  child.once('exit', (code) => (exited = code));
  for (;;) {
    if (exited !== null) throw new Error(`npm run dev exited with ${exited}:\n${output()}`);
    const ok = await fetch(url).then((r) => r.ok, () => false);
    if (ok) return;
    await new Promise((wait) => setTimeout(wait, 500));
  }
}

test('npm run dev serves a chapter, and an edit to its file shows in the open page without a restart', async (t) => {
  const chapters = await mkdtemp(join(tmpdir(), 'phasebook-dev-chapters-'));
  const caches = await mkdtemp(join(tmpdir(), 'phasebook-dev-cache-'));
  const chapter = join(chapters, 'introduction.mdx');
  await copyFile(join(ROOT, 'content', 'introduction.mdx'), chapter);
  const port = await freePort();
  const child = spawn('npm', ['run', 'dev', '--', '--port', String(port), '--host', '127.0.0.1'], {
    cwd: ROOT,
    env: { ...process.env, PHASEBOOK_CONTENT_DIR: chapters, PHASEBOOK_OUT_DIR: join(caches, 'out'), ASTRO_TELEMETRY_DISABLED: '1' },
    stdio: ['ignore', 'pipe', 'pipe'],
    detached: true,
  });
  let output = '';
  child.stdout.on('data', (chunk) => (output = (output + chunk).slice(-20_000)));
  child.stderr.on('data', (chunk) => (output = (output + chunk).slice(-20_000)));
  const browser = await launchBrowser();
  t.after(async () => {
    await browser.close();
    // npm, its shell and Astro: the whole group this test started.
    try {
      process.kill(-child.pid, 'SIGTERM');
    } catch {}
    await rm(chapters, { recursive: true, force: true });
    await rm(caches, { recursive: true, force: true });
    await rm(`${join(caches, 'out')}.astro-cache`, { recursive: true, force: true });
  });

  const origin = `http://127.0.0.1:${port}`;
  await answered(`${origin}/introduction/`, child, () => output);
  const page = await browser.context.newPage();
  await page.goto(`${origin}/introduction/`);
  await page.getByRole('heading', { level: 1, name: 'Introduction' }).waitFor();
  // The chapter's cells run under the dev server too: brought into view (cells start near it), the simulator is there.
  await page.locator('[data-cell="sim"]').scrollIntoViewIfNeeded();
  await page.locator('[data-cell="sim"] [data-widget="simulator"]').waitFor();

  const edited = 'Hamilton describes it, as this edit says, by a single function';
  const text = await readFile(chapter, 'utf8');
  assert.ok(text.includes('Hamilton describes it\nby a single function'));
  await writeFile(chapter, text.replace('Hamilton describes it\nby a single function', edited));
  // No reload or navigation by the test: the dev server brings the edit to the page.
  await page.waitForFunction((words) => document.querySelector('article, main')?.textContent.includes(words), edited);
  assert.equal(child.exitCode, null, 'the dev server is still the one started');
});
