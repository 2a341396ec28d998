/**
 * An embed page's side of the page around it (site/pages/embed/; the
 * README's "Embedding a widget" documents the messages). Loaded by boot.ts
 * on an embed page only.
 *
 * - Height: the page tells its parent its height whenever it changes
 *   (ResizeObserver), as `{type: 'phasebook:height', height}`, so the
 *   parent can size the iframe to the widget. Heights are no secret: they go
 *   to any parent (`'*'`).
 * - Edits: a link made by the Embed button carries the reader's edits in its
 *   fragment, as a share link does (share-format.ts); they run at once, as
 *   edits set by message do.
 * - Messages: any page may embed the book and drive it, since what it can
 *   set is a cell's code, which runs under the same sandbox as a reader's
 *   edit (sandbox/). Replies, which carry the cells' values, go only to the
 *   window that asked, at the origin it asked from; an asker with an opaque
 *   origin (a sandboxed iframe, a file: page) gets none.
 *
 *   → {type: 'phasebook:set', cell, source, id?}   ← {type: 'phasebook:set', id, cell, ok, error?}
 *   → {type: 'phasebook:get', id?}                 ← {type: 'phasebook:state', id, chapter, cell, cells, simulators}
 *
 * The page keeps nothing: its edits live in memory, for this load only.
 */
import type { ChapterCells } from './chapter.ts';
import type { LiveCell } from './cell.ts';
import { MemoryStorage } from './memory-storage.ts';
import { isShareFragment } from './share-fragment.ts';
import { EditStore } from './storage.ts';

/** The longest code a message may set, in characters: a cell is a few lines; anything near this is not one. */
const MAX_SOURCE = 100_000;

/**
 * The page's edits: in memory, holding the link's edits (if any) as run.
 * Reading a link's edits needs the share code, loaded then: an embed
 * without edits stays within a simulator's budget of script.
 */
async function embedStore(root: HTMLElement): Promise<EditStore> {
  const page = location.pathname;
  if (!isShareFragment(location.hash)) return new EditStore(page, new MemoryStorage());
  const [{ decodeShare }, { markSharedRun, planShared, sharedStore }] = await Promise.all([import('./share-format.ts'), import('./share-session.ts')]);
  const decoded = await decodeShare(location.hash);
  const cells = [...root.querySelectorAll<HTMLElement>('[data-cell]')].map((el) => ({ id: el.dataset.cell ?? '', hash: el.dataset.cellHash ?? '' }));
  const plan = decoded.ok ? planShared(decoded.edits, root.dataset.chapter ?? '', cells) : decoded.message;
  if (typeof plan === 'string') {
    // The widget is shown as the chapter has it; the reason is for whoever made the snippet.
    console.info(`Phasebook embed: the link's edits are not used. ${plan}`);
    return new EditStore(page, new MemoryStorage());
  }
  // An embed holds the chapter's cells only: a cell the reader added has nowhere to go.
  const edits = { ...plan, cells: plan.cells.filter((cell) => cell.kind === 'edit') };
  const store = sharedStore(page, edits, new Map(cells.map((cell) => [cell.id, cell.hash])));
  markSharedRun(store, edits.cells.map((cell) => cell.id));
  return store;
}

/** Reports the page's height to its parent whenever it changes. */
function reportHeight(identity: { chapter: string; cell: string }): void {
  if (window.parent === window) return;
  const main = document.querySelector('main') ?? document.body;
  let last = -1;
  const send = (): void => {
    const height = Math.ceil(main.getBoundingClientRect().bottom + scrollY);
    if (height === last) return;
    last = height;
    window.parent.postMessage({ type: 'phasebook:height', height, ...identity }, '*');
  };
  new ResizeObserver(send).observe(main);
  send();
}

/** A value as a message can carry it, or undefined: DOM nodes, functions and the like cannot be cloned. */
function portable(value: unknown): unknown {
  if (value instanceof Node || typeof value === 'function') return undefined;
  try {
    return structuredClone(value);
  } catch {
    return undefined;
  }
}

