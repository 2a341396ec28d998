/**
 * remark plugin: a chapter's root-relative links and images follow the base
 * path the book is built for (`PHASEBOOK_BASE`, astro.config.mjs).
 *
 * An author writes `[Introduction](/introduction/)`, as the site's root sees
 * it; built for a GitHub project site under `/course/`, that link must read
 * `/course/introduction/`, or it leaves the book and meets the host's 404.
 * Relative links (`../introduction/`, `#section`) and links to other hosts
 * (`https://…`, `//host/…`, `mailto:`) already resolve wherever the book
 * lives, and are left alone.
 *
 * Covered: Markdown links, images and link definitions (`[x]: /path/`), and
 * the URL attributes of JSX written in MDX (`<a href="/kepler/">`,
 * `<img src srcset>`, `<source>`, a component's `href`/`src` prop), when
 * their value is a literal string; an `{expression}` is the author's code
 * and is left to it.
 */

/** JSX attributes that hold one URL. */
const URL_ATTRIBUTES = new Set(['href', 'src', 'poster', 'action', 'data', 'cite']);

/** A path from the site's root: `/x`, not `//host/x` (another host, this scheme). */
const fromRoot = (url) => typeof url === 'string' && url.startsWith('/') && !url.startsWith('//');

/**
 * `url` under `base` when it is root-relative, else as it was.
 * @param {string} url
 * @param {string} prefix the base without its trailing slash (`/course`), or '' at the host's root
 */
export function underBase(url, prefix) {
  return prefix && fromRoot(url) ? `${prefix}${url}` : url;
}

/** A `srcset` (`/a.png 1x, /b.png 2x`), each candidate's URL under the base. */
function srcsetUnderBase(srcset, prefix) {
  return srcset
    .split(',')
    .map((candidate) => candidate.replace(/^(\s*)(\S+)/, (_, space, url) => space + underBase(url, prefix)))
    .join(',');
}

/** The base as a prefix: `/course/` and `/course` give `/course`, `/` and undefined give ''. */
export function basePrefix(base) {
  return (base ?? '').replace(/\/+$/, '');
}

function rewriteNode(node, prefix) {
  if ((node.type === 'link' || node.type === 'image' || node.type === 'definition') && typeof node.url === 'string') {
    node.url = underBase(node.url, prefix);
  } else if (node.type === 'mdxJsxFlowElement' || node.type === 'mdxJsxTextElement') {
    for (const attribute of node.attributes ?? []) {
      if (attribute.type !== 'mdxJsxAttribute' || typeof attribute.value !== 'string') continue;
      if (URL_ATTRIBUTES.has(attribute.name)) attribute.value = underBase(attribute.value, prefix);
      else if (attribute.name === 'srcset' || attribute.name === 'srcSet') attribute.value = srcsetUnderBase(attribute.value, prefix);
    }
  }
  for (const child of node.children ?? []) rewriteNode(child, prefix);
}

/**
 * @param {{ base?: string }} options `base`: the path the book is served under (`/course/`); none, the host's root
 * @returns {(tree: import('mdast').Root) => void}
 */
export function remarkBaseLinks({ base } = {}) {
  const prefix = basePrefix(base);
  return (tree) => {
    if (prefix) rewriteNode(tree, prefix);
  };
}
