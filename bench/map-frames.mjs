/**
 * Part h of `npm run bench:browser`: the standard map's portrait
 * (/standard-map/) as a reader drags its K slider, one step of K every
 * frame, so that every frame redraws the whole portrait at its default size
 * (1024 orbits of 300 iterates): the frame rate, and the main thread's work
 * per frame from DevTools' TaskDuration.
 */

/** In the page: moves the slider by one step every frame for `ms`, and returns the frames' times and the redraws seen. */
function sweepInPage(ms) {
  return new Promise((resolve) => {
    const root = document.querySelector('[data-widget="standard-map"]');
    const slider = root.querySelector('input[type="range"]');
    const stamps = [];
    const seen = new Set();
    const start = performance.now();
    let K = 0.5;
    const frame = (t) => {
      stamps.push(t);
      seen.add(root.dataset.k);
      K = K >= 2.5 ? 0.5 : K + 0.001;
      slider.value = String(K);
      slider.dispatchEvent(new Event('input', { bubbles: true }));
      if (performance.now() - start < ms) requestAnimationFrame(frame);
      else resolve({ stamps, redraws: seen.size, points: Number(root.dataset.points) });
    };
    requestAnimationFrame(frame);
  });
}

/**
 * Opens the chapter, waits for the portrait, warms up for `warmUpMs`, then sweeps K for `ms`.
 * Returns the rAF stamps, the number of distinct K drawn, the points of the last portrait, and the
 * main thread's busy share over the sweep.
 */
export async function mapSweep(context, origin, { ms, warmUpMs }) {
  const page = await context.newPage();
  const session = await context.newCDPSession(page);
  await session.send('Performance.enable');
  await page.goto(`${origin}/standard-map/`);
  // The portrait's cell runs as it comes near the view.
  await page.locator('[data-cell="portrait"]').scrollIntoViewIfNeeded();
  await page.waitForSelector('[data-widget="standard-map"][data-ready]');
  await page.evaluate(sweepInPage, warmUpMs);
  const metric = async (name) => (await session.send('Performance.getMetrics')).metrics.find((m) => m.name === name)?.value ?? NaN;
  const busyBefore = await metric('TaskDuration');
  const wallBefore = Date.now();
  const result = await page.evaluate(sweepInPage, ms);
  const busy = ((await metric('TaskDuration')) - busyBefore) / ((Date.now() - wallBefore) / 1000);
  await page.close();
  return { ...result, busy };
}
