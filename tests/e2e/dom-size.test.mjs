/**
 * A chapter's DOM stays small enough for a phone to style and lay out
 * (issue 25: 7.8k–10.8k elements made style and layout the bulk of a
 * phone's work), and the code far from the view, which the build leaves
 * plain with its highlighting as data (site/lib/highlight-js.mjs), is
 * coloured once the reader scrolls to it (cells/code-tokens.ts).
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { after, before, test } from 'node:test';
import { pages } from './every-page.mjs';
import { firstViewReady, openSite, watchPage } from './fixture.mjs';
import { DIST } from './server.mjs';

/**
 * Elements in a chapter once its first view has run, the measure Lighthouse's dom-size audit takes. Chosen from
 * the measurements (see the commit): the largest chapter holds ELEMENTS_MEASURED after the change, 9.2k–10.8k before;
 * the budget leaves room for a few more sections, not for the code spans to come back.
 */
const ELEMENT_BUDGET = 11_000;

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
before(async () => (site = await openSite({ viewport: { width: 1280, height: 900 } })));
after(() => site?.close());

const chapters = () => pages().filter((path) => readFileSync(join(DIST, path, 'index.html'), 'utf8').includes('data-chapter'));

test(`every chapter holds at most ${ELEMENT_BUDGET} elements once its first view has run`, async (t) => {
  const counts = [];
  for (const path of chapters()) {
    const page = await site.context.newPage();
    const { problems } = watchPage(page);
    await page.goto(site.origin + path);
    if (await page.evaluate(() => document.querySelector('[data-cell]') !== null)) await firstViewReady(page);
    counts.push([path, await page.evaluate(() => document.getElementsByTagName('*').length)]);
    assert.deepEqual(problems, [], path);
    await page.close();
  }
  t.diagnostic(counts.map(([path, n]) => `${path} ${n}`).join(', '));
  assert.ok(counts.length >= 10, `chapters: ${counts.length}`);
  assert.deepEqual(counts.filter(([, n]) => n > ELEMENT_BUDGET), []);
});

/** In the page: the code of cell `id` as text, whether it still waits for its colours, and its coloured tokens. */
function shownCode(id) {
  const host = document.getElementById(id).querySelector('.cell-editor');
  const code = host.querySelector('pre.cell-code > code');
  return {
    waiting: code?.hasAttribute('data-tokens') ?? false,
    text: code?.textContent ?? null,
    tokens: [...host.querySelectorAll('[class*="tok-"]')].map((span) => `${span.className}:${span.textContent}`),
  };
}

test('code far from the view arrives plain, with all its text, and is coloured once scrolled to, as the editor colours it', async () => {
  const page = await site.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  const last = await page.evaluate(() => [...document.querySelectorAll('[data-cell]')].at(-1).id);
  const before = await page.evaluate(shownCode, last);
  assert.equal(before.waiting, true, 'the last cell waits to be coloured');
  assert.deepEqual(before.tokens, []);
  assert.ok(before.text.length > 20, 'its text is there');

  await page.locator(`#${last} pre.cell-code`).scrollIntoViewIfNeeded();
  await page.waitForFunction((id) => !document.getElementById(id).querySelector('pre.cell-code > code[data-tokens]'), last);
  const coloured = await page.evaluate(shownCode, last);
  assert.equal(coloured.text, before.text);
  assert.ok(coloured.tokens.some((token) => token.startsWith('tok-keyword:') || token.startsWith('tok-variableName')), coloured.tokens.join(' '));

  // The editor, CodeMirror with the same grammar, parses the code in the page on its own: it colours it the same.
  await page.locator(`#${last} pre.cell-code`).focus();
  await page.locator(`#${last} .cm-editor`).waitFor();
  // CodeMirror parses in slices of time, so its last tokens may come a little later on a busy machine: waited for.
  await page.evaluate(`window.shownCode = ${shownCode}`);
  const want = JSON.stringify(coloured.tokens);
  await page.waitForFunction(([id, tokens]) => JSON.stringify(window.shownCode(id).tokens) === tokens, [last, want]).catch(() => {});
  assert.deepEqual((await page.evaluate(shownCode, last)).tokens, coloured.tokens);
  // The first view's code was coloured by the build.
  const first = await page.evaluate(() => document.querySelector('[data-cell]').id);
  assert.ok((await page.evaluate(shownCode, first)).tokens.length > 0);
  assert.deepEqual(problems, []);
  await page.close();
});
