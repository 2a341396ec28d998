/**
 * What the page says, and gives back, when something went wrong: the text
 * of an edit the browser's storage gave back damaged, and the notice of a
 * page a cell emptied. Rarely needed, so loaded only then (a chunk of its
 * own): a page's first scripts stay small.
 */

/**
 * The text of an edit that no longer parses, as far as it can be read: the
 * code that ran, else the draft, from the JSON (cut short or not), else the
 * raw value as it is.
 */
export function recoverText(raw: string): string {
  try {
    const value = JSON.parse(raw) as Partial<Record<'ran' | 'draft', unknown>>;
    const text = typeof value?.ran === 'string' ? value.ran : typeof value?.draft === 'string' ? value.draft : null;
    if (text !== null) return text;
  } catch {
    // Cut short or garbled: read the fields by hand.
  }
  for (const field of ['ran', 'draft']) {
    const match = new RegExp(`"${field}"\\s*:\\s*"((?:[^"\\\\]|\\\\.)*)("?)`).exec(raw);
    if (!match) continue;
    // A string cut short may end in half an escape: drop characters until it decodes.
    for (let end = match[1].length; end >= 0; end--) {
      try {
        return JSON.parse(`"${match[1].slice(0, end)}"`) as string;
      } catch {
        // One character fewer.
      }
    }
  }
  return raw;
}

/** Shows, over whatever is left, that cell `label` removed the page and that a reload brings it back. */
export function showPageBroken(label: string): void {
  const id = 'phasebook-page-broken';
  if (document.getElementById(id)) return;
  const banner = document.createElement('div');
  banner.id = id;
  banner.setAttribute('role', 'alert');
  banner.style.cssText =
    'position:fixed;inset:1rem 1rem auto;z-index:2147483647;padding:0.8rem 1rem;border:1px solid #a3261b;border-radius:6px;' +
    'background:#fbeceb;color:#a3261b;font:16px/1.4 system-ui,sans-serif;';
  banner.textContent = `The code of ${label} removed this page's content. Reload the page to get it back: your edit will be offered, not run.`;
  // The code may have taken everything, <html> included (document.write after load leaves no element at all).
  const html = document.documentElement ?? document.appendChild(document.createElement('html'));
  const body = document.body ?? html.appendChild(document.createElement('body'));
  body.append(banner);
}
