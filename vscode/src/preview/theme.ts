/**
 * The book's light or dark theme (global.css's `data-theme`) from VS
 * Code's: the webview's <body> carries `vscode-light`, `vscode-dark` or a
 * high-contrast class, and changes it when the user switches themes.
 */
function apply(): void {
  const classes = document.body.classList;
  const light = classes.contains('vscode-light') || classes.contains('vscode-high-contrast-light');
  document.documentElement.dataset.theme = light ? 'light' : 'dark';
}

export function followVsCodeTheme(): void {
  apply();
  new MutationObserver(apply).observe(document.body, { attributes: true, attributeFilter: ['class'] });
}
