import remarkMdx from 'remark-mdx';
import remarkParse from 'remark-parse';
import { unified } from 'unified';
import { describe, expect, it } from 'vitest';
import { remarkBaseLinks } from '../../../site/lib/remark-base-links.mjs';

type Node = { type: string; url?: string; name?: string; attributes?: { name: string; value: unknown }[]; children?: Node[] };

/** Every URL of the MDX after the plugin ran for `base`: `[link](url)`, `![image](url)`, `[def]: url`, `<Tag attr="url">`. */
function built(mdx: string, base?: string): string {
  const processor = unified().use(remarkParse).use(remarkMdx).use(remarkBaseLinks, { base });
  const tree = processor.runSync(processor.parse(mdx)) as Node;
  const urls: string[] = [];
  const walk = (node: Node) => {
    if (node.url !== undefined) urls.push(`${node.type} ${node.url}`);
    for (const a of node.attributes ?? []) urls.push(`<${node.name} ${a.name}=${typeof a.value === 'string' ? a.value : '{…}'}>`);
    node.children?.forEach(walk);
  };
  walk(tree);
  return urls.join('\n');
}

describe('site/lib/remark-base-links.mjs: root-relative links follow the base path', () => {
  it('puts a Markdown link and an image from the root under the base', () => {
    expect(built('See the [Introduction](/introduction/#energy) and ![orbit](/figures/orbit.png).', '/course/')).toBe(
      'link /course/introduction/#energy\nimage /course/figures/orbit.png',
    );
  });

  it('takes the base with or without its trailing slash', () => {
    expect(built('[Kepler](/kepler/)', '/course')).toBe('link /course/kepler/');
  });

  it('rewrites link definitions, used by reference links', () => {
    expect(built('[Kepler][k]\n\n[k]: /kepler/', '/course/')).toBe('definition /course/kepler/');
  });

  it('rewrites raw <a href>, <img src srcset> and a component prop in MDX, flow and inline', () => {
    const out = built(
      '<a href="/kepler/">Kepler</a>\n\nText <a href="/scattering/">inline</a>.\n\n<img src="/a.png" srcset="/a.png 1x, /b.png 2x" alt="" />\n\n<Figure src="/c.svg" />',
      '/course/',
    );
    expect(out.split('\n')).toEqual([
      '<a href=/course/kepler/>',
      '<a href=/course/scattering/>',
      '<img src=/course/a.png>',
      '<img srcset=/course/a.png 1x, /course/b.png 2x>',
      '<img alt=>',
      '<Figure src=/course/c.svg>',
    ]);
  });

  it('leaves relative links, fragments, other hosts, protocol-relative URLs and JSX expressions alone', () => {
    const source = '[a](../kepler/) [b](#energy) [c](https://example.org/x) [d](//cdn.example.org/x) [e](mailto:a@b.c)\n\n<a href={"/x/"}>x</a>';
    expect(built(source, '/course/')).toBe(built(source));
    expect(built(source, '/course/')).toContain('link ../kepler/\nlink #energy\nlink https://example.org/x\nlink //cdn.example.org/x\nlink mailto:a@b.c');
  });

  it('changes nothing when the book lives at the host root', () => {
    expect(built('[Introduction](/introduction/)', '/')).toBe('link /introduction/');
    expect(built('[Introduction](/introduction/)')).toBe('link /introduction/');
  });
});
