/**
 * The page's side of shared edits (share-format.ts, share-session.ts): the
 * "Share your edits" button under the chapter's title, and, on a page opened
 * from a shared link, the banner that says so, lists the changed cells, and
 * offers Run shared edits / Keep these edits / Back to the original.
 *
 * Markup: site/components/ShareEdits.astro renders
 *   <div class="share-edits" data-share-edits>
 *     <button data-share-button>…</button> <div data-share-panel hidden></div> <div data-share-banner hidden></div>
 *   </div>
 * (a page from an older build has none: then nothing here does anything).
 */
import type { ChapterCells } from './chapter.ts';
import { embedSnippet } from './embed-snippet.ts';
import { shareable } from './share-contents.ts';
import { decodeShare, encodeShare, type SharedCell } from './share-format.ts';
import { keepShared, markSharedRun, ownEdits, planShared, sharedStore, type PageCell, type SharedPlan } from './share-session.ts';
import { EditStore } from './storage.ts';

function bar(): HTMLElement | null {
  return document.querySelector<HTMLElement>('[data-share-edits]');
}

function element<K extends keyof HTMLElementTagNameMap>(tag: K, text = '', className = ''): HTMLElementTagNameMap[K] {
  const node = document.createElement(tag);
  if (text) node.textContent = text;
  if (className) node.className = className;
  return node;
}

function button(label: string, run: () => void, attribute: string, primary = false): HTMLButtonElement {
  const node = element('button', label, primary ? 'cell-button cell-run' : 'cell-button');
  node.type = 'button';
  node.setAttribute(attribute, '');
  node.addEventListener('click', run);
  return node;
}

const cellsWord = (n: number): string => `${n} cell${n === 1 ? '' : 's'}`;

/** The page as it is without the link (the reader's own saved edits, if any): a full load of the path. */
function leaveShared(): void {
  location.assign(location.pathname + location.search);
}

/** A cell's name for the reader: its id, or "your cell N" for an added one. */
function cellLabel(cell: SharedCell, addedIndex: number): string {
  return cell.kind === 'added' ? `added cell ${addedIndex}` : cell.id;
}

/** What the Share button does (cells/boot.ts wires it): the link to the chapter as the reader sees it, copied and shown with its length. */
export async function shareEdits(chapter: ChapterCells): Promise<void> {
  const panel = bar()?.querySelector<HTMLElement>('[data-share-panel]');
  if (panel) await share(chapter, panel);
}

async function share(chapter: ChapterCells, panel: HTMLElement): Promise<void> {
  // Text typed in the last moments is in the cells' editors, which shareable() reads.
  const { cells, unrun } = shareable(chapter.cells, chapter.store);
  panel.hidden = false;
  // One live region, kept across clicks, so that each new message is announced.
  let status = panel.querySelector<HTMLElement>('.share-status');
  if (!status) {
    status = element('p', '', 'share-status');
    status.setAttribute('role', 'status');
    panel.replaceChildren(status, element('div', '', 'share-body'));
  }
  const body = panel.querySelector<HTMLElement>('.share-body')!;
  if (cells.length === 0) {
    status.textContent = 'You have not changed any cell of this chapter yet. Edit a cell (or add one with + Cell), then share: the link carries the text of your cells.';
    body.replaceChildren();
    return;
  }
  let url: string;
  try {
    const slug = document.querySelector<HTMLElement>('[data-chapter]')?.dataset.chapter ?? '';
    url = `${location.origin}${location.pathname}${location.search}#${await encodeShare({ chapter: slug, cells })}`;
  } catch (error) {
    status.textContent = `This browser cannot make the link (${error instanceof Error ? error.message : String(error)}).`;
    body.replaceChildren();
    return;
  }
  let copied = false;
  try {
    await navigator.clipboard.writeText(url);
    copied = true;
  } catch {
    // No clipboard permission (or none at all): the field below is selectable.
  }
  status.textContent = `${copied ? 'Link copied' : 'Copy this link'}: your edits of ${cellsWord(cells.length)}, ${url.length} characters.`;
  const label = element('label', 'Link to your edits', 'share-label');
  const field = element('input', '', 'share-link');
  field.id = 'share-link';
  label.htmlFor = field.id;
  field.type = 'text';
  field.readOnly = true;
  field.value = url;
  field.dataset.shareLink = '';
  field.addEventListener('focus', () => field.select());
  const length = element('span', `${url.length} characters`, 'share-length');
  length.dataset.shareLength = '';
  const note = element(
    'p',
    'The edits travel in the part of the link after “#”, which browsers never send to a server: nothing leaves this browser until you send the link. Whoever opens it sees your code, and it runs only when they choose.',
    'share-note',
  );
  const parts: HTMLElement[] = [label, field, length, note];
  if (unrun.length) parts.splice(3, 0, element('p', `Not run yet here: ${unrun.join(', ')}. The link carries the text you see, not what last ran.`, 'share-note'));
  body.replaceChildren(...parts);
  field.focus();
}

