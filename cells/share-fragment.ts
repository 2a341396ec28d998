/**
 * How a shared link's fragment begins (`#share=…`, share-format.ts). On its
 * own because every page asks at boot whether it was opened from one, while
 * the code that reads and writes such links loads only when it is.
 */
export const SHARE_PREFIX = 'share=';

/** True when `hash` (with or without its `#`) is a shared-edits fragment, well formed or not. */
export function isShareFragment(hash: string): boolean {
  return hash.replace(/^#/, '').startsWith(SHARE_PREFIX);
}
