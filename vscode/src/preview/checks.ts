/**
 * Reads the theory checks a cell shows, once it has settled: the verdict and
 * numbers widgets/chapter/theory-check/theory-check.ts writes on its element's data
 * attributes (the ones the book's end-to-end tests read), with its label and
 * lines. A readout without `data-verdict` (an older widget) has agreed or not.
 */
import type { CheckResult, CheckVerdict, TheoryCheckReading } from '../shared/messages.ts';
import type { PreviewCell } from './preview-cell.ts';

/** Two animation frames: the runtime computes on one, so by then every redefined cell has gone pending. */
function frames(): Promise<void> {
  return new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(() => resolve())));
}

const VERDICTS: readonly CheckVerdict[] = ['agrees', 'disagrees', 'outside', 'undefined'];

/** A number the widget wrote, or NaN where it wrote none (it leaves out values that are not numbers). */
const number = (text: string | undefined) => (text === undefined || text === '' ? NaN : Number(text));

function reading(element: HTMLElement): TheoryCheckReading {
  const data = element.dataset;
  const rows = [...element.querySelectorAll('dt')].map((dt) => `${dt.textContent}: ${dt.nextElementSibling?.textContent ?? ''}`);
  const verdict = VERDICTS.find((v) => v === data.verdict) ?? (data.agrees === 'true' ? 'agrees' : 'disagrees');
  return {
    label: element.querySelector('figcaption strong')?.textContent ?? '',
    measured: number(data.measured),
    predicted: number(data.predicted),
    tolerance: number(data.tolerance),
    relative: data.relative === 'true',
    error: number(data.error),
    verdict,
    reason: data.reason ?? '',
    text: rows.join('\n'),
  };
}

export async function readChecks(cells: ReadonlyMap<string, PreviewCell>, ids: readonly string[], timeoutMs: number): Promise<CheckResult[]> {
  await frames();
  const deadline = new Promise<'timeout'>((resolve) => setTimeout(() => resolve('timeout'), timeoutMs));
  return Promise.all(
    ids.map(async (id): Promise<CheckResult> => {
      const cell = cells.get(id);
      if (!cell) return { id, state: 'missing', checks: [] };
      if ((await Promise.race([cell.settled(), deadline])) === 'timeout') return { id, state: 'timeout', checks: [] };
      if (cell.state === 'rejected') return { id, state: 'rejected', error: cell.root.querySelector('[data-cell-error]')?.textContent ?? cell.error, checks: [] };
      const found = [...cell.root.querySelectorAll<HTMLElement>('[data-cell-output] [data-widget="theory-check"]')];
      return { id, state: 'fulfilled', checks: found.map(reading) };
    }),
  );
}
