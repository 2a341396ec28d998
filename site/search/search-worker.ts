/**
 * Pagefind, run in a worker of its own. The page's WebAssembly is taken away
 * as soon as a reader's own code runs (cells/sandbox/code-from-text.ts), and
 * Pagefind's index is read by WebAssembly: here, out of the sandbox's reach,
 * search works before and after an edit alike, and a search never holds up
 * the page. The index is held in memory (held-index.ts), so that search
 * keeps working when the connection drops: `held` says when it all is.
 */
import { holdIndex } from './held-index.ts';
import { pageHit, type PagefindPage } from './hits.ts';
import type { FromWorker, ToWorker } from './protocol.ts';

/** The part of Pagefind's browser API used here (pagefind.js, written by the build beside the index). */
interface Pagefind {
  options(options: Record<string, unknown>): Promise<void>;
  init(): Promise<void>;
  search(query: string): Promise<{ results: readonly { data(): Promise<PagefindPage> }[] } | null>;
}

/** Chapters shown for one query: more than fit a phone's screen, fewer than the book has. */
const PAGES_SHOWN = 8;
/** Words of an excerpt. */
const EXCERPT_WORDS = 26;

const scope = self as unknown as {
  postMessage(message: FromWorker): void;
  onmessage: ((event: MessageEvent<ToWorker>) => void) | null;
};

const fetchOnline = globalThis.fetch.bind(globalThis);
let pagefind: Promise<Pagefind> | null = null;

/** Whether to fetch the whole index when the box opens: not for a reader who asked to save data, nor on a slow connection (site/lib/fonts.ts draws the same line). */
function wholeIndex(): boolean {
  const connection = (navigator as { connection?: { saveData?: boolean; effectiveType?: string } }).connection;
  return !(connection?.saveData || /^(slow-2g|2g|3g)$/.test(connection?.effectiveType ?? ''));
}

async function open(index: string, base: string): Promise<Pagefind> {
  const held = await holdIndex(index, fetchOnline, { whole: wholeIndex() });
  globalThis.fetch = held.fetch;
  void held.complete.then(() => scope.postMessage({ kind: 'held' }), () => {});
  const module = (await import(/* @vite-ignore */ new URL('pagefind.js', index).href)) as Pagefind;
  await module.options({ basePath: new URL(index).pathname, baseUrl: base, excerptLength: EXCERPT_WORDS });
  await module.init();
  return module;
}

/** A failed load said for the reader: a fetch that fails outright means the connection, anything else the index. */
function failure(error: unknown): FromWorker {
  const message = error instanceof Error ? error.message : String(error);
  return { kind: 'failed', offline: error instanceof TypeError || /fetch|import|network/i.test(message), message };
}

async function search(id: number, query: string): Promise<FromWorker> {
  if (!pagefind) throw new Error('search before open');
  const found = await (await pagefind).search(query);
  const results = found?.results ?? [];
  const pages = await Promise.all(results.slice(0, PAGES_SHOWN).map(async (result) => pageHit(await result.data())));
  return { kind: 'results', id, total: results.length, pages };
}

scope.onmessage = async ({ data }) => {
  if (data.kind === 'open') {
    try {
      pagefind ??= open(data.index, data.base);
      await pagefind;
      scope.postMessage({ kind: 'ready' });
    } catch (error) {
      // Asked again (the box's next focus), the index is loaded afresh.
      pagefind = null;
      scope.postMessage(failure(error));
    }
  } else if (data.kind === 'search') {
    try {
      scope.postMessage(await search(data.id, String(data.query)));
    } catch (error) {
      scope.postMessage(failure(error));
    }
  }
};
