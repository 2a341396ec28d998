import { describe, expect, it } from 'vitest';
import { embedSnippet } from '../../../cells/embed-snippet.ts';

const unescape = (text: string) => text.replace(/&quot;/g, '"').replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&amp;/g, '&');

describe('cells/embed-snippet.ts: the iframe snippet of the Embed button', () => {
  const src = 'https://ada.github.io/course/embed/kepler/stars/#share=1.abc"x';
  const snippet = embedSnippet({ src, title: 'Kepler: “stars” <orbit> & more' });

  it('is one iframe of the embed page, its attributes escaped, named by its title', () => {
    const tags = [...snippet.matchAll(/<iframe ([^>]*)><\/iframe>/g)];
    expect(tags).toHaveLength(1);
    const attributes = Object.fromEntries([...tags[0][1].matchAll(/(\w+)="([^"]*)"/g)].map((m) => [m[1], unescape(m[2])]));
    expect(attributes.src).toBe(src);
    expect(attributes.title).toBe('Kepler: “stars” <orbit> & more');
  });

  it('sizes its iframe from height messages of the book’s origin only', () => {
    const code = /<script>([\s\S]*)<\/script>/.exec(snippet)![1];
    const ours = { contentWindow: {}, style: { height: '' } };
    const other = { contentWindow: {}, style: { height: '' } };
    let listener: (event: { origin: string; data: unknown; source: unknown }) => void = () => {};
    const listen = (type: string, handler: typeof listener) => type === 'message' && (listener = handler);
    new Function('addEventListener', 'document', code)(listen, { getElementsByTagName: () => [other, ours] });
    listener({ origin: 'https://elsewhere.example', data: { type: 'phasebook:height', height: 999 }, source: ours.contentWindow });
    expect(ours.style.height).toBe('');
    listener({ origin: 'https://ada.github.io', data: { type: 'phasebook:height', height: 612 }, source: ours.contentWindow });
    expect([ours.style.height, other.style.height]).toEqual(['612px', '']);
    listener({ origin: 'https://ada.github.io', data: { type: 'phasebook:state', height: 1 }, source: ours.contentWindow });
    expect(ours.style.height).toBe('612px');
  });
});
