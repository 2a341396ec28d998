/**
 * "Print handout" (site/components/PrintHandout.astro). The browser prints
 * in one synchronous pass right after `beforeprint`, too soon for a cell
 * that has not run to load its modules and compute: Ctrl+P prints what has
 * run (and each simulator's frame, widgets/simulator/print-frame.ts). This
 * runs every cell first, waits until each has shown its value or error and
 * the widgets have drawn, and then prints: every figure and verdict is there.
 */

/** What the handout needs of the page: to start every cell, and to hear when all have shown a result. */
export interface HandoutPage {
  startAll(): void;
  /** Settles once every cell of the page has shown its first value or error. */
  readonly complete: Promise<void>;
}

/** Resolves after the next animation frame has been drawn: the widgets draw on frames. */
function afterFrame(): Promise<void> {
  return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
}

/** Runs every cell and waits for the page to have its results drawn; `say` tells the reader where it is. */
export async function prepareHandout(page: HandoutPage, say: (text: string) => void): Promise<void> {
  say('Running every cell…');
  page.startAll();
  await page.complete;
  // A widget made by its cell's result draws its first frame on the next animation frame.
  await afterFrame();
  await afterFrame();
  say('');
}

/** Wires the button: prepares, then opens the print dialog; pressing it again meanwhile does nothing. */
export function wireHandout(button: HTMLButtonElement, status: HTMLElement, page: HandoutPage): void {
  const say = (text: string): void => {
    status.textContent = text;
  };
  button.addEventListener('click', () => {
    if (button.getAttribute('aria-disabled') === 'true') return;
    button.setAttribute('aria-disabled', 'true');
    void prepareHandout(page, say).then(() => {
      button.removeAttribute('aria-disabled');
      print();
    });
  });
}