/** A link that cannot be used: one clear line above the chapter, which shows as it does without the link. */
export function showShareProblem(message: string): void {
  const banner = bar()?.querySelector<HTMLElement>('[data-share-banner]');
  if (!banner) return;
  const text = element('p', `${message} The chapter is shown without the link’s edits.`);
  banner.setAttribute('role', 'alert');
  banner.className = 'share-banner share-problem';
  banner.replaceChildren(text);
  banner.hidden = false;
}

export interface SharedView {
  readonly plan: SharedPlan;
  /** The in-memory store the page's cells use (share-session.ts). */
  readonly store: EditStore;
  /** The reader's own store, made only when they keep the edits (making one may draw the browser's secret). */
  readonly ownStore: () => EditStore;
}

/**
 * The link's edits that apply to this chapter, in a store of their own; null
 * (after saying why, above the chapter) when the fragment is malformed, of
 * another version or chapter, or has nothing for this page.
 */
export async function openShared(root: HTMLElement): Promise<SharedView | null> {
  const decoded = await decodeShare(location.hash);
  if (!decoded.ok) {
    showShareProblem(decoded.message);
    return null;
  }
  const page: PageCell[] = [...root.querySelectorAll<HTMLElement>('[data-cell]')].map((el) => ({ id: el.dataset.cell ?? '', hash: el.dataset.cellHash ?? '' }));
  const plan = planShared(decoded.edits, root.dataset.chapter ?? '', page);
  if (typeof plan === 'string') {
    showShareProblem(plan);
    return null;
  }
  const hashes = new Map(page.map((cell) => [cell.id, cell.hash]));
  return { plan, store: sharedStore(location.pathname, plan, hashes), ownStore: () => new EditStore(location.pathname) };
}

/**
 * The banner of a page opened from a shared link. Shared code is someone
 * else's code: it runs only after the reader presses Run shared edits; until
 * then each changed cell shows the shared text, "not run yet", and runs the
 * chapter's original.
 */
export function showSharedBanner(view: SharedView, chapter: ChapterCells): void {
  const banner = bar()?.querySelector<HTMLElement>('[data-share-banner]');
  if (!banner) return;
  const { plan } = view;
  const ids = plan.cells.map((cell) => cell.id);
  markSharedCells(chapter, ids);

  const heading = element('p', `You are viewing shared edits of ${cellsWord(plan.cells.length)}.`, 'share-heading');
  heading.id = 'share-banner-heading';
  banner.setAttribute('role', 'region');
  banner.setAttribute('aria-labelledby', heading.id);
  banner.className = 'share-banner';

  let added = 0;
  const list = element('ul', '', 'share-cells');
  list.setAttribute('aria-label', 'Changed cells');
  for (const cell of plan.cells) {
    const item = element('li');
    // A button, not a #cell-… link: following a link would replace the fragment that holds the edits.
    item.append(button(cellLabel(cell, cell.kind === 'added' ? ++added : 0), () => goToCell(cell.id), 'data-share-goto'));
    list.append(item);
  }

  const state = element('p', 'The shared code has not run: each changed cell shows the shared text, marked “not run yet”, while the chapter’s original runs. Read it, then press Run shared edits to run it — code from a link can do anything a cell can do on this page.', 'share-state');
  state.dataset.shareState = '';
  const notes: HTMLElement[] = [element('p', 'Your own saved edits of this chapter, if you have any, are not shown here and are left as they are.', 'share-note')];
  if (plan.changed.length) notes.push(element('p', `Changed in the chapter since the link was made: ${plan.changed.join(', ')}. The shared text is as it was written then.`, 'share-note'));
  if (plan.missing.length) notes.push(element('p', `Left out, as this chapter no longer has these cells: ${plan.missing.join(', ')}.`, 'share-note'));

  const confirm = element('div', '', 'share-confirm');
  confirm.hidden = true;
  const actions = element('div', '', 'share-actions');
  const run = button('Run shared edits', () => {
    markSharedRun(view.store, ids);
    for (const cell of chapter.cells) if (ids.includes(cell.id) && cell.started) void cell.run();
    // The button goes; the keyboard's place goes to the next choice rather than to the top of the page.
    run.remove();
    keep.focus();
    state.textContent = 'The shared edits are running. They are not saved: keep them, or go back to the original.';
    banner.dataset.shareRan = '';
  }, 'data-share-run', true);
  const keep = button('Keep these edits', () => askToKeep(view, chapter, confirm, keep), 'data-share-keep');
  const back = button('Back to the original', leaveShared, 'data-share-back');
  actions.append(run, keep, back);

  banner.replaceChildren(heading, list, state, ...notes, actions, confirm);
  banner.hidden = false;
}

