/**
 * Shareable edits (cells/share-*.ts): a reader's edits travel in a
 * link's fragment to a fresh browser, which shows them marked and runs none
 * of their code until asked; Back to the original leaves them; Keep these
 * edits asks before replacing the reader's own; a damaged link is a message
 * over the original chapter. Links of typical edits are measured.
 */
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { after, before, test } from 'node:test';
import { launchBrowser } from './browser.mjs';
import { addedCells, cell, cellsReady, firstViewReady, openChapter, openSite, outputOf, typeIntoAddedCell, typeIntoCell, waitForOutput, watchPage } from './fixture.mjs';

/** @type {Awaited<ReturnType<typeof openSite>>} */
let site;
/** A second profile on a new temp dir: the browser the link is sent to. */
/** @type {Awaited<ReturnType<typeof launchBrowser>>} */
let friend;
before(async () => {
  site = await openSite({ permissions: ['clipboard-read', 'clipboard-write'] });
  friend = await launchBrowser();
});
after(async () => {
  await friend?.close();
  await site?.close();
});

// The playground (content/playground.mdx): H(t, q, p) = p²/2 + ω²(1 + u cos γt) q²/2 − f q cos(κt + β) with
// (u, γ, β, κ, ω, f) = (0.3, 21.7, 0.2, 8, 10, 20) and (q, p) = (2, 0). Its cell H0 is H at t = 0, which by
// that formula is ω²(1 + u) q²/2 − f q cos β (p = 0), plus q⁴/4 when the shared H adds that term.
const H0 = ({ omega = 10, quartic = false, q = 2 } = {}) => {
  const value = omega ** 2 * 1.3 * q ** 2 / 2 - 20 * q * Math.cos(0.2) + (quartic ? q ** 4 / 4 : 0);
  return `H0 = ${Number(value.toPrecision(12))}`;
};
const PARAMS_12 = 'params = ({u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 12, f: 20})';
const H_QUARTIC = 'H = "p^2/2 + omega^2*(1 + u*cos(gamma*t))*q^2/2 - f*q*cos(kappa*t + beta) + q^4/4"';
/** Sets a flag on the page when it runs: the test of "nothing shared runs until asked". */
const ADDED = 'mine = (window.sharedCodeRan = true, 2 * params.omega)';

const AXE = readFileSync(createRequire(import.meta.url).resolve('axe-core/axe.min.js'), 'utf8');
/**
 * axe's violations in the share bar (its panel, banner or message open) and the cells' toolbars, as in
 * accessibility.test.mjs. Only these: an editor mounted on a long line is a scroller axe flags, which is the
 * editor's matter, not sharing's (accessibility.test.mjs checks pages whose editors are not mounted).
 */
async function axeViolations(page) {
  await page.evaluate(AXE);
  return page.evaluate(async () =>
    (await window.axe.run({ include: ['[data-share-edits]', '.cell-toolbar'] }, { resultTypes: ['violations'] })).violations.map(
      (v) => `${v.id} (${v.nodes.length}): ${v.nodes[0]?.target.join(' ')}`,
    ),
  );
}

const banner = (page) => page.locator('[data-share-banner]');

/** Adds a cell below `anchor`, types `source` into it and runs it. */
async function addCell(page, anchor, source) {
  await cell(page, anchor).locator('[data-cell-add]').click();
  await typeIntoAddedCell(page, source);
}

/** Presses Share (by keyboard, as it must work that way) and returns the link shown, after checking its stated length. */
async function share(page) {
  await page.locator('[data-share-button]').focus();
  await page.keyboard.press('Enter');
  const field = page.locator('[data-share-link]');
  await field.waitFor();
  const url = await field.inputValue();
  assert.equal(await page.locator('[data-share-length]').textContent(), `${url.length} characters`);
  return url;
}

/** The keys of this book's saved edits and added cells in the page's storage. */
const savedKeys = (page) => page.evaluate(() => Object.keys(localStorage).filter((key) => /:(edit|added|running)(:|$)/.test(key)));

/** Text a cell shows: its editor's, or the static code's. */
const shownText = (page, id) => cell(page, id).locator('.cell-editor').textContent();

