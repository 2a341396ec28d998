/**
 * The preview webview's page: the book's styles and the preview script from
 * the extension's dist/, under a Content-Security-Policy that allows only
 * them, plus what cells need: 'unsafe-eval' (cells are compiled with
 * `new Function`, as on the book's pages), inline styles (KaTeX and the
 * widgets set them) and blob: workers.
 */
import * as vscode from 'vscode';

function escapeAttribute(text: string): string {
  return text.replace(/[&<>"']/g, (c) => `&#${c.charCodeAt(0)};`);
}

function nonce(): string {
  const bytes = new Uint8Array(18);
  crypto.getRandomValues(bytes);
  return btoa(String.fromCharCode(...bytes));
}

/** `document` is kept in the webview's state, so that VS Code can restore the preview after a reload. */
export function previewHtml(webview: vscode.Webview, extensionUri: vscode.Uri, document: vscode.Uri): string {
  const asset = (name: string) => webview.asWebviewUri(vscode.Uri.joinPath(extensionUri, 'dist', name)).toString();
  const source = webview.cspSource;
  const once = nonce();
  const policy = [
    "default-src 'none'",
    `img-src ${source} data: blob:`,
    `style-src ${source} 'unsafe-inline'`,
    `font-src ${source} data:`,
    `script-src 'nonce-${once}' 'unsafe-eval'`,
    `worker-src blob:`,
    `connect-src ${source}`,
  ].join('; ');
  return `<!doctype html>
<html lang="en">
  <head>
    <meta charset="utf-8">
    <meta http-equiv="Content-Security-Policy" content="${policy}">
    <meta name="viewport" content="width=device-width, initial-scale=1">
    <link rel="stylesheet" href="${asset('preview.css')}">
  </head>
  <body>
    <main id="main" class="page"><article data-chapter="preview" data-document="${escapeAttribute(document.toString())}"></article></main>
    <script nonce="${once}" src="${asset('preview.js')}" data-workers="${asset('workers/')}"></script>
  </body>
</html>`;
}
