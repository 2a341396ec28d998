/**
 * The HTML a teacher pastes into their own page to show one widget of the
 * book (the Embed button, share-ui.ts): an iframe of its embed page, and a
 * few lines of script that size the iframe to the height the embed reports
 * (embed.ts). Only messages from the book's origin are listened to.
 */

const escapeAttribute = (text: string): string => text.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

export interface EmbedTarget {
  /** The embed page's full URL, with the edits' fragment if any. */
  readonly src: string;
  /** The iframe's accessible name. */
  readonly title: string;
}

/** The iframe, then the script that keeps its height to the widget's. */
export function embedSnippet({ src, title }: EmbedTarget): string {
  const origin = new URL(src).origin;
  return [
    `<iframe src="${escapeAttribute(src)}" title="${escapeAttribute(title)}" style="width: 100%; height: 480px; border: 0" loading="lazy"></iframe>`,
    '<script>',
    '  // Phasebook: the embed says its height whenever it changes; this sizes its iframe to it.',
    "  addEventListener('message', (event) => {",
    `    if (event.origin !== ${JSON.stringify(origin)} || event.data?.type !== 'phasebook:height') return;`,
    "    for (const frame of document.getElementsByTagName('iframe')) if (frame.contentWindow === event.source) frame.style.height = `${event.data.height}px`;",
    '  });',
    '</script>',
  ].join('\n');
}
