/**
 * The search box's behaviour, loaded when the reader first focuses it or
 * presses `/` (site/lib/search-box.ts). Pagefind runs in a worker
 * (search-worker.ts); this side sends what is typed and shows what comes
 * back: for each chapter, its best sections, each a link to its heading,
 * with the matched words marked.
 *
 * Keyboard: typing searches; ↓ and ↑ move through the results and back to
 * the box; Enter in the box opens the first section found; Escape closes the
 * results and returns to the box. The status line is a live region, so a
 * screen reader hears how many chapters match. Once the whole index is in
 * the worker (search works offline from then on), the form is marked
 * `data-search-held`.
 */
import { excerptPieces } from './excerpt.ts';
import type { FromWorker, PageHit, ToWorker } from './protocol.ts';

/** A query longer than this is cut: no one types more, and Pagefind need not read a pasted page. */
const LONGEST_QUERY = 200;
/** Typing pauses this long before a search: each key would otherwise redraw the list under the reader's eyes. */
const PAUSE_MS = 90;

const HINT = 'Search the text and the formulas of every chapter; a formula by its TeX too, as in \\partial H.';

interface Parts {
  readonly form: HTMLFormElement;
  readonly input: HTMLInputElement;
  readonly panel: HTMLElement;
  readonly status: HTMLElement;
  readonly list: HTMLElement;
}

class SearchBox {
  #worker: Worker | null = null;
  #ready = false;
  #failed = false;
  #asked = 0;
  #timer: ReturnType<typeof setTimeout> | undefined;

  constructor(private readonly parts: Parts) {
    const { form, input, panel } = parts;
    input.addEventListener('focus', () => this.open());
    input.addEventListener('input', () => this.#soon());
    // Enter goes to the best place: the first chapter's densest section.
    form.addEventListener('submit', (event) => {
      event.preventDefault();
      this.parts.list.querySelector<HTMLAnchorElement>('a.search-section')?.click();
    });
    form.addEventListener('keydown', (event) => this.#key(event));
    // Leaving the box and its results, by keyboard or pointer, closes them.
    form.addEventListener('focusout', (event) => {
      if (!(event.relatedTarget instanceof Node && form.contains(event.relatedTarget))) this.close();
    });
    document.addEventListener('pointerdown', (event) => {
      if (!(event.target instanceof Node && form.contains(event.target))) this.close();
    });
    // A result on this page moves the view without loading a page: the results step aside.
    panel.addEventListener('click', (event) => {
      if (event.target instanceof Element && event.target.closest('a')) {
        this.close();
        input.blur();
      }
    });
  }

  /** Shows the panel, starting the worker the first time and again after a failure. */
  open(): void {
    this.parts.panel.hidden = false;
    if (!this.#worker || this.#failed) this.#start();
    else this.#soon(0);
  }

  close(): void {
    this.parts.panel.hidden = true;
  }

  #start(): void {
    this.#failed = false;
    this.#say('Loading the index…');
    try {
      this.#worker ??= this.#makeWorker();
    } catch (error) {
      this.#fail({ kind: 'failed', offline: false, message: error instanceof Error ? error.message : String(error) });
      return;
    }
    const { searchIndex = '/pagefind/', searchBase = '/' } = this.parts.form.dataset;
    this.#send({ kind: 'open', index: new URL(searchIndex, location.href).href, base: searchBase });
  }

  #makeWorker(): Worker {
    const worker = new Worker(new URL('./search-worker.ts', import.meta.url), { type: 'module', name: 'phasebook-search' });
    worker.onmessage = ({ data }: MessageEvent<FromWorker>) => this.#receive(data);
    // The worker's own script could not be fetched: the connection is gone.
    worker.onerror = () => {
      this.#worker = null;
      this.#fail({ kind: 'failed', offline: true, message: 'the search worker did not load' });
    };
    return worker;
  }

  #send(message: ToWorker): void {
    this.#worker?.postMessage(message);
  }