/** Shared cells are marked on the page, in each cell's toolbar, besides the banner. */
function markSharedCells(chapter: ChapterCells, ids: readonly string[]): void {
  for (const cell of chapter.cells) {
    if (!ids.includes(cell.id)) continue;
    cell.root.toggleAttribute('data-cell-shared', true);
    const status = cell.root.querySelector('[data-cell-status]');
    if (status && !cell.root.querySelector('.cell-shared-label')) status.before(element('span', 'shared', 'cell-shared-label'));
  }
}

function goToCell(id: string): void {
  const cell = document.querySelector<HTMLElement>(`[data-cell="${CSS.escape(id)}"]`);
  if (!cell) return;
  cell.scrollIntoView({ block: 'center' });
  cell.querySelector<HTMLElement>('pre.cell-code, [contenteditable="true"]')?.focus();
}

/** Keep: straight away when the reader saved nothing of this chapter, else only after they confirm. */
function askToKeep(view: SharedView, chapter: ChapterCells, confirm: HTMLElement, keep: HTMLButtonElement): void {
  // Drafts typed in the shared view in the last moments go into its store first.
  chapter.cells.forEach((cell) => cell.flush());
  const own = view.ownStore();
  if (!own.available) {
    showConfirm(confirm, 'This browser does not let the page keep edits (storage is full or disabled), so these cannot be kept.', []);
    return;
  }
  const existing = ownEdits(own);
  const doKeep = (): void => {
    if (keepShared(view.store, own)) leaveShared();
    else showConfirm(confirm, 'The browser would not keep these edits (its storage for this site may be full). Your own edits are as they were where it could not write.', []);
  };
  if (existing.length === 0) {
    doKeep();
    return;
  }
  keep.disabled = true;
  showConfirm(
    confirm,
    `You have saved edits of your own in ${cellsWord(existing.length)} of this chapter (${existing.join(', ')}). Keeping the shared edits replaces all of them.`,
    [
      { label: 'Replace my edits', attribute: 'data-share-replace', run: doKeep },
      {
        label: 'Cancel',
        attribute: 'data-share-cancel',
        run: () => {
          confirm.hidden = true;
          confirm.replaceChildren();
          keep.disabled = false;
          keep.focus();
        },
      },
    ],
  );
}

function showConfirm(confirm: HTMLElement, message: string, actions: { label: string; attribute: string; run: () => void }[]): void {
  const text = element('p', message);
  text.setAttribute('role', 'alert');
  confirm.replaceChildren(text, ...actions.map(({ label, attribute, run }) => button(label, run, attribute)));
  confirm.hidden = false;
  // On the way out (Cancel), so that Enter pressed at once replaces nothing.
  [...confirm.querySelectorAll<HTMLButtonElement>('button')].at(-1)?.focus();
}

/** The chapter's embed page of a cell: beside the chapter under the same base, `<base>embed/<chapter>/<cell>/`. */
function embedPageUrl(slug: string, cell: string): string {
  const base = location.pathname.replace(/[^/]+\/?$/, '');
  return `${location.origin}${base}embed/${slug}/${encodeURIComponent(cell)}/`;
}

