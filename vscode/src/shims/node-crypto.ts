/**
 * Stands in for `node:crypto` in the extension's bundles, which run in a
 * web worker and a webview. site/lib/remark-cells.mjs hashes each cell's
 * source (data-cell-hash) to recognise a reader's saved edit of an older
 * version; the preview keeps no readers' edits, so any stable hash will do:
 * FNV-1a over UTF-16 code units, in two 32-bit lanes.
 */
function fnv(text: string, seed: number): string {
  let hash = seed >>> 0;
  for (let i = 0; i < text.length; i++) hash = Math.imul(hash ^ text.charCodeAt(i), 0x01000193) >>> 0;
  return hash.toString(16).padStart(8, '0');
}

export function createHash(_algorithm: string) {
  let text = '';
  const hash = {
    update(data: string) {
      text += data;
      return hash;
    },
    digest(_encoding: 'hex') {
      return (fnv(text, 0x811c9dc5) + fnv(text, 0x050c5d1f)).repeat(4);
    },
  };
  return hash;
}