interface SimulatorLike {
  readonly simulation: { readonly t: number; readonly dt: number; readonly state: ArrayLike<number> };
  readonly model: { readonly paramNames: readonly string[]; readonly params: ArrayLike<number> };
}

/** The simulator a cell's value holds (widgets/simulator/mount.ts: `element.simulator`), if any. */
function simulatorOf(value: unknown): SimulatorLike | null {
  const handle = value instanceof HTMLElement ? (value as HTMLElement & { simulator?: SimulatorLike }).simulator : undefined;
  return handle?.simulation && handle.model ? handle : null;
}

/** What `phasebook:get` answers: every cell's code and value (where it can travel), and each simulator's state. */
function state(cells: readonly LiveCell[]) {
  const entries = cells.map((cell) => {
    const value = portable(cell.value);
    return [cell.id, { name: cell.name, source: cell.running, ...(value === undefined ? {} : { value }), ...(cell.error ? { error: cell.error } : {}) }] as const;
  });
  const simulators = cells.flatMap((cell) => {
    const sim = simulatorOf(cell.value);
    if (!sim) return [];
    const { simulation, model } = sim;
    const params = Object.fromEntries(model.paramNames.map((name, i) => [name, model.params[i]]));
    return [{ cell: cell.id, t: simulation.t, dt: simulation.dt, state: Array.from(simulation.state), params }];
  });
  return { cells: Object.fromEntries(entries), simulators };
}

/** One message from the page around: a reply for the asker, or null for a message that is not the book's. */
async function answer(data: unknown, chapter: ChapterCells, identity: { chapter: string; cell: string }): Promise<Record<string, unknown> | null> {
  if (typeof data !== 'object' || data === null) return null;
  const message = data as Record<string, unknown>;
  const id = typeof message.id === 'string' || typeof message.id === 'number' ? message.id : null;
  if (message.type === 'phasebook:get') return { type: 'phasebook:state', id, ...identity, ...state(chapter.cells) };
  if (message.type !== 'phasebook:set') return null;
  const reply = (ok: boolean, error?: string) => ({ type: 'phasebook:set', id, cell: message.cell, ok, ...(error ? { error } : {}) });
  if (typeof message.cell !== 'string' || typeof message.source !== 'string') return reply(false, 'phasebook:set needs a cell (its id or name) and a source (its code), both strings.');
  if (message.source.length > MAX_SOURCE) return reply(false, `The source is ${message.source.length} characters long; a cell may be at most ${MAX_SOURCE}.`);
  const cell = chapter.cells.find((c) => c.id === message.cell) ?? chapter.cells.find((c) => c.name === message.cell);
  if (!cell) return reply(false, `This embed has no cell “${message.cell}”; it has ${chapter.cells.map((c) => c.id).join(', ')}.`);
  await cell.setSource(message.source);
  // Code that does not parse is kept as the cell's text, not run: the message says why, as the cell does.
  return cell.running === message.source ? reply(true) : reply(false, cell.root.querySelector('[data-cell-error]')?.textContent?.trim() || 'The code did not run.');
}

function listen(chapter: ChapterCells, identity: { chapter: string; cell: string }): void {
  addEventListener('message', (event: MessageEvent) => {
    const asker = event.source as WindowProxy | null;
    void answer(event.data, chapter, identity).then((reply) => {
      if (reply && asker && event.origin !== 'null') asker.postMessage(reply, event.origin);
    });
  });
}

/**
 * Starts the embed: its store, then the cells (boot.ts's `start`, given the
 * store), then its height and its messages.
 */
export async function startEmbed(root: HTMLElement, start: (store: EditStore) => Promise<ChapterCells>): Promise<void> {
  const identity = { chapter: root.dataset.chapter ?? '', cell: root.dataset.embedCell ?? '' };
  reportHeight(identity);
  const chapter = await start(await embedStore(root));
  listen(chapter, identity);
  if (window.parent !== window) window.parent.postMessage({ type: 'phasebook:ready', ...identity, cells: chapter.cells.map((c) => c.id) }, '*');
}
