/**
 * The notice of a page that reloaded itself in a loop (reload-loop.ts): the
 * reader's saved edits are shown and not run, and the reader decides, once
 * for the page: **Run my edits** (each held cell runs its edit, and cells
 * that start later run theirs) or **Keep them off** (each stays as an unrun
 * draft, kept for the reader to fix).
 */

/** A cell whose saved edit is held. */
export interface HeldCell {
  runHeld(): void;
  keepHeldOff(): void;
}

export type Decision = 'pending' | 'run' | 'off';

export class ReloadLoopNotice {
  readonly #held: HeldCell[] = [];
  readonly #turns: number;
  #decision: Decision = 'pending';
  #element: HTMLElement | null = null;

  constructor(turns: number) {
    this.#turns = turns;
  }

  /**
   * A cell with a saved edit is starting: true when it must hold the edit
   * (the notice then lists it), false when it may run it.
   */
  hold(cell: HeldCell): boolean {
    if (this.#turns === 0 || this.#decision === 'run') return false;
    if (this.#decision === 'off') {
      cell.keepHeldOff();
      return true;
    }
    this.#held.push(cell);
    this.#show();
    return true;
  }

  #show(): void {
    if (this.#element) return;
    const element = document.createElement('div');
    element.className = 'share-banner';
    element.setAttribute('role', 'alert');
    element.dataset.reloadLoop = '';
    const text = document.createElement('p');
    const times = this.#turns === 1 ? 'as soon as your edits ran' : `${this.#turns} times in a row, each as soon as your edits ran`;
    text.textContent = `This page reloaded itself ${times}: that is a loop, so your edits are shown but not run now.`;
    const actions = document.createElement('div');
    actions.className = 'share-actions';
    const button = (label: string, decide: Decision) => {
      const b = document.createElement('button');
      b.type = 'button';
      b.className = 'cell-button';
      b.textContent = label;
      b.addEventListener('click', () => this.#decide(decide));
      return b;
    };
    actions.append(button('Run my edits', 'run'), button('Keep them off', 'off'));
    element.append(text, actions);
    const place = document.querySelector('[data-share-edits]') ?? document.querySelector('[data-chapter]');
    place?.prepend(element);
    this.#element = element;
  }

  #decide(decision: Decision): void {
    this.#decision = decision;
    this.#element?.remove();
    for (const cell of this.#held.splice(0)) {
      if (decision === 'run') cell.runHeld();
      else cell.keepHeldOff();
    }
  }
}
