/**
 * The book on a phone, checked by geometry (getBoundingClientRect), not by
 * screenshots: the audit that the sweep of every page runs at 360 and 390 px
 * (every-page.mjs), and phone-layout.test.mjs shows can fail.
 *
 * - Nothing in the text column reaches past the screen's edges unless it
 *   lies inside a box that scrolls sideways, which a keyboard can focus
 *   and which shows that it scrolls (a shadow at the edge that has more).
 * - Display math and code blocks fit, or are such boxes.
 * - Every table shows all its columns: each header cell is visible, within
 *   the screen or within the scrolling width of its box, and cut by no box
 *   that hides what overflows it.
 * - Charts keep their axis text at 11 CSS px or more (the canvas is drawn
 *   at its displayed size, never scaled down), and so does text in SVG.
 */

/** The smallest text a reader must be able to read, CSS px. */
export const SMALLEST_TEXT = 11;

/**
 * Runs in the page: every way the text column fails a phone, as lines of
 * text (empty when it does not). Refers to nothing outside itself.
 * @param {number} smallest
 */
export function audit(smallest) {
  const problems = [];
  const vw = document.documentElement.clientWidth;
  const column = document.querySelector('main.page');
  if (!column) return ['no main.page'];
  const name = (el) => {
    const cell = el.closest('[data-cell]')?.getAttribute('data-cell');
    const cls = typeof el.className === 'string' && el.className ? `.${el.className.trim().split(/\s+/).join('.')}` : '';
    return `${el.tagName.toLowerCase()}${cls}${cell ? ` in cell ${cell}` : ''}`;
  };
  const shown = (el) => {
    if (el.closest('details:not([open]) > :not(summary)')) return false;
    const style = getComputedStyle(el);
    if (style.visibility === 'hidden' || style.display === 'none') return false;
    const r = el.getBoundingClientRect();
    return r.width > 0 && r.height > 0 && el.getClientRects().length > 0;
  };
  /** Hidden on purpose for sighted readers: clipped to nothing, for screen readers. */
  const screenReaderOnly = (el) => {
    for (let e = el; e && e !== column; e = e.parentElement) {
      const s = getComputedStyle(e);
      if (s.position === 'absolute' && (s.clipPath !== 'none' || s.clip !== 'auto')) return true;
    }
    return false;
  };
  const scrollsSideways = (el) => {
    const s = getComputedStyle(el);
    return (s.overflowX === 'auto' || s.overflowX === 'scroll') && el.scrollWidth > el.clientWidth + 1;
  };
  const cue = (box) => /gradient/.test(getComputedStyle(box).backgroundImage);
  /**
   * A scroll box a reader can find and use: it shows that it scrolls (shadows
   * drawn as gradients), and a keyboard can scroll it, being focusable itself
   * or holding the focusable control that overflows (focus brings it into view).
   */
  const usable = (box, el = null) => {
    if (!cue(box)) return false;
    if (box.tabIndex >= 0) return true;
    const control = el?.closest('a[href], button, input, select, textarea, [tabindex]');
    return !!control && box.contains(control);
  };
  const scroller = (el) => {
    for (let e = el.parentElement; e && e !== document.body; e = e.parentElement) if (scrollsSideways(e)) return e;
    return null;
  };

  // 1. Nothing overflows the screen except inside a usable scroll box. What a box hides
  // (overflow: hidden, as KaTeX's stretchy glyphs) or scrolls is cut to that box first.
  const reported = new Set();
  for (const el of column.querySelectorAll('*')) {
    if (!shown(el) || screenReaderOnly(el)) continue;
    const r = el.getBoundingClientRect();
    let [left, right] = [r.left, r.right];
    for (let e = el.parentElement; e && e !== document.body && left < right; e = e.parentElement) {
      const s = getComputedStyle(e);
      if (s.overflowX === 'visible') continue;
      const b = e.getBoundingClientRect();
      // (a box that does not scroll holds nothing beyond it: what pokes out is the hanging space of wrapped text)
      const beyond = left < b.left - 0.5 || right > b.right + 0.5;
      if (beyond && scrollsSideways(e) && !usable(e, el) && !reported.has(e)) {
        reported.add(e);
        problems.push(`${name(el)} overflows into ${name(e)}, which ${cue(e) ? 'a keyboard cannot scroll' : 'shows no scroll cue'}`);
      }
      [left, right] = [Math.max(left, b.left), Math.min(right, b.right)];
    }
    if (left >= right || (right <= vw + 0.5 && left >= -0.5) || reported.has(el)) continue;
    reported.add(el);
    problems.push(`${name(el)} reaches ${Math.round(left)}…${Math.round(right)} px on a ${vw} px screen, with nothing to scroll it`);
  }

  // 2. Display math and code fit, or scroll in a usable box.
  for (const el of column.querySelectorAll('.katex-display, pre')) {
    if (!shown(el) || el.scrollWidth <= el.clientWidth + 1) continue;
    if (!scrollsSideways(el)) problems.push(`${name(el)} is wider than its box and does not scroll`);
    else if (!usable(el)) problems.push(`${name(el)} scrolls but ${el.tabIndex < 0 ? 'a keyboard cannot focus it' : 'shows no scroll cue'}`);
  }

  // 3. Every column of every table can be seen.
  for (const table of column.querySelectorAll('table')) {
    if (!shown(table)) continue;
    const headers = [...(table.tHead?.rows[0] ?? table.rows[0])?.cells ?? []];
    for (const th of headers) {
      const label = `column "${th.textContent.trim()}" of ${name(table)}`;
      if (!shown(th)) {
        problems.push(`${label} is hidden`);
        continue;
      }
      const r = th.getBoundingClientRect();
      for (let e = th.parentElement; e && e !== document.body; e = e.parentElement) {
        const s = getComputedStyle(e);
        const b = e.getBoundingClientRect();
        if (s.overflowX === 'auto' || s.overflowX === 'scroll') {
          // inside a scroll box: within its scrolling width, and the box must be usable if it scrolls
          const start = b.left - e.scrollLeft;
          if (r.left < start - 0.5 || r.right > start + e.scrollWidth + 0.5) problems.push(`${label} lies beyond the scrolling width of ${name(e)}`);
          if (scrollsSideways(e) && !usable(e)) problems.push(`${label} is in ${name(e)}, which scrolls without a cue or keyboard access`);
          break;
        }
        if ((s.overflowX === 'hidden' || s.overflowX === 'clip') && (r.left < b.left - 0.5 || r.right > b.right + 0.5)) {
          problems.push(`${label} is cut off by ${name(e)} (overflow: ${s.overflowX})`);
          break;
        }
      }
      if (r.left < -0.5 || r.right > vw + 0.5) {
        if (!scroller(th)) problems.push(`${label} is off the screen with nothing to scroll it`);
      }
    }
  }

  // 4. Chart and SVG text at 11 px or more.
  for (const canvas of column.querySelectorAll('[data-widget="chart"] canvas')) {
    if (!shown(canvas)) continue;
    const drawnAt = parseFloat(canvas.style.width);
    const scale = canvas.getBoundingClientRect().width / drawnAt;
    const font = Number(canvas.dataset.fontPx) * scale;
    if (!(font >= smallest - 0.01)) problems.push(`${name(canvas.closest('figure'))} "${canvas.getAttribute('aria-label')}": axis text ${font.toFixed(1)} px`);
  }
  for (const text of column.querySelectorAll('svg text')) {
    if (!shown(text)) continue;
    const svg = text.ownerSVGElement;
    const box = svg.viewBox.baseVal;
    const scale = box && box.width ? svg.getBoundingClientRect().width / box.width : 1;
    const font = parseFloat(getComputedStyle(text).fontSize) * scale;
    if (font < smallest - 0.01) problems.push(`text "${text.textContent}" in ${name(svg)} is ${font.toFixed(1)} px`);
  }
  return problems;
}

/**
 * Lets the layout settle as for a reader who has read the whole page: the
 * fonts in; every part of the page shown once, a viewport at a time, with
 * the frames in which the page marks the boxes that scroll
 * (cells/scrollables.ts: prose far from the view is not laid out
 * until it comes near, global.css); then every block laid out at once, so
 * that the audit can measure them all.
 * @param {import('playwright-core').Page} page
 */
export async function settle(page) {
  await page.evaluate(() => document.fonts.ready);
  await page.evaluate(async () => {
    const frames = () => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(done, 20))));
    for (let y = 0; y < document.documentElement.scrollHeight; y += innerHeight * 0.8) {
      scrollTo(0, y);
      await frames();
    }
    scrollTo(0, 0);
    await frames();
  });
  await page.addStyleTag({ content: 'article[data-chapter] > * { content-visibility: visible !important; }' });
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
}
