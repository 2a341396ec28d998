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

/** After the toggle button: its label names the theme a click switches to. */
export const themeToggleScript = `(() => {
  const button = document.querySelector('[data-theme-toggle]');
  const root = document.documentElement;
  const system = matchMedia('(prefers-color-scheme: dark)');
  const current = () => root.dataset.theme || (system.matches ? 'dark' : 'light');
  const label = () => {
    button.textContent = current() === 'dark' ? 'Light theme' : 'Dark theme';
  };
  button.addEventListener('click', () => {
    const next = current() === 'dark' ? 'light' : 'dark';
    root.dataset.theme = next;
    try {
      localStorage.setItem('phasebook:theme', next);
    } catch {}
    label();
  });
  system.addEventListener('change', label);
  label();
})();`;