/** @type {string} */
let link;

test('the Share button puts changed and added cells in a link, copied and shown with its length', async () => {
  const { page, problems } = await openChapter(site, '/playground/');
  // With nothing changed there is nothing to share, and the page says so.
  await page.locator('[data-share-button]').click();
  await page.waitForFunction(() => /not changed any cell/.test(document.querySelector('[data-share-panel] [role=status]')?.textContent ?? ''));

  await typeIntoCell(page, 'H', H_QUARTIC);
  await typeIntoCell(page, 'params', PARAMS_12);
  await waitForOutput(page, 'H0', (text) => text === H0({ omega: 12, quartic: true }));
  await addCell(page, 'params', ADDED);
  await page.waitForFunction(() => document.querySelector('[data-cell-added] [data-cell-output]')?.textContent === 'mine = 24');

  link = await share(page);
  const url = new URL(link);
  assert.equal(url.origin + url.pathname, `${site.origin}/playground/`);
  assert.match(url.hash, /^#share=1\.[A-Za-z0-9_-]+$/);
  assert.match(await page.locator('[data-share-panel] [role=status]').textContent(), new RegExp(`Link copied: your edits of 3 cells, ${link.length} characters`));
  assert.equal(await page.evaluate(() => navigator.clipboard.readText()), link);
  assert.ok(link.length < 2000, `a link of three edits is ${link.length} characters`);
  console.log(`# link of H, params and an added cell: ${link.length} characters`);
  assert.deepEqual(await axeViolations(page), []);
  assert.deepEqual(problems, []);
  await page.close();
});

test('in a fresh profile the link shows the edits, marked, runs none of their code until asked, and goes back to the original', async () => {
  assert.ok(link, 'the link of the test before');
  const page = await friend.context.newPage();
  const { problems, requests } = watchPage(page);
  await page.goto(link);
  await cellsReady(page);

  await banner(page).waitFor();
  assert.match(await banner(page).textContent(), /You are viewing shared edits of 3 cells\./);
  assert.deepEqual(await banner(page).locator('[data-share-goto]').allTextContents(), ['H', 'params', 'added cell 1']);
  // Shown, marked "shared" and "not run yet"; the chapter's original runs.
  assert.equal(await shownText(page, 'params'), PARAMS_12);
  assert.equal(await shownText(page, 'H'), H_QUARTIC);
  for (const id of ['H', 'params']) {
    assert.equal(await cell(page, id).getAttribute('data-cell-shared'), '');
    assert.equal(await cell(page, id).locator('[data-cell-status]').textContent(), 'not run yet');
    assert.equal(await cell(page, id).locator('.cell-shared-label').textContent(), 'shared');
  }
  assert.equal(await addedCells(page).count(), 1);
  assert.equal(await addedCells(page).locator('.cell-editor').textContent(), ADDED);
  assert.equal(await outputOf(page, 'H0'), H0());
  assert.equal(await page.evaluate(() => window.sharedCodeRan), undefined);
  // Nothing of the link is saved in this browser.
  assert.deepEqual(await savedKeys(page), []);
  assert.deepEqual(await axeViolations(page), []);

  // The banner's list takes the reader to a cell without touching the link.
  await banner(page).locator('[data-share-goto]', { hasText: 'params' }).click();
  assert.equal(new URL(page.url()).hash, new URL(link).hash);

  await banner(page).locator('[data-share-run]').click();
  await waitForOutput(page, 'H0', (text) => text === H0({ omega: 12, quartic: true }));
  await page.waitForFunction(() => document.querySelector('[data-cell-added] [data-cell-output]')?.textContent === 'mine = 24');
  assert.equal(await page.evaluate(() => window.sharedCodeRan), true);
  assert.equal(await banner(page).locator('[data-share-run]').count(), 0);
  assert.equal(await page.evaluate(() => document.activeElement?.hasAttribute('data-share-keep')), true);
  assert.match(await banner(page).textContent(), /shared edits are running/);
  assert.deepEqual(await savedKeys(page), []);

  // One click back: the chapter without the link's edits.
  await banner(page).locator('[data-share-back]').click();
  await page.waitForURL(`${new URL(link).origin}/playground/`);
  await cellsReady(page);
  assert.equal(await banner(page).isVisible(), false);
  assert.equal(await page.locator('[data-cell-shared]').count(), 0);
  assert.equal(await addedCells(page).count(), 0);
  assert.equal(await outputOf(page, 'H0'), H0());
  assert.equal(await page.evaluate(() => window.sharedCodeRan), undefined);
  assert.deepEqual(await savedKeys(page), []);

  // The fragment never leaves the browser: no request carries it.
  assert.equal(requests.filter((url) => url.includes('share=')).length, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test('Keep these edits asks before replacing the reader’s own saved edits, and keeps them on yes', async () => {
  assert.ok(link, 'the link of the test before');
  const page = await friend.context.newPage();
  const { problems } = watchPage(page);
  await page.goto(`${site.origin}/playground/`);
  await cellsReady(page);
  await typeIntoCell(page, 'initial', 'initial = [1, 0]');
  await waitForOutput(page, 'H0', (text) => text === H0({ q: 1 }));
  const editKeys = async () => (await savedKeys(page)).filter((key) => key.includes(':edit:'));
  const own = await editKeys();
  assert.equal(own.length, 1);

  // Pasting the link on the same page changes only the fragment: the page loads for it.
  await page.goto(link);
  await page.waitForFunction(() => document.querySelector('[data-share-banner]')?.hidden === false);
  await cellsReady(page);
  // The reader's own edit is not shown in the shared view, and is not touched.
  assert.equal(await outputOf(page, 'H0'), H0());
  await banner(page).locator('[data-share-keep]').click();
  const confirm = banner(page).locator('.share-confirm');
  await confirm.waitFor();
  assert.match(await confirm.textContent(), /saved edits of your own in 1 cell of this chapter \(initial\)\. Keeping the shared edits replaces all of them\./);
  assert.deepEqual(await axeViolations(page), []);
  // The keyboard lands on Cancel: Enter pressed at once replaces nothing.
  assert.equal(await page.evaluate(() => document.activeElement?.hasAttribute('data-share-cancel')), true);
  await page.keyboard.press('Enter');
  assert.equal(await confirm.isVisible(), false);
  assert.deepEqual(await editKeys(), own);

  await banner(page).locator('[data-share-run]').click();
  await waitForOutput(page, 'H0', (text) => text === H0({ omega: 12, quartic: true }));
  await banner(page).locator('[data-share-keep]').click();
  await confirm.locator('[data-share-replace]').click();
  await page.waitForURL(`${site.origin}/playground/`);
  await cellsReady(page);
  // Now the reader's: they ran, so they run; their own edit of initial is gone.
  assert.equal(await banner(page).isVisible(), false);
  await waitForOutput(page, 'H0', (text) => text === H0({ omega: 12, quartic: true }));
  assert.equal(await outputOf(page, 'initial'), 'initial = [2, 0]');
  await page.waitForFunction(() => document.querySelector('[data-cell-added] [data-cell-output]')?.textContent === 'mine = 24');
  assert.equal((await savedKeys(page)).filter((key) => key.endsWith(':edit:initial')).length, 0);
  assert.deepEqual(problems, []);
  await page.close();
});

test('shared edits kept without running stay drafts: shown on the next visit, not run', async () => {
  const fresh = await launchBrowser();
  try {
    const page = await fresh.context.newPage();
    const { problems } = watchPage(page);
    await page.goto(link);
    await banner(page).waitFor();
    await cellsReady(page);
    // No saved edits of their own here: Keep does not need to ask.
    await banner(page).locator('[data-share-keep]').click();
    await page.waitForURL(`${site.origin}/playground/`);
    await cellsReady(page);
    assert.equal(await shownText(page, 'params'), PARAMS_12);
    assert.equal(await cell(page, 'params').locator('[data-cell-status]').textContent(), 'not run yet');
    assert.equal(await outputOf(page, 'H0'), H0());
    assert.equal(await page.evaluate(() => window.sharedCodeRan), undefined);
    assert.deepEqual(problems, []);
  } finally {
    await fresh.close();
  }
});

test('a damaged, cut, foreign or future link shows a clear message over the original chapter', async () => {
  assert.ok(link, 'the link of the test before');
  const fragment = new URL(link).hash.slice(1);
  // Without the edits kept by the test before: the chapter as it is without the link is then its original.
  const clear = await friend.context.newPage();
  await clear.goto(`${site.origin}/`);
  await clear.evaluate(() => localStorage.clear());
  await clear.close();
  const cases = [
    [`${site.origin}/playground/#share=1.not*base64`, /damaged/],
    [`${site.origin}/playground/#${fragment.slice(0, -12)}`, /damaged/],
    [`${site.origin}/playground/#${fragment.replace(/^share=1\./, 'share=7.')}`, /newer version of Phasebook/],
    [`${site.origin}/introduction/#${fragment}`, /another chapter \(“playground”\)/],
  ];
  for (const [url, message] of cases) {
    const page = await friend.context.newPage();
    const { problems } = watchPage(page);
    await page.goto(url);
    await firstViewReady(page);
    const alert = page.locator('[data-share-banner][role=alert]');
    await alert.waitFor();
    assert.match(await alert.textContent(), message);
    assert.match(await alert.textContent(), /The chapter is shown without the link’s edits\./);
    assert.equal(await page.locator('[data-cell-shared]').count(), 0);
    if (message.source === 'damaged') assert.deepEqual(await axeViolations(page), []);
    if (url.includes('/playground/')) {
      await cellsReady(page);
      assert.equal(await outputOf(page, 'H0'), H0());
      assert.equal(await addedCells(page).count(), 0);
    }
    assert.deepEqual(problems, [], url);
    await page.close();
  }
});

test('links of typical edits: one parameter cell, one H, an added cell, each under 2000 characters', async () => {
  const lengths = {};
  const edits = {
    'one parameter cell': (page) => typeIntoCell(page, 'params', PARAMS_12),
    'one H': (page) => typeIntoCell(page, 'H', H_QUARTIC),
    'an added cell': (page) => addCell(page, 'params', 'lambda = 2 * params.omega'),
  };
  for (const [name, edit] of Object.entries(edits)) {
    const { page, problems } = await openChapter(site, '/playground/');
    await edit(page);
    await page.waitForFunction(() => !document.querySelector('[data-cell-unrun]'));
    const url = await share(page);
    lengths[name] = url.length;
    assert.ok(url.length < 2000, `${name}: ${url.length} characters`);
    assert.deepEqual(problems, []);
    await page.close();
  }
  console.log(`# link lengths on ${site.origin} (characters): ${JSON.stringify(lengths)}`);
});

test('a cell far down the chapter, not started yet when Share is pressed, still goes in the link with its saved edit', async () => {
  const UNFORCED = 'unforced = canonicalEquations({dof: 1, hamiltonian: H, params: {...params, f: 0, u: 0}})';
  const { page, problems } = await openChapter(site, '/introduction/');
  await typeIntoCell(page, 'unforced', UNFORCED);
  await page.waitForFunction(() => !document.querySelector('[data-cell-unrun]'));
  // A new visit at the top of the chapter: the cell is far below and waits to be scrolled to.
  await page.goto(`${site.origin}/introduction/`);
  await firstViewReady(page);
  assert.equal(await cell(page, 'unforced').getAttribute('data-cell-state'), 'waiting');
  const url = await share(page);
  assert.match(await page.locator('[data-share-panel] [role=status]').textContent(), /your edits of 1 cell,/);
  assert.deepEqual(problems, []);
  await page.close();

  const shared = await friend.context.newPage();
  const watched = watchPage(shared);
  await shared.goto(url);
  await banner(shared).waitFor();
  assert.deepEqual(await banner(shared).locator('[data-share-goto]').allTextContents(), ['unforced']);
  await banner(shared).locator('[data-share-goto]').click();
  await shared.waitForFunction(() => document.querySelector('[data-cell="unforced"]')?.dataset.cellState !== 'waiting');
  assert.equal(await shownText(shared, 'unforced'), UNFORCED);
  assert.deepEqual(watched.problems, []);
  await shared.close();
});
