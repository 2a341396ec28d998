/**
 * Loads the heavy halves of the cell machinery only when they are needed:
 * the editor (CodeMirror, ~140 kB gzip) on the first interaction with a cell
 * or once the page has settled and the browser is idle, the parser (acorn,
 * ~40 kB gzip) on the first Run of changed source.
 */

/** How long after the cells' first values the idle preload may start. */
const IDLE_PRELOAD_DELAY_MS = 3000;

let editorModule: Promise<typeof import('./editor.ts')> | null = null;
let parserModule: Promise<typeof import('./parse.ts')> | null = null;

export function loadEditor(): Promise<typeof import('./editor.ts')> {
  return (editorModule ??= import('./editor.ts'));
}

export function loadParser(): Promise<typeof import('./parse.ts')> {
  return (parserModule ??= import('./parse.ts'));
}

function whenIdle(task: () => void): void {
  if (typeof requestIdleCallback === 'function') requestIdleCallback(task, { timeout: 10_000 });
  else setTimeout(task, 200);
}

function prefersSavingData(): boolean {
  const connection = (navigator as Navigator & { connection?: { saveData?: boolean } }).connection;
  return connection?.saveData === true;
}

/**
 * Runs `tasks` one per idle period, starting a while after the page settled,
 * so mounting editors never competes with the reader's first scroll.
 * Skipped when the reader asked the browser to save data.
 */
export function scheduleIdle(tasks: ReadonlyArray<() => void | Promise<void>>): void {
  if (prefersSavingData()) return;
  const queue = [...tasks];
  const next = () => {
    const task = queue.shift();
    if (!task) return;
    whenIdle(() => {
      void Promise.resolve()
        .then(task)
        .catch(() => undefined)
        .then(next);
    });
  };
  setTimeout(next, IDLE_PRELOAD_DELAY_MS);
}
