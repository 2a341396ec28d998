/**
 * The extension in a desktop VS Code: packaged as the .vsix an author installs, installed into
 * code-server (code-server.ts) with `--install-extension`, served headless on the loopback, and
 * driven from Debian's Chromium with playwright-core as an author would, in a workspace laid out
 * as a fork of the book (the template, a chapter, and the extension's fixtures under vscode/test/).
 * It checks, in order:
 *   1. the extension activates in the Node extension host (the remote host's log says so);
 *   2. "Phasebook: New Chapter" asks for a title and writes content/<title>.mdx from the template;
 *   3. the fork's fixtures give no problems (the status bar's count is zero);
 *   4. the new chapter's preview renders: its simulator draws, and moves;
 *   5. "Test: Run All Tests" passes every theory check and exercise, the fixtures' being none of them.
 * Each step waits for its state; none is judged by how long it took. Too slow to install for
 * every run of `npm test` (see code-server.ts), it runs alone:
 *
 *   npm run test:vscode:desktop
 */
import { execFileSync, spawn } from 'node:child_process';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { cp, mkdir, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { chromium, type Page } from 'playwright-core';
import { build, EXTENSION_DIR } from '../../build/build.ts';
import { checkCanvas, previewFrame } from '../driver/preview-checks.ts';
import { prepareCodeServer } from './code-server.ts';

const ROOT = path.resolve(EXTENSION_DIR, '..');
const CHROMIUM = process.env.PHASEBOOK_CHROMIUM ?? '/usr/bin/chromium';
/** Guards against a hang, not measures: each step takes seconds, longer on a busy machine. */
const STEP_TIMEOUT_MS = 180_000;
const NEW_TITLE = 'Waves on a string';

/** Polls `probe` until it returns something truthy; throws saying `what` after the guard. */
async function waitUntil<T>(what: string, probe: () => Promise<T | undefined | null | false> | T | undefined | null | false): Promise<T> {
  const deadline = Date.now() + STEP_TIMEOUT_MS;
  for (;;) {
    const value = await probe();
    if (value) return value;
    if (Date.now() > deadline) throw new Error(`timed out waiting for ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 250));
  }
}

/** The .vsix an author would install, built from this tree. */
async function packageExtension(into: string): Promise<string> {
  await build({ minify: true });
  const vsix = path.join(into, 'phasebook.vsix');
  execFileSync('npx', ['vsce', 'package', '--no-dependencies', '--allow-missing-repository', '-o', vsix], { cwd: EXTENSION_DIR, stdio: ['ignore', 'ignore', 'inherit'] });
  return vsix;
}

/** A fork's layout: the template, the template as a chapter with a simulator, the extension's fixtures where a fork keeps them. */
async function prepareWorkspace(folder: string): Promise<void> {
  await mkdir(path.join(folder, 'templates'), { recursive: true });
  await mkdir(path.join(folder, 'content'), { recursive: true });
  await cp(path.join(ROOT, 'templates/chapter.mdx'), path.join(folder, 'templates/chapter.mdx'));
  await cp(path.join(ROOT, 'templates/chapter.mdx'), path.join(folder, 'content/pendulum.mdx'));
  await cp(path.join(EXTENSION_DIR, 'test/fixtures/book'), path.join(folder, 'vscode/test/fixtures/book'), { recursive: true });
}

function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.once('error', reject);
    server.listen(0, '127.0.0.1', () => {
      const { port } = server.address() as { port: number };
      server.close(() => resolve(port));
    });
  });
}

/** The Node extension host's log lines, from every session's log folder of the user data. */
function extensionHostLog(userData: string): string {
  const logs = path.join(userData, 'logs');
  if (!existsSync(logs)) return '';
  return readdirSync(logs)
    .flatMap((session) => {
      const file = path.join(logs, session, 'exthost1/remoteexthost.log');
      return existsSync(file) ? [readFileSync(file, 'utf8')] : [];
    })
    .join('\n');
}

/** Runs a command from the palette, once the palette lists it first (it fills in as extensions register). */
async function runCommand(page: Page, title: string): Promise<void> {
  const input = page.locator('.quick-input-widget input.input');
  const first = page.locator('.quick-input-list .monaco-list-row').first();
  await waitUntil(`"${title}" in the command palette`, async () => {
    if (!(await input.isVisible())) await page.keyboard.press('F1');
    await input.fill(`>${title}`);
    const found = await first.getAttribute('aria-label', { timeout: 2000 }).catch(() => null);
    if (found?.startsWith(title)) return true;
    await page.keyboard.press('Escape');
    return false;
  });
  await page.keyboard.press('Enter');
}

/** The Test Explorer's rows, as their accessible names ("The pendulum (Passed), in 15.5s"). */
async function testRows(page: Page): Promise<string[]> {
  const labels = await page.locator('.test-explorer .monaco-list-row').evaluateAll((rows) => rows.map((row) => row.getAttribute('aria-label') ?? ''));
  return labels.filter((label) => label !== '');
}

async function main(): Promise<number> {
  const started = Date.now();
  const stage = (what: string) => console.log(`[${((Date.now() - started) / 1000).toFixed(1)} s] ${what}`);
  const codeServer = await prepareCodeServer(stage);
  stage('code-server ready');
  const scratch = await mkdtemp(path.join(tmpdir(), 'phasebook-vscode-desktop-'));
  const userData = path.join(scratch, 'user');
  const extensions = path.join(scratch, 'extensions');
  const workspace = path.join(scratch, 'fork');
  const options = ['--user-data-dir', userData, '--extensions-dir', extensions, '--config', path.join(scratch, 'config.yaml')];
  let server: ReturnType<typeof spawn> | undefined;
  let context: Awaited<ReturnType<typeof chromium.launchPersistentContext>> | undefined;
  try {
    const vsix = await packageExtension(scratch);
    stage('packaged the extension');
    const installed = execFileSync(process.execPath, [codeServer, ...options, '--install-extension', vsix], { encoding: 'utf8' });
    if (!/successfully installed/.test(installed)) throw new Error(`code-server did not install the extension: ${installed}`);
    stage('installed the .vsix with --install-extension');
    await prepareWorkspace(workspace);
    // No welcome page over the editors; the workspace is trusted, since the preview runs its code.
    await mkdir(path.join(userData, 'User'), { recursive: true });
    await writeFile(path.join(userData, 'User/settings.json'), JSON.stringify({ 'workbench.startupEditor': 'none', 'security.workspace.trust.enabled': false }));
    const port = await freePort();
    server = spawn(process.execPath, [codeServer, ...options, '--auth', 'none', '--bind-addr', `127.0.0.1:${port}`, '--disable-telemetry', '--disable-update-check', '--disable-workspace-trust', workspace], { stdio: ['ignore', 'pipe', 'pipe'] });
    const serverLog: string[] = [];
    server.stdout?.on('data', (chunk: Buffer) => serverLog.push(String(chunk)));
    server.stderr?.on('data', (chunk: Buffer) => serverLog.push(String(chunk)));
    await waitUntil('code-server to listen', () => serverLog.join('').includes('HTTP server listening'));

    const profile = path.join(scratch, 'chromium');
    await mkdir(path.join(profile, 'Default'), { recursive: true });
    // Cookies allowed, or the webviews' service worker is refused and they stay blank (see the notes).
    await writeFile(path.join(profile, 'Default/Preferences'), JSON.stringify({ profile: { cookie_controls_mode: 0 } }));
    context = await chromium.launchPersistentContext(profile, {
      executablePath: CHROMIUM,
      headless: true,
      args: ['--no-sandbox', '--disable-gpu', '--disable-quic'],
      viewport: { width: 1600, height: 1000 },
    });
    const page = context.pages()[0] ?? (await context.newPage());
    await page.goto(`http://127.0.0.1:${port}/?folder=${encodeURIComponent(workspace)}`);
    await page.locator('.monaco-workbench').waitFor({ timeout: STEP_TIMEOUT_MS });
    stage('workbench opened');

    await waitUntil('the extension to activate in the Node extension host', () => /_doActivateExtension phasebook\.phasebook\b/.test(extensionHostLog(userData)));
    stage('1. the extension activated in the Node extension host');

    await runCommand(page, 'Phasebook: New Chapter');
    const title = page.locator('.quick-input-widget input.input[placeholder="The pendulum"]');
    await title.waitFor({ timeout: STEP_TIMEOUT_MS });
    await title.fill(NEW_TITLE);
    await page.keyboard.press('Enter');
    const chapter = path.join(workspace, 'content/waves-on-a-string.mdx');
    await waitUntil('the new chapter on disk', () => existsSync(chapter) && readFileSync(chapter, 'utf8').includes(`title: "${NEW_TITLE}"`));
    await page.locator('.tabs-container .tab.active', { hasText: 'waves-on-a-string.mdx' }).waitFor({ timeout: STEP_TIMEOUT_MS });
    stage('2. New Chapter wrote content/waves-on-a-string.mdx from the template and opened it');

    // New Chapter waits for the workspace's chapters to be read, whose diagnostics are published first: the
    // fixtures under vscode/test/ would add 7 problems by now. The new chapter, the template's copy, has none.
    const problems = page.locator('.statusbar-item[id="status.problems"] a');
    await waitUntil('the status bar to count problems', async () => (await problems.getAttribute('aria-label').catch(() => null)) !== null);
    const counted = await problems.getAttribute('aria-label');
    if (counted !== 'No Problems') throw new Error(`the fork shows problems: ${counted}`);
    stage(`3. the fork's fixtures give no problems ("${counted}")`);

    await runCommand(page, 'Phasebook: Open Preview to the Side');
    const frame = await waitUntil('the preview of the new chapter', () => previewFrame(page, NEW_TITLE));
    await waitUntil('the simulator to be ready', () => frame.evaluate(() => document.querySelector('[data-widget="simulator"][data-ready]') !== null).catch(() => false));
    const drawing = await checkCanvas(frame);
    if (drawing) throw new Error(drawing);
    stage('4. the preview renders, its simulator drawing and moving');

    await runCommand(page, 'Test: Run All Tests');
    await runCommand(page, 'Testing: Focus on Test Explorer View');
    const chapters = ['The pendulum', NEW_TITLE];
    const rows = await waitUntil('every chapter to have passed or failed', async () => {
      const found = await testRows(page);
      return chapters.every((c) => found.some((row) => row.startsWith(`${c} (Passed)`) || row.startsWith(`${c} (Failed)`) || row.startsWith(`${c} (Errored)`))) ? found : undefined;
    });
    const failed = chapters.filter((c) => !rows.some((row) => row.startsWith(`${c} (Passed)`)));
    if (failed.length) throw new Error(`theory checks or exercises did not pass: ${rows.join('; ')}`);
    if (rows.some((row) => row.startsWith('Checks that pass, fail and throw'))) throw new Error(`the fixtures' checks are listed as tests: ${rows.join('; ')}`);
    stage(`5. every theory check and exercise passed: ${rows.join('; ')}`);
    return 0;
  } catch (error) {
    stage(`failed: ${(error as Error).message}`);
    if (context && process.env.PHASEBOOK_TEST_SCREENSHOT) await context.pages()[0]?.screenshot({ path: process.env.PHASEBOOK_TEST_SCREENSHOT });
    return 1;
  } finally {
    await context?.close();
    if (server && server.exitCode === null) {
      const exited = new Promise((resolve) => server!.once('exit', resolve));
      server.kill();
      await exited;
    }
    await rm(scratch, { recursive: true, force: true });
  }
}

main().then(
  (code) => process.exit(code),
  (error: unknown) => {
    console.error(error);
    process.exit(1);
  },
);
