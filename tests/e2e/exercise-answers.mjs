/**
 * Answering an exercise in the page as a reader does: reach it, type a
 * number or write a cell, and read the verdict it gives. Shared by
 * exercises.test.mjs and the chapters' own e2e files.
 */
import { typeIntoCell, waitForOutput } from './fixture.mjs';

export const exercise = (page, id) => page.locator(`[data-exercise="${id}"]`);

/** Scrolls to the exercise and waits until it is live. */
export async function reach(page, id) {
  await exercise(page, id).scrollIntoViewIfNeeded();
  await page.waitForSelector(`[data-exercise="${id}"][data-exercise-live] [data-exercise-feedback]`, { state: 'attached' });
}

/** Runs `act`, then waits for the exercise's new verdict and returns its text and result. */
export async function verdictAfter(page, id, act) {
  await exercise(page, id).evaluate((root) => delete root.dataset.exerciseResult);
  await act();
  await page.waitForFunction((target) => {
    const result = document.querySelector(`[data-exercise="${target}"]`)?.getAttribute('data-exercise-result');
    return result === 'passed' || result === 'failed' || (result === 'problem' && !/Checking/.test(document.querySelector(`[data-exercise="${target}"] [data-exercise-feedback]`)?.textContent ?? ''));
  }, id);
  const root = exercise(page, id);
  return { result: await root.getAttribute('data-exercise-result'), text: (await root.locator('[data-exercise-feedback]').textContent()) ?? '' };
}

/** Types a number into the exercise's labelled field and presses Enter. */
export async function answer(page, id, text) {
  await reach(page, id);
  return verdictAfter(page, id, async () => {
    const field = exercise(page, id).getByLabel(/Your answer/);
    await field.fill(text);
    await field.press('Enter');
  });
}

/** Writes `source` into the answer cell, runs it, and checks the code. */
export async function answerCode(page, id, cellName, source) {
  await reach(page, id);
  await typeIntoCell(page, cellName, source);
  // The check reads the cell's value as it is: wait until the edit has run (its value shown, or its error).
  const value = source.slice(source.indexOf('=') + 1).trim();
  await waitForOutput(page, cellName, (out) => out.includes(value) || out === '').catch(() => undefined);
  return verdictAfter(page, id, () => exercise(page, id).getByRole('button', { name: 'Check my code' }).click());
}
