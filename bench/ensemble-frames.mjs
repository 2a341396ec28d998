/**
 * Part i of `npm run bench:browser`: the pendulum's ensemble (/liouville/)
 * playing at its default size, 20 000 points and the refined boundary moved
 * in its worker and drawn on the page: the frame rate, the frames whose
 * ensemble was new (the worker keeping up), and the main thread's work per
 * frame from DevTools' TaskDuration.
 */

/** In the page: counts frames for `ms`, and the distinct ensemble times drawn among them. */
function watchInPage(ms) {
  return new Promise((resolve) => {
    const root = document.querySelector('[data-cell="blob"] [data-widget="ensemble"]');
    const stamps = [];
    const seen = new Set();
    const start = performance.now();
    const frame = (t) => {
      stamps.push(t);
      seen.add(root.dataset.t);
      if (performance.now() - start < ms) requestAnimationFrame(frame);
      else resolve({ stamps, updates: seen.size, points: Number(root.dataset.points), vertices: Number(root.dataset.vertices), t: Number(root.dataset.t), state: root.dataset.state });
    };
    requestAnimationFrame(frame);
  });
}

/** Opens the chapter, waits for the ensemble to play, warms up for `warmUpMs`, then watches it for `ms`. */
export async function ensembleWatch(context, origin, { ms, warmUpMs }) {
  const page = await context.newPage();
  const session = await context.newCDPSession(page);
  await session.send('Performance.enable');
  await page.goto(`${origin}/liouville/`);
  await page.locator('[data-cell="blob"]').scrollIntoViewIfNeeded();
  await page.waitForSelector('[data-cell="blob"] [data-widget="ensemble"][data-state="playing"]');
  await page.evaluate(watchInPage, warmUpMs);
  const metric = async (name) => (await session.send('Performance.getMetrics')).metrics.find((m) => m.name === name)?.value ?? NaN;
  const busyBefore = await metric('TaskDuration');
  const wallBefore = Date.now();
  const result = await page.evaluate(watchInPage, ms);
  const busy = ((await metric('TaskDuration')) - busyBefore) / ((Date.now() - wallBefore) / 1000);
  await page.close();
  return { ...result, busy };
}
