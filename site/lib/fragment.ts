/**
 * The inline script at the end of every page's body, kept as text so that
 * the page's Content-Security-Policy (csp.ts) can allow it by hash.
 *
 * A link to a place in a chapter (`/kepler/#cell-stars`) shows that place
 * from the first paint. Browsers scroll to the fragment only once the page
 * has loaded, every module and font in: until then the reader would watch
 * the top of the chapter, then a jump. Here the whole text is parsed and
 * styled, so the place is where it will stay. A reload or a return keeps
 * the place the browser restores, and a reader who has already scrolled
 * keeps theirs.
 */
export const fragmentScript = `(() => {
  if (location.hash.length < 2 || scrollY !== 0) return;
  const navigation = performance.getEntriesByType?.('navigation')[0];
  if (navigation && navigation.type !== 'navigate') return;
  let target;
  try {
    target = document.getElementById(decodeURIComponent(location.hash.slice(1)));
  } catch {
    return; // a malformed escape in the fragment
  }
  target?.scrollIntoView();
})();`;
