/**
 * The sandbox reader code runs in: loaded (its own chunk) and installed
 * before the first code that is not the chapter's own runs — an edit, an
 * added cell, a shared link's edits once the reader runs them — so that a
 * page whose reader only reads pays nothing for it. Installed once per
 * page; from then on it holds for every cell, the chapter's too.
 *
 * - code made from text is refused (code-from-text.ts);
 * - each cell's timers and listeners are its own, and go with it when it is
 *   defined again or its loops keep being stopped (callbacks.ts);
 * - huge allocations are refused (allocation.ts, through the cell's scope);
 * - navigation, windows, dialogs and history stay the reader's (navigation.ts);
 * - frames, link hints to other sites and meta refresh never enter the page (dom-guard.ts);
 * - WebRTC and the like are gone (network.ts);
 * - a page reloading itself in a loop is seen (reload-loop.ts, reload-notice.ts).
 *
 * README, "What a cell can do", states what this does and does not protect.
 */
import type { CellScope } from '../cell-definition.ts';
import { recentCell } from '../cell-errors.ts';
import type { LiveCell } from '../cell.ts';
import type { EditStore } from '../storage.ts';
import { allocationScope } from './allocation.ts';
import { CellCallbacks, type Cleared } from './callbacks.ts';
import { guardCodeFromText } from './code-from-text.ts';
import { guardElements } from './dom-guard.ts';
import { guardNavigation } from './navigation.ts';
import { removeUngoverned } from './network.ts';
import { editsKey, leaveNote, loopTurns, selfLoadNote, takeNote, type ThisLoad } from './reload-loop.ts';
import { ReloadLoopNotice, type HeldCell } from './reload-notice.ts';

/** Stops of one cell's loops within {@link STOP_WINDOW_MS} after which its timers and listeners are cleared. */
export const STOPS_BEFORE_CLEARING = 2;
export const STOP_WINDOW_MS = 60_000;

export interface Sandbox {
  /** The names reader code sees in place of the page's (compileCell's scope). */
  readonly scope: CellScope;
  /** True when a cell with a saved edit must show it unrun: the page is reloading itself in a loop. */
  holdSaved(cell: HeldCell): boolean;
  /** A loop of `cell` was stopped: when its loops keep being stopped, its callbacks are cleared and this says so; else null. */
  loopStopped(cell: string): string | null;
  /** `cell` is being defined again: the timers and listeners of its old code go. */
  redefining(cell: string): void;
}

let installed: Sandbox | null = null;

/** Installs the sandbox over the page whose edits `store` keeps and whose cells `cells` lists. */
export function installSandbox(store: EditStore, cells: () => readonly LiveCell[]): Sandbox {
  if (installed) return installed;
  // What the sandbox has to say about a cell shows under it (under the cell that ran last, when it cannot tell).
  const report = (id: string | null, message: string) => {
    const cell = cells().find((c) => c.id === (id ?? recentCell()));
    if (cell) cell.showLaterError(message);
    else console.warn(message);
  };
  // The reader's code that runs on this page, as stored: what a reload would run.
  const edits = () => store.all().flatMap(({ cellId, edit }) => (edit.ran !== null ? [[cellId, edit.ran] as const] : []));
  const ranAt = performance.timeOrigin + performance.now();
  const load = (): ThisLoad => ({ path: location.pathname, loadedAt: performance.timeOrigin, ranAt, edits: editsKey(edits()) });
  const turns = loopTurns(takeNote(), load());
  const notice = new ReloadLoopNotice(turns);

  const codeScope = guardCodeFromText();
  const callbacks = new CellCallbacks();
  guardNavigation({
    report,
    selfLoad: () => leaveNote(selfLoadNote(load(), Date.now(), turns)),
  });
  guardElements();
  removeUngoverned();

  const stops = new Map<string, number[]>();
  installed = {
    scope: { ...allocationScope(), Function: codeScope.Function, eval: codeScope.eval },
    holdSaved: (cell) => notice.hold(cell),
    loopStopped(cell) {
      const now = performance.now();
      const recent = (stops.get(cell) ?? []).filter((t) => t > now - STOP_WINDOW_MS);
      recent.push(now);
      stops.set(cell, recent);
      if (recent.length < STOPS_BEFORE_CLEARING) return null;
      stops.delete(cell);
      return `since this keeps happening, ${clearedText(callbacks.clear(cell))}.`;
    },
    redefining(cell) {
      stops.delete(cell);
      callbacks.clear(cell);
    },
  };
  return installed;
}

/** "the cell's timer was cleared", "the cell's 2 timers and 1 listener were cleared". */
function clearedText({ timers, listeners }: Cleared): string {
  const count = (n: number, word: string) => (n === 1 ? word : `${n} ${word}s`);
  const what = [timers ? count(timers, 'timer') : '', listeners ? count(listeners, 'listener') : ''].filter(Boolean).join(' and ');
  if (!what) return "the cell's timers and listeners were cleared";
  return `the cell's ${what} ${timers + listeners === 1 ? 'was' : 'were'} cleared`;
}
