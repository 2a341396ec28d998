/**
 * What the book's own scripts (bin/book-pdf.mjs, bin/package-scorm.mjs) share
 * in reading their arguments: the error that ends in one line on stderr with
 * status 2, and `--site`, the address the book is published at.
 */

/** A mistake in the arguments: said in one line, exit status 2. */
export class UsageError extends Error {}

/**
 * `--site`'s value as an absolute http(s) address ending in `/`, where the
 * book's other pages are linked.
 * @param {string} site
 */
export function siteAddress(site) {
  let url;
  try {
    url = new URL(site.endsWith('/') ? site : `${site}/`);
  } catch {
    throw new UsageError(`--site must be an absolute address such as https://you.github.io/course/, not ${site}`);
  }
  if (!/^https?:$/.test(url.protocol)) throw new UsageError(`--site must be an http(s) address, not ${site}`);
  return url.href;
}
