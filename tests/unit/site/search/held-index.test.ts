import { describe, expect, it } from 'vitest';
import { holdIndex, indexFiles, INDEX_FILES } from '../../../../site/search/held-index.ts';

const INDEX = 'https://book.example/phasebook/pagefind/';

/** A fetch over `files` (path → text) that records what it was asked, and fails for everything once `offline` is set. */
function server(files: Record<string, string>) {
  const asked: string[] = [];
  let offline = false;
  const fetchFile = async (input: RequestInfo | URL): Promise<Response> => {
    const url = new URL(input instanceof Request ? input.url : String(input));
    asked.push(url.pathname + url.search);
    if (offline) throw new TypeError('Failed to fetch');
    const body = files[url.pathname];
    return body === undefined ? new Response('missing', { status: 404 }) : new Response(body);
  };
  return { fetchFile, asked, goOffline: () => (offline = true) };
}

describe('site/search/held-index.ts: the index in memory', () => {
  it('fetches every listed file when opened, then serves them, query or not, with no connection', async () => {
    const { fetchFile, asked, goOffline } = server({
      [`/phasebook/pagefind/${INDEX_FILES}`]: JSON.stringify({ files: ['pagefind-entry.json', 'index/en_1.pf_index'] }),
      '/phasebook/pagefind/pagefind-entry.json': '{"version":"1"}',
      '/phasebook/pagefind/index/en_1.pf_index': 'chunk',
    });
    const held = await holdIndex(INDEX, fetchFile);
    await held.complete;
    expect(asked.sort()).toEqual(['/phasebook/pagefind/index/en_1.pf_index', `/phasebook/pagefind/${INDEX_FILES}`, '/phasebook/pagefind/pagefind-entry.json'].sort());
    goOffline();
    expect(await (await held.fetch(`${INDEX}pagefind-entry.json?ts=123`)).text()).toBe('{"version":"1"}');
    expect(await (await held.fetch(new URL('index/en_1.pf_index', INDEX))).text()).toBe('chunk');
    // Twice: a Response's body is read once, the held bytes are not used up.
    expect(await (await held.fetch(`${INDEX}index/en_1.pf_index`)).text()).toBe('chunk');
    // Anything else goes to the network.
    await expect(held.fetch(`${INDEX}fragment/en_9.pf_fragment`)).rejects.toThrow('Failed to fetch');
  });

  it('to save data, fetches a file only when asked for it, then keeps it', async () => {
    const { fetchFile, asked, goOffline } = server({
      [`/pagefind/${INDEX_FILES}`]: '{"files":["a.pf_index","b.pf_index"]}',
      '/pagefind/a.pf_index': 'a',
      '/pagefind/b.pf_index': 'b',
    });
    const held = await holdIndex('https://book.example/pagefind/', fetchFile, { whole: false });
    expect(asked).toEqual([`/pagefind/${INDEX_FILES}`]);
    expect(await (await held.fetch('https://book.example/pagefind/a.pf_index')).text()).toBe('a');
    expect(asked).toEqual([`/pagefind/${INDEX_FILES}`, '/pagefind/a.pf_index']);
    goOffline();
    expect(await (await held.fetch('https://book.example/pagefind/a.pf_index')).text()).toBe('a');
    await expect(held.fetch('https://book.example/pagefind/b.pf_index')).rejects.toThrow('Failed to fetch');
  });

  it('asks again for a file that failed to arrive', async () => {
    let failures = 1;
    const { fetchFile } = server({ [`/pagefind/${INDEX_FILES}`]: '{"files":["wasm.en.pagefind"]}', '/pagefind/wasm.en.pagefind': 'wasm' });
    const flaky = async (input: RequestInfo | URL) => (String(input).endsWith('.pagefind') && failures-- > 0 ? Promise.reject(new TypeError('Failed to fetch')) : fetchFile(input));
    const held = await holdIndex('https://book.example/pagefind/', flaky);
    await expect(held.complete).rejects.toThrow();
    expect(await (await held.fetch('https://book.example/pagefind/wasm.en.pagefind')).text()).toBe('wasm');
  });

  it('refuses a list that lists nothing, and keeps only names from one that does', async () => {
    expect(() => indexFiles(null)).toThrow(INDEX_FILES);
    expect(() => indexFiles({ files: 'a' })).toThrow(INDEX_FILES);
    expect(indexFiles({ files: ['a', 3, '', null, 'b'] })).toEqual(['a', 'b']);
    const { fetchFile } = server({ [`/pagefind/${INDEX_FILES}`]: 'not json' });
    await expect(holdIndex('https://book.example/pagefind/', fetchFile)).rejects.toThrow();
    await expect(holdIndex('https://book.example/nothing/', fetchFile)).rejects.toThrow('HTTP 404');
  });
});
