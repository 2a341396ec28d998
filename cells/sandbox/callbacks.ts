/**
 * The timers, animation frames and event listeners each cell has set, so
 * that they can go with the cell: when the cell is defined again (its old
 * code's callbacks are obsolete, and an interval left behind would run for
 * ever), and when its callbacks keep getting stopped by the loop guard
 * (`setInterval(() => { while (true) {} }, 100)` would otherwise stall the
 * page for 2 s at every tick, for ever).
 *
 * The page's setTimeout, setInterval, requestAnimationFrame,
 * requestIdleCallback and addEventListener are replaced by versions that
 * note a cell's calls (caller.ts) and pass the book's own through. A string
 * given as a timer's code is refused: it is eval (code-from-text.ts).
 */
import { callerCell } from './caller.ts';
import { CodeFromText } from './code-from-text.ts';

/** One cell's callbacks. */
interface Owned {
  readonly timeouts: Set<unknown>;
  readonly intervals: Set<unknown>;
  readonly frames: Set<unknown>;
  readonly idles: Set<unknown>;
  readonly listeners: Set<{ target: EventTarget; type: string; listener: EventListenerOrEventListenerObject; capture: boolean }>;
}

/** What a cell's callbacks amounted to, for the line said when they are cleared. */
export interface Cleared {
  readonly timers: number;
  readonly listeners: number;
}

/** The cell whose timer or frame callback is running now, if any. */
let running: string | null = null;

/**
 * The cell whose timer, interval or frame callback is running: its code
 * may call the book's own functions (`setTimeout(location.reload.bind(location))`),
 * so the stack alone does not always name it.
 */
export function callbackCell(): string | null {
  return running;
}

const captureOf = (options: unknown): boolean => (typeof options === 'boolean' ? options : Boolean((options as AddEventListenerOptions | undefined)?.capture));

type Fn = (this: unknown, ...args: unknown[]) => unknown;

export class CellCallbacks {
  readonly #owned = new Map<string, Owned>();
  /** The page's own functions, as they were before. */
  readonly #real: Record<'setTimeout' | 'clearTimeout' | 'setInterval' | 'clearInterval' | 'requestAnimationFrame' | 'cancelAnimationFrame' | 'requestIdleCallback' | 'cancelIdleCallback' | 'addEventListener' | 'removeEventListener', Fn | undefined>;

