/**
 * Keeps a reader's cell from breaking the page for the other cells and the
 * widgets. Cells run in the page's own global scope, so a cell can replace
 * `Math.sqrt` (which every generated stepper and plot calls) or empty
 * `document.body`. The first is undone at once; the second cannot be, so
 * the page says what happened and how to get it back (recovery.ts).
 */

/** Math as the page found it: every function and constant. */
export class MathSnapshot {
  readonly #values = new Map<string, unknown>();

  constructor() {
    for (const name of Object.getOwnPropertyNames(Math)) this.#values.set(name, Reflect.get(Math, name));
  }

  /** Puts back whatever was replaced or deleted, and names it. */
  restore(): string[] {
    const changed: string[] = [];
    for (const [name, value] of this.#values) {
      if (Reflect.get(Math, name) === value) continue;
      changed.push(`Math.${name}`);
      try {
        Object.defineProperty(Math, name, { value, writable: true, configurable: true, enumerable: false });
      } catch {
        // A frozen or redefined-as-unconfigurable property: the change is reported, not undone.
      }
    }
    return changed;
  }
}

/** True while the chapter's content is still in the page (a cell may have emptied it). */
export function pageIntact(chapterRoot: Element): boolean {
  return chapterRoot.isConnected && document.body?.contains(chapterRoot) === true;
}
