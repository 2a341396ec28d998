/**
 * Starts cells when they are wanted, not all at once: a cell starts when it
 * comes near the reader's view, or when a started cell reads its name. A
 * long chapter then runs, and loads the modules of, only what the reader is
 * looking at and what that depends on; the rest follows as they scroll.
 * Starting early (half a viewport ahead) gives a widget time to load
 * and draw before it is seen, so nothing appears to wait and nothing on
 * screen shifts when it does.
 *
 * `ready` is called once every cell wanted at first has shown its first
 * value or error, and `complete` once every cell of the page has (which
 * needs the reader, or a printout, to have reached them all).
 */
import type { LiveCell } from './cell.ts';

/** How far beyond the viewport a cell starts, as an IntersectionObserver margin. */
export const START_MARGIN = '50% 0px 50% 0px';

export class CellScheduler {
  readonly #byName = new Map<string, LiveCell>();
  readonly #waitingFirst = new Set<LiveCell>();
  /** Every cell of the page that has not shown a first result yet. */
  readonly #unfinished = new Set<LiveCell>();
  readonly #ready: () => void;
  readonly #complete: () => void;
  #settled = false;
  /** True once the cells near the view at load have been found (and started). */
  #initialRound = false;
  #observer: IntersectionObserver | null = null;

  readonly #starting: (cell: LiveCell) => void;

  /** `starting` hears of each cell just before it starts, to fetch what it will need. */
  constructor(ready: () => void, complete: () => void = () => {}, starting: (cell: LiveCell) => void = () => {}) {
    this.#ready = ready;
    this.#complete = complete;
    this.#starting = starting;
  }

  /** Adds the page's cells; call {@link watch} once all are added. */
  add(cell: LiveCell): void {
    if (cell.name && !this.#byName.has(cell.name)) this.#byName.set(cell.name, cell);
    this.#unfinished.add(cell);
  }

  /**
   * Starts the cells near the view now and the others as they come near.
   * Without IntersectionObserver (or with `all`, e.g. for printing) every cell starts.
   */
  watch(cells: readonly LiveCell[], all = typeof IntersectionObserver === 'undefined'): void {
    if (all) {
      for (const cell of cells) this.want(cell);
      this.#initialRoundDone();
      return;
    }
    let first = true;
    const byRoot = new Map(cells.map((cell) => [cell.root, cell]));
    // A link to a cell (`/kepler/#cell-stars`) says what the reader came for: start it now, not after the first layout.
    // (The page itself shows the linked place from its first paint: site/lib/fragment.ts.)
    const target = linkedElement()?.closest<HTMLElement>('[data-cell]');
    const linked = target ? byRoot.get(target) : undefined;
    if (linked) this.want(linked);
    this.#observer = new IntersectionObserver(
      (entries) => {
        for (const entry of entries) {
          const cell = byRoot.get(entry.target as HTMLElement);
          if (!entry.isIntersecting || !cell) continue;
          this.#observer?.unobserve(entry.target);
          this.want(cell);
        }
        if (first) {
          first = false;
          this.#initialRoundDone();
        }
      },
      { rootMargin: START_MARGIN },
    );
    for (const cell of cells) this.#observer.observe(cell.root);
    if (cells.length === 0) {
      this.#initialRoundDone();
      this.#complete();
    }
  }

  /** Starts `cell` (if it has not started); the cells it reads follow through {@link wantInputs}. */
  want(cell: LiveCell): void {
    if (cell.started) return;
    this.#observer?.unobserve(cell.root);
    if (!this.#settled) this.#waitingFirst.add(cell);
    this.#starting(cell);
    void cell.start();
  }

  /** A cell is being defined and reads `names`: the cells defining them must run. */
  wantInputs(names: readonly string[]): void {
    for (const name of names) {
      const cell = this.#byName.get(name);
      if (cell) this.want(cell);
    }
  }

  /** A cell showed its first value or error. */
  firstResult(cell: LiveCell): void {
    if (this.#unfinished.delete(cell) && this.#unfinished.size === 0) this.#complete();
    if (!this.#waitingFirst.delete(cell) || this.#settled) return;
    this.#checkSettled();
  }

  #initialRoundDone(): void {
    this.#initialRound = true;
    this.#checkSettled();
  }

  #checkSettled(): void {
    if (this.#settled || !this.#initialRound || this.#waitingFirst.size > 0) return;
    this.#settled = true;
    this.#ready();
  }
}

/** The element the page's URL fragment names, if any. */
function linkedElement(): Element | null {
  if (location.hash.length < 2) return null;
  try {
    return document.getElementById(decodeURIComponent(location.hash.slice(1)));
  } catch {
    return null; // a malformed escape in the fragment
  }
}
