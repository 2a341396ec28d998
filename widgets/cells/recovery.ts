/**
 * What the page says when something went wrong: the notice of a page a
 * cell emptied. Rarely needed, so loaded only then (a chunk of its own): a
 * page's first scripts stay small.
 */

/** Shows, over whatever is left, that cell `label` removed the page and that a reload brings it back. */
export function showPageBroken(label: string): void {
  const id = 'phasebook-page-broken';
  if (document.getElementById(id)) return;
  const banner = document.createElement('div');
  banner.id = id;
  banner.setAttribute('role', 'alert');
  banner.style.cssText =
    'position:fixed;inset:1rem 1rem auto;z-index:2147483647;padding:0.8rem 1rem;border:1px solid #a3261b;border-radius:6px;' +
    'background:#fbeceb;color:#a3261b;font:16px/1.4 system-ui,sans-serif;';
  banner.textContent = `The code of ${label} removed this page's content. Reload the page to get it back: your edit will be offered, not run.`;
  // The code may have taken everything, <html> included (document.write after load leaves no element at all).
  const html = document.documentElement ?? document.appendChild(document.createElement('html'));
  const body = document.body ?? html.appendChild(document.createElement('body'));
  body.append(banner);
}
