/**
 * The messages between the search box (search-ui.ts) and the worker that
 * runs Pagefind (search-worker.ts).
 */

/** A section of a chapter that matches: its heading (or the chapter's title, for the text before the first heading) and an excerpt. */
export interface SectionHit {
  readonly title: string;
  /** The section's address: the chapter's, with the heading's anchor. */
  readonly url: string;
  /** Pagefind's excerpt: text with `<`, `>` escaped and the matched words in `<mark>` (excerpt.ts reads it). */
  readonly excerpt: string;
}

/** A chapter that matches, with its best sections in page order. */
export interface PageHit {
  readonly title: string;
  readonly url: string;
  readonly sections: readonly SectionHit[];
}

export type ToWorker =
  /** Load the index, whose files are at `index` (an absolute URL ending in `/`), for pages under `base`. */
  | { readonly kind: 'open'; readonly index: string; readonly base: string }
  | { readonly kind: 'search'; readonly id: number; readonly query: string };

export type FromWorker =
  | { readonly kind: 'ready' }
  /** Every file of the index is in the worker's memory: search needs no connection any more. */
  | { readonly kind: 'held' }
  /** The index could not be loaded; `offline` when the connection seems to be the reason. */
  | { readonly kind: 'failed'; readonly offline: boolean; readonly message: string }
  | { readonly kind: 'results'; readonly id: number; readonly total: number; readonly pages: readonly PageHit[] };
