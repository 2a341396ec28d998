/**
 * `npm run package:scorm`: SCORM 1.2 packages of two chapters, read back.
 *
 * Each manifest is parsed as XML (the browser's DOMParser) and its files
 * are compared with the ZIP's, both ways. The introduction's package is
 * unpacked under a deep path no page of the book knows, /lms/course-7/sco-3/,
 * beside a test LMS page, /lms/host.html, whose SCORM 1.2 API is
 * scorm-again's Scorm12API (a maintained implementation of the LMS side,
 * independent of the book), and which opens the launch page in an iframe as
 * an LMS does. Two exercises are solved there, against their closed forms:
 * the harmonic oscillator's period 2π/ω at ω = 5, and the drive's spectral
 * line κ/2π at κ = 8 (a cosine of angular frequency κ has period 2π/κ).
 * The score and status the LMS received are checked, and printed as a
 * transcript; every request of the page must stay inside the package.
 *
 * The package's book is the base-path build the other e2e files serve
 * (base-build.mjs, made once, under a lock): its base is the packages' own,
 * so the packager takes it as it is, and this file checks that it did not
 * build the book again.
 */
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import { mkdtemp, mkdir, readFile, rm, writeFile } from 'node:fs/promises';
import { createRequire } from 'node:module';
import { readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { after, before, test } from 'node:test';
import { unzipSync } from 'fflate';
import { launchBrowser, watchPage } from './browser.mjs';
import { startServer } from './server.mjs';
import { answer, exercise } from './exercise-answers.mjs';
import { BASE_DIST, ensureBaseBuild } from './base-build.mjs';

const ROOT = fileURLToPath(new URL('../../', import.meta.url));
const require = createRequire(import.meta.url);
const SCORM_AGAIN = require.resolve('scorm-again/scorm12/min');
const AXE = readFileSync(require.resolve('axe-core/axe.min.js'), 'utf8');
const CHAPTERS = ['introduction', 'nonlinear-oscillator'];
/** Where the LMS unpacks the introduction: deep, and named like nothing in the book. */
const SCO = '/lms/course-7/sco-3/';
const LAUNCH = 'introduction/index.html';

const siteDir = process.env.PHASEBOOK_SCORM_SITE_DIR ?? BASE_DIST;

/** The host page of the test LMS: scorm-again's API as window.API, a transcript of every call the SCO makes, the SCO in an iframe. */
const HOST = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Test LMS</title><link rel="icon" href="data:,">
<script src="scorm12.min.js"></script>
<script>
  window.transcript = [];
  window.API = new Scorm12API({ autocommit: false, logLevel: 5 });
  for (const name of ['LMSInitialize', 'LMSCommit', 'LMSFinish']) window.API.on(name, () => window.transcript.push([name]));
  window.API.on('LMSSetValue.cmi.*', (element, value) => window.transcript.push(['LMSSetValue', element, value]));
</script></head>
<body><h1>Course 7</h1><iframe title="The chapter" src="course-7/sco-3/${LAUNCH}" style="width: 1200px; height: 800px"></iframe></body></html>`;

/** A host whose LMS refuses every value: the SCO must say so once, politely, and go on working. */
const REFUSING_HOST = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Refusing LMS</title><link rel="icon" href="data:,">
<script>
  window.calls = 0;
  window.API = {
    LMSInitialize: () => 'true', LMSFinish: () => 'true', LMSCommit: () => 'true',
    LMSGetValue: () => '',
    LMSSetValue: () => { window.calls++; return 'false'; },
    LMSGetLastError: () => '351', LMSGetErrorString: () => 'Not implemented here',
  };
</script></head>
<body><iframe title="The chapter" src="course-7/sco-3/${LAUNCH}" style="width: 1200px; height: 800px"></iframe></body></html>`;

let scratch;
let packages;
let server;
let browser;

/** Runs the packager; resolves with its stdout, or rejects with its stderr. */
function packageScorm(args) {
  return new Promise((resolve, reject) => {
    execFile(join(ROOT, 'node_modules/.bin/tsx'), [join(ROOT, 'bin/package-scorm.mjs'), ...args], {
      cwd: ROOT,
      env: { ...process.env, ...(siteDir ? { PHASEBOOK_SCORM_SITE_DIR: siteDir } : {}) },
      maxBuffer: 1 << 24,
    }, (error, stdout, stderr) => (error ? reject(new Error(`package:scorm failed (${error.code}): ${stderr}`)) : resolve({ stdout, stderr })));
  });
}

before(async () => {
  scratch = await mkdtemp(join(tmpdir(), 'phasebook-scorm-'));
  if (!process.env.PHASEBOOK_SCORM_SITE_DIR) await ensureBaseBuild();
  const { stdout, stderr } = await packageScorm([...CHAPTERS, '--output', join(scratch, 'packages')]);
  process.stderr.write(stderr);
  assert.doesNotMatch(stderr, /Building the book/, 'the packager takes the base-path build as it is: its base must be the packages\' own');
  assert.equal(stdout.trim(), join(scratch, 'packages'), 'the packager names its folder on stdout');
  packages = Object.fromEntries(await Promise.all(CHAPTERS.map(async (slug) => [slug, unzipSync(await readFile(join(scratch, 'packages', `${slug}.zip`)))])));
  // The LMS's own folder: its pages, and the introduction's package unpacked deep below.
  const lms = join(scratch, 'lms');
  for (const [path, bytes] of Object.entries(packages.introduction)) {
    await mkdir(dirname(join(lms, SCO.slice('/lms/'.length), path)), { recursive: true });
    await writeFile(join(lms, SCO.slice('/lms/'.length), path), bytes);
  }
  await writeFile(join(lms, 'index.html'), '<!doctype html><title>LMS</title>');
  await writeFile(join(lms, 'host.html'), HOST);
  await writeFile(join(lms, 'refusing.html'), REFUSING_HOST);
  await writeFile(join(lms, 'scorm12.min.js'), await readFile(SCORM_AGAIN));
  server = await startServer(lms, { base: '/lms/' });
  browser = await launchBrowser({ viewport: { width: 1280, height: 900 } });
});

after(async () => {
  await browser?.close();
  await server?.close();
  if (scratch) await rm(scratch, { recursive: true, force: true });
});

/** What axe finds wrong in a page or frame, one line per rule. */
async function axeViolations(target) {
  await target.evaluate(AXE);
  return target.evaluate(async () =>
    (await window.axe.run(document, { resultTypes: ['violations'] })).violations.map((v) => `${v.id} (${v.nodes.length}): ${v.nodes[0]?.target.join(' ')}`));
}

/** The manifest read by the browser's XML parser: its parse error if any, and what SCORM 1.2 asks of it. */
async function readManifest(xml) {
  const page = await browser.context.newPage();
  try {
    return await page.evaluate((text) => {
      const doc = new DOMParser().parseFromString(text, 'application/xml');
      const error = doc.getElementsByTagName('parsererror')[0]?.textContent ?? null;
      const IMSCP = 'http://www.imsproject.org/xsd/imscp_rootv1p1p2';
      const ADLCP = 'http://www.adlnet.org/xsd/adlcp_rootv1p2';
      const all = (name) => [...doc.getElementsByTagNameNS(IMSCP, name)];
      return {
        error,
        schema: all('schema').map((e) => e.textContent),
        schemaversion: all('schemaversion').map((e) => e.textContent),
        organizations: all('organization').length,
        items: all('item').map((e) => e.getAttribute('identifierref')),
        resources: all('resource').map((e) => ({ id: e.getAttribute('identifier'), href: e.getAttribute('href'), scormtype: e.getAttributeNS(ADLCP, 'scormtype') })),
        files: all('file').map((e) => decodeURIComponent(e.getAttribute('href'))),
      };
    }, xml);
  } finally {
    await page.close();
  }
}

test('each package’s manifest is SCORM 1.2, and lists every file of its ZIP, and only those', async () => {
  for (const slug of CHAPTERS) {
    const zip = packages[slug];
    const manifest = await readManifest(new TextDecoder().decode(zip['imsmanifest.xml']));
    assert.equal(manifest.error, null, `${slug}: the manifest parses as XML`);
    assert.deepEqual(manifest.schema, ['ADL SCORM']);
    assert.deepEqual(manifest.schemaversion, ['1.2']);
    assert.equal(manifest.organizations, 1);
    assert.equal(manifest.resources.length, 1);
    assert.deepEqual(manifest.items, [manifest.resources[0].id], 'one item, launching the one resource');
    assert.equal(manifest.resources[0].scormtype, 'sco');
    assert.equal(manifest.resources[0].href, `${slug}/index.html`);
    const inZip = Object.keys(zip).filter((path) => path !== 'imsmanifest.xml').sort();
    assert.deepEqual([...manifest.files].sort(), inZip, `${slug}: the manifest's files are the ZIP's`);
    assert.ok(inZip.includes('phasebook-scorm.js') && inZip.some((p) => p.startsWith('_astro/')));
    assert.ok(!inZip.some((p) => p.startsWith('pagefind/') || (p.endsWith('index.html') && p !== `${slug}/index.html`)), `${slug}: no other page, no search index`);
    console.log(`${slug}.zip: ${inZip.length + 1} files, manifest lists ${manifest.files.length}`);
  }
});

test('inside a test LMS under /lms/course-7/sco-3/, two solved exercises reach the LMS as the score, incomplete, committed; every request stays in the package', async () => {
  const page = await browser.context.newPage();
  const watch = watchPage(page);
  try {
    await page.goto(`${server.origin}/lms/host.html`);
    const frame = await (async () => {
      for (;;) {
        const found = page.frames().find((f) => f.url().endsWith(`${SCO}${LAUNCH}`));
        if (found) return found;
        await page.waitForEvent('framenavigated');
      }
    })();
    await frame.waitForSelector('body[data-cells-ready]', { state: 'attached' });
    await page.waitForFunction(() => window.transcript.some(([name]) => name === 'LMSInitialize'), null);
    const exercises = await frame.locator('[data-exercise]').count();
    assert.ok(exercises >= 2, 'the chapter has exercises');

    const period = await answer(frame, 'period-at-omega-5', String((2 * Math.PI) / 5));
    assert.equal(period.result, 'passed', period.text);
    const drive = await answer(frame, 'drive-line', String(8 / (2 * Math.PI)));
    assert.equal(drive.result, 'passed', drive.text);

    const expected = String(Math.round((10_000 * 2) / exercises) / 100);
    await page.waitForFunction((score) => window.API.cmi.core.score.raw === score, expected);
    const lms = await page.evaluate(() => ({
      raw: window.API.cmi.core.score.raw,
      min: window.API.cmi.core.score.min,
      max: window.API.cmi.core.score.max,
      status: window.API.cmi.core.lesson_status,
      transcript: window.transcript,
    }));
    assert.equal(lms.raw, expected, `2 of ${exercises} solved`);
    assert.equal(lms.min, '0');
    assert.equal(lms.max, '100');
    assert.equal(lms.status, 'incomplete');
    assert.equal(lms.transcript.filter(([name]) => name === 'LMSInitialize').length, 1);
    const sets = lms.transcript.filter(([name]) => name === 'LMSSetValue');
    assert.deepEqual(sets.filter(([, element]) => element === 'cmi.core.score.raw').map(([, , value]) => value), [String(Math.round(10_000 / exercises) / 100), expected]);
    // Every change is committed: after the last value set, a commit.
    const lastSet = lms.transcript.findLastIndex(([name]) => name === 'LMSSetValue');
    assert.ok(lms.transcript.slice(lastSet).some(([name]) => name === 'LMSCommit'), 'LMSCommit after the last change');
    assert.equal(await frame.locator('[data-scorm-note]').count(), 0, 'no complaint when the LMS takes everything');

    // Leaving the chapter finishes the session.
    await page.evaluate(() => document.querySelector('iframe').remove());
    await page.waitForFunction(() => window.transcript.some(([name]) => name === 'LMSFinish'), null);
    console.log(`The LMS received (${exercises} exercises in the chapter):`);
    for (const call of await page.evaluate(() => window.transcript)) console.log(`  ${call[0]}(${call.slice(1).map((v) => `'${v}'`).join(', ')})`);
    console.log(`  cmi.core.score.raw = ${lms.raw}, score.min = ${lms.min}, score.max = ${lms.max}, lesson_status = ${lms.status} (before LMSFinish)`);

    const outside = watch.requests.filter((url) => {
      const { origin, pathname } = new URL(url);
      if (origin !== server.origin) return !url.startsWith('data:') && !url.startsWith('blob:');
      return !pathname.startsWith(SCO) && pathname !== '/lms/host.html' && pathname !== '/lms/scorm12.min.js';
    });
    assert.deepEqual(outside, [], 'every request of the chapter is inside its package');
    assert.ok(watch.requests.some((url) => url.includes(`${SCO}_astro/`)), 'the chapter’s scripts came from the package');
    assert.deepEqual(watch.problems, []);
  } finally {
    await page.close();
  }
});

test('an LMS that refuses values is told of once, politely, in the page, and the exercise still grades', async () => {
  const page = await browser.context.newPage();
  const watch = watchPage(page);
  try {
    await page.goto(`${server.origin}/lms/refusing.html`);
    await page.waitForFunction(() => window.calls > 0, null);
    const frame = page.frames().find((f) => f.url().endsWith(`${SCO}${LAUNCH}`));
    assert.ok(frame);
    const period = await answer(frame, 'period-at-omega-5', String((2 * Math.PI) / 5));
    assert.equal(period.result, 'passed', period.text);
    const notes = frame.locator('[data-scorm-note]');
    assert.equal(await notes.count(), 1, 'said once, however many calls were refused');
    assert.match(await notes.textContent(), /error 351: Not implemented here.*not lost/);
    assert.ok(await page.evaluate(() => window.calls) > 3);
    assert.deepEqual(await axeViolations(frame), [], 'the chapter with its note passes axe');
    assert.deepEqual(watch.problems, []);
  } finally {
    await page.close();
  }
});

test('the launch page opened on its own, with no LMS, grades an exercise and says nothing of SCORM', async () => {
  const page = await browser.context.newPage();
  const watch = watchPage(page);
  try {
    await page.goto(`${server.origin}${SCO}${LAUNCH}`);
    await page.waitForSelector('body[data-cells-ready]', { state: 'attached' });
    const drive = await answer(page, 'drive-line', String(8 / (2 * Math.PI)));
    assert.equal(drive.result, 'passed', drive.text);
    assert.equal(await exercise(page, 'drive-line').getAttribute('data-exercise-state'), 'solved');
    assert.equal(await page.locator('[data-scorm-note]').count(), 0);
    assert.deepEqual(await axeViolations(page), [], 'the packaged page (no search box, links to other pages kept as text) passes axe at 1280 px');
    assert.deepEqual(watch.problems, []);
  } finally {
    await page.close();
  }
});
