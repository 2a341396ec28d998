/**
 * The inline script of a chapter's "On this page" lists
 * (site/components/OnThisPage.astro), kept as text so that the page's
 * Content-Security-Policy (csp.ts) can allow it by hash.
 *
 * It marks the section being read, `aria-current="location"` on its links,
 * with IntersectionObservers only: no scroll handler, and nothing that asks
 * for a layout. A section is being read once its heading has passed the
 * reading line, a third of the way down the view. The observed box reaches
 * far above the view, so that every heading already scrolled past stays
 * inside it and a jump across many sections changes what it holds. At the
 * end of a chapter, whose last sections may be too short ever to reach the
 * line, the last heading in view counts.
 *
 * A section picked from the menu is where the reader goes: the menu, left
 * above them, closes.
 */
export const readingPositionScript = `(() => {
  const links = [...document.querySelectorAll('a[data-section-link]')];
  const menu = document.querySelector('[data-section-menu]');
  menu?.addEventListener('click', (event) => {
    if (event.target instanceof Element && event.target.closest('a')) menu.open = false;
  });
  if (!links.length || typeof IntersectionObserver !== 'function') return;
  const headings = [...new Set(links.map((a) => a.dataset.sectionLink))].map((id) => document.getElementById(id)).filter(Boolean);
  const end = document.querySelector('.chapter-nav-bottom');
  const passed = new Set();
  const inView = new Set();
  let atEnd = false;
  let current = null;
  const mark = () => {
    let last = null;
    for (const heading of headings) if (passed.has(heading) || (atEnd && inView.has(heading))) last = heading;
    const id = last ? last.id : '';
    if (id === current) return;
    current = id;
    for (const link of links) {
      if (link.dataset.sectionLink === id) link.setAttribute('aria-current', 'location');
      else link.removeAttribute('aria-current');
    }
  };
  const note = (set, entry) => (entry.isIntersecting ? set.add(entry.target) : set.delete(entry.target));
  const line = new IntersectionObserver((entries) => {
    for (const entry of entries) note(passed, entry);
    mark();
  }, { rootMargin: '1000000px 0px -67% 0px' });
  const view = new IntersectionObserver((entries) => {
    for (const entry of entries) {
      if (entry.target === end) atEnd = entry.isIntersecting;
      else note(inView, entry);
    }
    mark();
  });
  for (const heading of headings) {
    line.observe(heading);
    view.observe(heading);
  }
  if (end) view.observe(end);
})();`;