  /** Replaces the page's scheduling functions by ones that note which cell called them. */
  constructor(global: typeof globalThis = globalThis) {
    const g = global as unknown as Record<string, Fn | undefined>;
    const target = global.EventTarget.prototype as unknown as Record<string, Fn>;
    this.#real = {
      setTimeout: g.setTimeout,
      clearTimeout: g.clearTimeout,
      setInterval: g.setInterval,
      clearInterval: g.clearInterval,
      requestAnimationFrame: g.requestAnimationFrame,
      cancelAnimationFrame: g.cancelAnimationFrame,
      requestIdleCallback: g.requestIdleCallback,
      cancelIdleCallback: g.cancelIdleCallback,
      addEventListener: target.addEventListener,
      removeEventListener: target.removeEventListener,
    };
    const real = this.#real as Record<string, Fn>;
    const self = this;
    const owned = (what: keyof Omit<Owned, 'listeners'>): { cell: string; set: Set<unknown> } | null => {
      const cell = callerCell();
      return cell === null ? null : { cell, set: self.#of(cell)[what] as Set<unknown> };
    };
    /** `callback`, run as `cell`'s (see callbackCell). */
    const as = (cell: string, callback: Fn): Fn =>
      function (this: unknown, ...args: unknown[]) {
        const outer = running;
        running = cell;
        try {
          return callback.apply(this, args);
        } finally {
          running = outer;
        }
      };
    const code = (handler: unknown, what: string) => {
      if (typeof handler === 'string' && callerCell() !== null) throw new CodeFromText(`${what} with a string of code`);
    };
    /** `callback`, run as `owner.cell`'s, forgetting its handle once it has run. */
    const once = (owner: { cell: string; set: Set<unknown> }, callback: Fn, handle: { id?: unknown }): Fn => {
      const call = as(owner.cell, callback);
      return function (this: unknown, ...args: unknown[]) {
        owner.set.delete(handle.id);
        return call.apply(this, args);
      };
    };

    g.setTimeout = function (handler: unknown, ...rest: unknown[]) {
      code(handler, 'setTimeout');
      const owner = typeof handler === 'function' ? owned('timeouts') : null;
      if (!owner) return real.setTimeout.call(global, handler, ...rest);
      const handle: { id?: unknown } = {};
      handle.id = real.setTimeout.call(global, once(owner, handler as Fn, handle), ...rest);
      owner.set.add(handle.id);
      return handle.id;
    };
    g.setInterval = function (handler: unknown, ...rest: unknown[]) {
      code(handler, 'setInterval');
      const owner = typeof handler === 'function' ? owned('intervals') : null;
      if (!owner) return real.setInterval.call(global, handler, ...rest);
      const id = real.setInterval.call(global, as(owner.cell, handler as Fn), ...rest);
      owner.set.add(id);
      return id;
    };
    g.requestAnimationFrame = function (callback: unknown) {
      const owner = owned('frames');
      if (!owner) return real.requestAnimationFrame.call(global, callback);
      const handle: { id?: unknown } = {};
      handle.id = real.requestAnimationFrame.call(global, once(owner, callback as Fn, handle));
      owner.set.add(handle.id);
      return handle.id;
    };
    if (real.requestIdleCallback) {
      g.requestIdleCallback = function (callback: unknown, ...rest: unknown[]) {
        const owner = owned('idles');
        if (!owner) return real.requestIdleCallback.call(global, callback, ...rest);
        const handle: { id?: unknown } = {};
        handle.id = real.requestIdleCallback.call(global, once(owner, callback as Fn, handle), ...rest);
        owner.set.add(handle.id);
        return handle.id;
      };
    }
    // A cell that clears its own timer, or removes its own listener, owns it no more.
    const forget = (what: keyof Omit<Owned, 'listeners'>, id: unknown) => {
      for (const owned of self.#owned.values()) (owned[what] as Set<unknown>).delete(id);
    };
    const clearing = (what: keyof Omit<Owned, 'listeners'>, clear: Fn) =>
      function (id: unknown) {
        forget(what, id);
        return clear.call(global, id);
      };
    g.clearTimeout = clearing('timeouts', real.clearTimeout);
    g.clearInterval = clearing('intervals', real.clearInterval);
    g.cancelAnimationFrame = clearing('frames', real.cancelAnimationFrame);
    if (real.cancelIdleCallback) g.cancelIdleCallback = clearing('idles', real.cancelIdleCallback);
    target.removeEventListener = function (this: unknown, type: unknown, listener: unknown, options?: unknown) {
      const on = (this ?? global) as EventTarget;
      const capture = captureOf(options);
      for (const owned of self.#owned.values()) {
        for (const entry of owned.listeners) {
          if (entry.target === on && entry.type === type && entry.listener === listener && entry.capture === capture) owned.listeners.delete(entry);
        }
      }
      return real.removeEventListener.call(on, type, listener, options);
    };
    target.addEventListener = function (this: unknown, type: unknown, listener: unknown, options?: unknown) {
      const on = (this ?? global) as EventTarget;
      const cell = listener ? callerCell() : null;
      if (cell !== null) self.#of(cell).listeners.add({ target: on, type: String(type), listener: listener as EventListenerOrEventListenerObject, capture: captureOf(options) });
      return real.addEventListener.call(on, type, listener, options);
    };
  }

  /**
   * Clears every timer, frame and listener `cell` has set, and says how many
   * there were. The cell's code can set new ones when it runs again.
   */
  clear(cell: string): Cleared {
    const owned = this.#owned.get(cell);
    if (!owned) return { timers: 0, listeners: 0 };
    this.#owned.delete(cell);
    const real = this.#real;
    owned.timeouts.forEach((id) => real.clearTimeout?.call(globalThis, id));
    owned.intervals.forEach((id) => real.clearInterval?.call(globalThis, id));
    owned.frames.forEach((id) => real.cancelAnimationFrame?.call(globalThis, id));
    owned.idles.forEach((id) => real.cancelIdleCallback?.call(globalThis, id));
    for (const { target, type, listener, capture } of owned.listeners) real.removeEventListener?.call(target, type, listener, capture);
    return { timers: owned.timeouts.size + owned.intervals.size + owned.frames.size + owned.idles.size, listeners: owned.listeners.size };
  }

  #of(cell: string): Owned {
    let owned = this.#owned.get(cell);
    if (!owned) {
      owned = { timeouts: new Set(), intervals: new Set(), frames: new Set(), idles: new Set(), listeners: new Set() };
      this.#owned.set(cell, owned);
    }
    return owned;
  }
}
