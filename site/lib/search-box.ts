/**
 * The header's search box, before any search code has loaded: the inline
 * script that loads it when the reader asks, kept as text so that the page's
 * Content-Security-Policy (csp.ts) can allow it by hash.
 *
 * Nothing of search is fetched with the page. Focusing the box, or pressing
 * `/` anywhere but in a field or a cell's editor (where `/` is a character
 * to type), imports the search module (site/search/search-ui.ts), whose
 * address the build writes into the form (site/lib/search-index.mjs: the
 * module's file name has a hash known only once the bundle is written). A
 * module that cannot be fetched (the connection is gone) is said in the
 * box's status line, and tried again on the next focus.
 */

/** Stands for the search module's address in the rendered pages until the build knows it. */
export const SEARCH_MODULE_PLACEHOLDER = '__PHASEBOOK_SEARCH_MODULE__';

export const searchBoxScript = `const form = document.querySelector('form[data-search]');
const input = form?.querySelector('input[type="search"]');
let opening = null;
const open = () => {
  opening ??= import(form.dataset.searchModule).then((search) => search.openSearch(form)).catch(() => {
    opening = null;
    form.querySelector('[data-search-panel]').hidden = false;
    form.querySelector('[data-search-status]').textContent = 'Search could not be loaded: the connection to the book\\'s site seems to be lost. Try again when you are back online.';
  });
};
if (form && input) {
  input.addEventListener('focus', open);
  form.addEventListener('submit', (event) => event.preventDefault());
  document.addEventListener('keydown', (event) => {
    if (event.key !== '/' || event.ctrlKey || event.metaKey || event.altKey || event.isComposing || event.defaultPrevented) return;
    const target = event.target;
    if (target instanceof Element && (target.isContentEditable || target.closest('input, textarea, select, [contenteditable], .cell-editor'))) return;
    event.preventDefault();
    input.focus();
  });
}`;
