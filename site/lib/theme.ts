/**
 * The light/dark theme's two inline scripts, kept as text here so that the
 * page's Content-Security-Policy (csp.ts) can allow exactly them by hash.
 * With no choice saved the page follows the system (prefers-color-scheme); a
 * click pins the opposite of what is showing and remembers it in
 * localStorage under `phasebook:theme`.
 */

/** In the head: applies the saved theme before the first paint, so the page never flashes. */
export const themeScript = `try {
  const theme = localStorage.getItem('phasebook:theme');
  if (theme === 'light' || theme === 'dark') document.documentElement.dataset.theme = theme;
} catch {}`;

/**
 * The toggle's click, as an inline module script: deferred, so it never
 * holds up the parsing of a long chapter while the stylesheet loads, as a
 * classic script after a stylesheet does. The button's label needs no
 * script: it holds both labels, and global.css shows the one that names the
 * theme a click switches to.
 */
export const themeToggleScript = `const button = document.querySelector('[data-theme-toggle]');
const root = document.documentElement;
const system = matchMedia('(prefers-color-scheme: dark)');
button?.addEventListener('click', () => {
  const next = (root.dataset.theme || (system.matches ? 'dark' : 'light')) === 'dark' ? 'light' : 'dark';
  root.dataset.theme = next;
  try {
    localStorage.setItem('phasebook:theme', next);
  } catch {}
});`;
