/**
 * Driving the header's search box as a reader does, for the e2e tests.
 */

/** The search box's field. */
export const searchInput = (page) => page.locator('#site-search-input');

/**
 * Types `query` into the search box (focusing it, which loads search) and
 * waits until its status line speaks of that query: the results for it are
 * then on the page. Returns the status line's text.
 * @param {import('playwright-core').Page} page
 * @param {string} query
 */
export async function search(page, query) {
  const input = searchInput(page);
  await input.focus();
  await input.fill(query);
  const status = page.locator('[data-search-status]');
  await page.waitForFunction(
    (q) => document.querySelector('[data-search-status]')?.textContent?.includes(`“${q}”`),
    query,
  );
  return (await status.textContent()) ?? '';
}

/** The results as shown: each chapter's title and address, and its sections' titles, addresses and excerpts (with the marked words apart). */
export function shownResults(page) {
  return page.locator('[data-search-results] > li').evaluateAll((items) =>
    items.map((item) => ({
      title: item.querySelector('.search-page')?.textContent ?? '',
      href: item.querySelector('.search-page')?.getAttribute('href') ?? '',
      sections: [...item.querySelectorAll('.search-section')].map((link) => ({
        title: link.querySelector('.search-section-title')?.textContent ?? '',
        href: link.getAttribute('href') ?? '',
        excerpt: link.querySelector('.search-excerpt')?.textContent ?? '',
        marked: [...link.querySelectorAll('mark')].map((mark) => mark.textContent),
      })),
    })),
  );
}
