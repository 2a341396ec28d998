/**
 * The book's Content-Security-Policy, as a <meta> tag (a static site sets no
 * headers). Cells run the reader's code, and that code must stay inside the
 * book: no request, image, script, import or worker from any host but the
 * book's own, so nothing a reader types (or pastes) can send their data
 * elsewhere or fetch code to run. What the book itself needs:
 *
 * - `'unsafe-eval'`: cells and the generated steppers are compiled with
 *   `new Function` (cells/cell-definition.ts, core/expression/);
 * - the hashes of the page's own inline scripts (theme, fonts), and no
 *   other inline script;
 * - inline styles (KaTeX's typesetting and the widgets position things
 *   with style attributes);
 * - `data:` and `blob:` images (the favicon, plot downloads);
 * - workers from the book's own scripts only (`worker-src 'self'`): the
 *   compile, stability and simulation workers are bundled modules of the
 *   site, and make no request of their own; the search worker fetches the
 *   book's own index (site/search/).
 *
 * Search adds nothing to the policy, and in particular no
 * `'wasm-unsafe-eval'`. Pagefind reads its index with WebAssembly, but in
 * the search worker (site/search/search-worker.ts), not in the page: the
 * sandbox takes WebAssembly from the page once a reader's code runs, and a
 * worker is out of its reach. A worker loaded from the site is not under
 * this policy at all: a policy delivered in a <meta> tag governs only its
 * document (CSP 3 gives a worker the policy its own response carries, and a
 * static host sends none). Were the book served with this policy as a
 * header, the worker would get it too, and `'unsafe-eval'`, which the
 * cells need anyway, allows compiling WebAssembly as well.
 *
 * A blocked request shows under the cell that made it (cells/boot.ts).
 *
 * Being framed: `frame-ancestors` is not in the policy, on purpose. A policy
 * in a <meta> tag cannot say it (browsers ignore the directive there, and
 * say so in the console), so every page of the book may be framed by any
 * site, which the embed pages (site/pages/embed/) need: chapters and embeds
 * alike keep this one policy. `frame-src 'none'` is the other direction:
 * what the book's own pages may frame, which is nothing.
 *
 * What a policy cannot say is left to the sandbox reader code runs in
 * (cells/sandbox/): navigations (`navigate-to` never shipped; the
 * Navigation API's `navigate` event cancels a cell's, navigation.ts),
 * WebRTC (no directive in Chromium; the constructors are removed,
 * network.ts), link hints such as preconnect (no directive; refused before
 * they enter the page, dom-guard.ts), and the code a cell would make with
 * eval, which `'unsafe-eval'` has to allow for the book's own compiling
 * (refused when a cell asks, code-from-text.ts). `form-action 'self'` stays
 * as the policy's own word on forms.
 */
import { createHash } from 'node:crypto';

/** The CSP source expression of an inline script's exact text. */
export function scriptHash(text: string): string {
  return `'sha256-${createHash('sha256').update(text, 'utf8').digest('base64')}'`;
}

export function contentSecurityPolicy(inlineScripts: readonly string[]): string {
  const directives = [
    "default-src 'self'",
    `script-src 'self' 'unsafe-eval' ${inlineScripts.map(scriptHash).join(' ')}`,
    "style-src 'self' 'unsafe-inline'",
    "img-src 'self' data: blob:",
    "font-src 'self' data:",
    "connect-src 'self'",
    "worker-src 'self'",
    "media-src 'self'",
    "object-src 'none'",
    "frame-src 'none'",
    "base-uri 'self'",
    "form-action 'self'",
  ];
  return directives.join('; ');
}