  #receive(message: FromWorker): void {
    if (message.kind === 'ready') {
      this.#ready = true;
      this.#soon(0);
    } else if (message.kind === 'held') {
      this.parts.form.dataset.searchHeld = '';
    } else if (message.kind === 'failed') {
      this.#fail(message);
    } else if (message.kind === 'results' && message.id === this.#asked) {
      this.#show(this.#query(), message.total, message.pages);
    }
  }

  #fail(message: Extract<FromWorker, { kind: 'failed' }>): void {
    this.#failed = true;
    this.#ready = false;
    this.parts.list.replaceChildren();
    this.#say(
      message.offline
        ? "Search could not load its index: the connection to the book's site seems to be lost. Try again when you are back online."
        : `Search is not available: ${message.message}`,
    );
  }

  #query(): string {
    return this.parts.input.value.trim().slice(0, LONGEST_QUERY);
  }

  /** Searches what the box holds once typing pauses. */
  #soon(pause = PAUSE_MS): void {
    clearTimeout(this.#timer);
    this.#timer = setTimeout(() => this.#search(), pause);
  }

  #search(): void {
    if (!this.#ready) return;
    const query = this.#query();
    this.#asked++;
    if (!query) {
      this.parts.list.replaceChildren();
      this.#say(HINT);
      return;
    }
    this.#send({ kind: 'search', id: this.#asked, query });
  }

  #show(query: string, total: number, pages: readonly PageHit[]): void {
    this.parts.list.replaceChildren(...pages.map(pageItem));
    this.#say(total === 0 ? `No chapter matches “${query}”.` : `${total === 1 ? 'One chapter matches' : `${total} chapters match`} “${query}”.`);
  }

  #say(text: string): void {
    if (this.parts.status.textContent !== text) this.parts.status.textContent = text;
  }

  #links(): HTMLAnchorElement[] {
    return [...this.parts.list.querySelectorAll<HTMLAnchorElement>('a[href]')];
  }

  #key(event: KeyboardEvent): void {
    const { input } = this.parts;
    if (event.key === 'Escape') {
      if (this.parts.panel.hidden) return;
      event.preventDefault();
      this.close();
      input.focus();
      return;
    }
    if (event.key !== 'ArrowDown' && event.key !== 'ArrowUp') return;
    const links = this.#links();
    if (!links.length) return;
    event.preventDefault();
    const at = links.indexOf(document.activeElement as HTMLAnchorElement);
    const next = event.key === 'ArrowDown' ? at + 1 : at - 1;
    if (next < 0) input.focus();
    else links[Math.min(next, links.length - 1)]?.focus();
    // Moving back into the box re-opens the results Escape closed.
    this.parts.panel.hidden = false;
  }
}

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
  const node = document.createElement(tag);
  node.className = className;
  if (text !== undefined) node.textContent = text;
  return node;
}

/** A chapter's entry: its title, then its sections with their excerpts. */
function pageItem(page: PageHit): HTMLLIElement {
  const item = document.createElement('li');
  const title = element('a', 'search-page', page.title);
  title.href = page.url;
  const sections = document.createElement('ol');
  for (const section of page.sections) {
    const link = element('a', 'search-section');
    link.href = section.url;
    const excerpt = element('span', 'search-excerpt');
    excerpt.append(...excerptPieces(section.excerpt).map((piece) => (piece.marked ? element('mark', '', piece.text) : document.createTextNode(piece.text))));
    link.append(element('span', 'search-section-title', section.title), excerpt);
    const entry = document.createElement('li');
    entry.append(link);
    sections.append(entry);
  }
  item.append(title, sections);
  return item;
}

const boxes = new WeakMap<HTMLFormElement, SearchBox>();

/** Wires the search box `form` (site/components/SearchBox.astro) once, and opens it. */
export function openSearch(form: HTMLFormElement): void {
  let box = boxes.get(form);
  if (!box) {
    const part = <T extends HTMLElement>(selector: string): T => {
      const found = form.querySelector<T>(selector);
      if (!found) throw new Error(`the search box has no ${selector}`);
      return found;
    };
    box = new SearchBox({
      form,
      input: part<HTMLInputElement>('input[type="search"]'),
      panel: part('[data-search-panel]'),
      status: part('[data-search-status]'),
      list: part('[data-search-results]'),
    });
    boxes.set(form, box);
  }
  if (form.contains(document.activeElement)) box.open();
}
