/** Lines of the readout under a spectrum listing up to `peaks` peaks (shared with simulator/reserve.ts). */
export function readoutLines(peaks: number): number {
  return peaks + 2;
}

/**
 * The text under a spectrum: a numbered list of peaks (numbered as on the
 * plot), the comparison with the theoretical value, and what the spectrum
 * was computed from. Text rather than canvas so it can be read by a screen
 * reader and copied; elements are reused, since it changes a few times a second.
 */
export class SpectrumReadout {
  readonly element: HTMLDivElement;
  private readonly list: HTMLOListElement;
  private readonly comparison: HTMLParagraphElement;
  private readonly note: HTMLParagraphElement;
  private readonly basis: HTMLParagraphElement;

  /**
   * @param peaks the most peaks it lists: with the comparison and the line
   *   on what the spectrum was computed from, the lines it is tall enough for
   *   (readoutLines). Its height is fixed, so that peaks coming and going
   *   never move the page; text that wraps on a narrow screen scrolls.
   */
  constructor(peaks: number) {
    this.element = document.createElement('div');
    this.element.className = 'pb-spectrum-readout';
    this.element.style.setProperty('--pb-readout-lines', String(readoutLines(peaks)));
    // Scrollable, so it must be reachable by keyboard.
    this.element.tabIndex = 0;
    this.element.setAttribute('role', 'region');
    this.element.setAttribute('aria-label', 'Spectrum peaks');
    this.list = document.createElement('ol');
    this.list.className = 'pb-spectrum-peaks';
    this.list.style.cssText = 'margin:0;padding-left:1.6em;';
    const paragraph = (name: string, muted: boolean) => {
      const p = document.createElement('p');
      p.className = name;
      p.style.cssText = `margin:0.15em 0 0;${muted ? 'color:var(--muted,#5e5b55);' : ''}`;
      return p;
    };
    this.comparison = paragraph('pb-spectrum-theory', false);
    this.note = paragraph('pb-spectrum-note', true);
    this.basis = paragraph('pb-spectrum-basis', true);
    this.element.append(this.list, this.comparison, this.note, this.basis);
  }

  show(peaks: readonly string[], basis: string, comparison?: string, note?: string): void {
    const items = this.list.children;
    while (items.length > peaks.length) items[items.length - 1].remove();
    while (items.length < peaks.length) this.list.append(document.createElement('li'));
    peaks.forEach((text, i) => set(items[i], text));
    set(this.comparison, comparison ?? '');
    set(this.note, note ?? '');
    set(this.basis, basis);
  }
}

function set(element: Element, text: string): void {
  if (element.textContent !== text) element.textContent = text;
  (element as HTMLElement).hidden = text === '';
}
