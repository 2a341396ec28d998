/**
 * A new chapter made from the book's template (templates/chapter.mdx): the
 * template's text with the author's title and the next free order.
 */

/**
 * The smallest whole number from 1 that no chapter uses. Back matter sits
 * at high orders (90, 98, 99 in the book), so the new chapter lands after
 * the numbered chapters and before it; the author can move it by editing `order`.
 */
export function nextFreeOrder(orders: Iterable<number>): number {
  const used = new Set(orders);
  let order = 1;
  while (used.has(order)) order++;
  return order;
}

/** A file name for a title: lower case, words joined by hyphens, only ASCII letters and digits. */
export function fileNameFor(title: string): string {
  const slug = title
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-+|-+$/g, '');
  return `${slug || 'chapter'}.mdx`;
}

/** YAML for a one-line string: quoted, since a title may hold `:` or `#`. */
function yamlString(text: string): string {
  return JSON.stringify(text.replace(/[\r\n]+/g, ' '));
}

/** The template with `title:` and `order:` replaced; throws when the template lacks either line. */
export function chapterFromTemplate(template: string, title: string, order: number): string {
  let text = template;
  for (const [key, value] of [['title', yamlString(title)], ['order', String(order)]] as const) {
    const line = new RegExp(`^${key}:.*$`, 'm');
    if (!line.test(text)) throw new Error(`the template has no \`${key}:\` line in its front matter`);
    text = text.replace(line, `${key}: ${value}`);
  }
  return text;
}
