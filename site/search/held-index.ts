/**
 * The search index, held in the worker's memory once the reader has opened
 * the box: a search that fetched its pieces only as words are typed would
 * stop working the moment the connection drops (on a train, the page still
 * open). Pagefind fetches what it needs as it goes; the fetch handed to it
 * here serves every file of the index from memory, waiting for one still on
 * its way, and passes anything else on. With `whole`, every file starts at
 * once when the box opens (the first search waits for nothing more than it
 * would have), and `complete` says when all are in; without it (a reader who
 * asked the browser to save data, or a slow connection), a file is fetched
 * when Pagefind first asks for it, and kept.
 */

/** The list of the index's files the build writes beside them (site/lib/search-index.mjs), relative to the index's folder. */
export const INDEX_FILES = 'phasebook-files.json';

type Fetch = (input: RequestInfo | URL, init?: RequestInit) => Promise<Response>;

export interface HeldIndex {
  /** A fetch that answers for the index's files from memory. */
  readonly fetch: Fetch;
  /** Settles once every file is held (never, unless all were asked for at once): from then on, search needs no connection. */
  readonly complete: Promise<void>;
}

async function fetched(fetchFile: Fetch, url: URL): Promise<Response> {
  const response = await fetchFile(url);
  if (!response.ok) throw new Error(`${url.pathname}: HTTP ${response.status}`);
  return response;
}

/** The files `list` names: its `files`, strings only. */
export function indexFiles(list: unknown): string[] {
  const files = (list as { files?: unknown } | null)?.files;
  if (!Array.isArray(files)) throw new Error(`${INDEX_FILES} lists no files`);
  return files.filter((file): file is string => typeof file === 'string' && file !== '');
}

/**
 * Holds the files of the index at `index` (an absolute URL ending in `/`)
 * that its list names, all at once or as asked (`whole`). Files are matched
 * by path: Pagefind adds a query to one of them to get past caches.
 */
export async function holdIndex(index: string, fetchFile: Fetch, { whole = true } = {}): Promise<HeldIndex> {
  const base = new URL(index);
  const files = new Set(indexFiles(await (await fetched(fetchFile, new URL(INDEX_FILES, base))).json()).map((file) => new URL(file, base).pathname));
  const held = new Map<string, Promise<ArrayBuffer>>();
  const hold = (url: URL) => {
    const bytes = fetched(fetchFile, url).then((response) => response.arrayBuffer());
    // Whoever asks for the file sees its failure; the promise itself must not count as unhandled.
    bytes.catch(() => {});
    held.set(url.pathname, bytes);
    return bytes;
  };
  const complete = whole ? Promise.all([...files].map((path) => hold(new URL(path, base)))).then(() => undefined) : new Promise<void>(() => {});
  complete.catch(() => {});
  return {
    complete,
    async fetch(input, init) {
      const url = new URL(input instanceof Request ? input.url : String(input), base);
      if (url.origin !== base.origin || !files.has(url.pathname)) return fetchFile(input, init);
      // A file not asked for yet, or one that failed to arrive (the connection blinked), is fetched now.
      const bytes = held.get(url.pathname) ?? hold(url);
      return new Response(await bytes.catch(() => hold(url)));
    },
  };
}