/** Of the widgets on offer, the first whose cell reaches into the view: what the reader is looking at. */
function widgetInView(ids: readonly string[]): string {
  const seen = ids.find((id) => (document.querySelector(`[data-cell="${CSS.escape(id)}"]`)?.getBoundingClientRect().bottom ?? -1) > 0);
  return seen ?? ids[0];
}

/**
 * What the Embed button does (cells/boot.ts wires it): the HTML that shows
 * one of the chapter's widgets in another page (embed-snippet.ts), with the
 * reader's edits of its cells in the link as Share puts them, copied and
 * shown. The widgets on offer are the chapter's cells that have an embed
 * page (`data-embeds`, site/components/ShareEdits.astro).
 */
export async function embedWidget(chapter: ChapterCells): Promise<void> {
  const box = bar();
  const panel = box?.querySelector<HTMLElement>('[data-embed-panel]');
  const ids = (box?.dataset.embeds ?? '').split(' ').filter(Boolean);
  if (!panel || ids.length === 0) return;
  panel.hidden = false;
  let choice = panel.querySelector<HTMLSelectElement>('[data-embed-choice]');
  if (!choice) {
    choice = element('select', '', 'pb-select');
    choice.id = 'embed-choice';
    choice.dataset.embedChoice = '';
    for (const id of ids) choice.append(Object.assign(element('option', id), { value: id }));
    const choiceLabel = element('label', 'Widget', 'share-label');
    choiceLabel.htmlFor = choice.id;
    const status = element('p', '', 'share-status');
    status.setAttribute('role', 'status');
    const snippet = element('textarea', '', 'share-link embed-snippet');
    snippet.id = 'embed-snippet';
    snippet.readOnly = true;
    snippet.rows = 6;
    snippet.dataset.embedSnippet = '';
    snippet.addEventListener('focus', () => snippet.select());
    const snippetLabel = element('label', 'HTML to paste into your page', 'share-label');
    snippetLabel.htmlFor = snippet.id;
    const note = element(
      'p',
      'The iframe shows the widget with the cells it reads folded under it, and the script after it keeps the iframe as tall as the widget; without the script, set a height yourself. Your edits of the chapter’s cells travel in the link, as with Share, and run in the embed as soon as it opens.',
      'share-note',
    );
    panel.replaceChildren(status, choiceLabel, choice, snippetLabel, snippet, note);
    choice.value = widgetInView(ids);
    choice.addEventListener('change', () => void showSnippet(chapter, panel));
  }
  await showSnippet(chapter, panel);
  panel.querySelector<HTMLTextAreaElement>('[data-embed-snippet]')?.focus();
}

async function showSnippet(chapter: ChapterCells, panel: HTMLElement): Promise<void> {
  const status = panel.querySelector<HTMLElement>('.share-status')!;
  const snippet = panel.querySelector<HTMLTextAreaElement>('[data-embed-snippet]')!;
  const cell = panel.querySelector<HTMLSelectElement>('[data-embed-choice]')!.value;
  const root = document.querySelector<HTMLElement>('[data-chapter]');
  const slug = root?.dataset.chapter ?? '';
  // An embed holds the chapter's cells only: cells the reader added stay on this page.
  const edits = shareable(chapter.cells, chapter.store).cells.filter((c) => c.kind === 'edit');
  let fragment = '';
  try {
    if (edits.length) fragment = `#${await encodeShare({ chapter: slug, cells: edits })}`;
  } catch (error) {
    status.textContent = `This browser cannot put your edits into the link (${error instanceof Error ? error.message : String(error)}); the snippet shows the chapter’s original.`;
  }
  const title = `${cell} — ${root?.querySelector('h1')?.textContent?.trim() ?? slug} — Phasebook`;
  snippet.value = embedSnippet({ src: embedPageUrl(slug, cell) + fragment, title });
  let copied = false;
  try {
    await navigator.clipboard.writeText(snippet.value);
    copied = true;
  } catch {
    // No clipboard permission: the field is there to copy from.
  }
  if (!fragment && edits.length) return;
  const what = edits.length ? `with your edits of ${cellsWord(edits.length)}` : 'as the chapter has it';
  status.textContent = `${copied ? 'Copied' : 'Copy this HTML'}: the widget ${cell}, ${what}.`;
}
