/**
 * A legend of toggle buttons, one per series: a colour swatch and the name.
 * Clicking (or Enter/Space on) an entry hides or shows its series; the
 * pressed state is exposed as aria-pressed.
 */
export interface LegendEntry {
  name: string;
  color: string;
  visible: boolean;
}

export class Legend {
  readonly element: HTMLElement;
  private readonly buttons: HTMLButtonElement[] = [];

  constructor(
    entries: readonly LegendEntry[],
    private readonly onToggle: (index: number, visible: boolean) => void,
    note?: string,
  ) {
    this.element = document.createElement('div');
    this.element.className = 'pb-legend';
    this.element.setAttribute('role', 'group');
    this.element.setAttribute('aria-label', 'Series (click to hide or show)');
    entries.forEach((entry, i) => {
      const button = document.createElement('button');
      button.type = 'button';
      button.className = 'pb-legend-entry';
      const swatch = document.createElement('span');
      swatch.className = 'pb-swatch';
      swatch.setAttribute('aria-hidden', 'true');
      const label = document.createElement('span');
      label.textContent = entry.name;
      button.append(swatch, label);
      button.title = `Hide or show ${entry.name}`;
      button.addEventListener('click', () => {
        const visible = button.getAttribute('aria-pressed') !== 'true';
        this.set(i, visible);
        this.onToggle(i, visible);
      });
      this.buttons.push(button);
      this.element.append(button);
      this.recolor(i, entry.color);
      this.set(i, entry.visible);
    });
    if (note) {
      const span = document.createElement('span');
      span.className = 'pb-legend-note';
      span.textContent = note;
      this.element.append(span);
    }
  }

  set(index: number, visible: boolean): void {
    this.buttons[index]?.setAttribute('aria-pressed', String(visible));
  }

  recolor(index: number, color: string): void {
    const swatch = this.buttons[index]?.querySelector<HTMLElement>('.pb-swatch');
    if (swatch) swatch.style.background = color;
  }
}
