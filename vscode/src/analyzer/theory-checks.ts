/**
 * Theory checks as tests: which cells hold one (they read the `theoryCheck`
 * builtin, by the parser's own list of inputs), what to call them, and
 * what a run of one says once the preview has read its readout.
 */
import type { CheckResult, TheoryCheckReading } from '../shared/messages.ts';
import type { ChapterCell } from './cells.ts';

export interface CheckCell {
  readonly cell: ChapterCell;
  /** The check's `label` as the cell writes it (the first, if it makes several), else the cell's name. */
  readonly label: string;
}

const LABEL = /\blabel\s*:\s*(['"`])((?:\\.|(?!\1).)*)\1/;

/**
 * A label written as a template literal, as the Test Explorer shows it. Its
 * substitutions are known only when the cell runs (a cell that makes a
 * check per method labels each `Order of ${method}`), so each is shown as
 * "…" and the label keeps its static parts: "Order of …". Each check's
 * own label, with its values, is in the test's output after a run.
 */
export function staticLabel(template: string): string {
  let text = '';
  for (let i = 0; i < template.length; i++) {
    if (template[i] === '\\') {
      text += template.slice(i, i + 2);
      i++;
    } else if (template.startsWith('${', i)) {
      let depth = 0;
      for (; i < template.length; i++) {
        if (template[i] === '{') depth++;
        else if (template[i] === '}' && --depth === 0) break;
      }
      text += '…';
    } else {
      text += template[i];
    }
  }
  return text;
}

export function checkCells(cells: readonly ChapterCell[]): CheckCell[] {
  return cells.flatMap((cell) => {
    if (!cell.spec?.inputs.includes('theoryCheck')) return [];
    const written = LABEL.exec(cell.source);
    const label = written ? (written[1] === '`' ? staticLabel(written[2]) : written[2]) : (cell.name ?? `cell ${cell.index + 1}`);
    return [{ cell, label }];
  });
}

/**
 * A test's outcome: `skipped` when the formula's regime does not hold (the
 * check then judges nothing, as the book says), `errored` when the cell
 * failed or a check could give no verdict, `failed` when the check
 * disagrees or had no verdict within its time limit.
 */
export interface Verdict {
  readonly outcome: 'passed' | 'failed' | 'skipped' | 'errored';
  readonly message: string;
  /** For a failed check: what theory allows, and what the simulation gave. */
  readonly expected?: string;
  readonly actual?: string;
}

const shown = (x: number) => (Number.isFinite(x) ? String(x) : '—');

function size(reading: TheoryCheckReading, x: number): string {
  if (!Number.isFinite(x)) return '—';
  return reading.relative ? `${+(x * 100).toPrecision(3)} %` : String(+x.toPrecision(3));
}

function allowance(reading: TheoryCheckReading): string {
  return `${shown(reading.predicted)} ± ${size(reading, reading.tolerance)}`;
}

const SAYS = {
  agrees: () => 'agrees',
  disagrees: () => 'outside the expected error',
  outside: (reason: string) => `outside the formula’s validity: ${reason}`,
  undefined: (reason: string) => `no verdict: ${reason}`,
};

/** One line for a reading: label, measured and predicted values, the difference against what is allowed, the verdict. */
export function describeReading(reading: TheoryCheckReading): string {
  const numbers = `measured ${shown(reading.measured)}, predicted ${shown(reading.predicted)}; difference ${size(reading, reading.error)}, allowed ${size(reading, reading.tolerance)}`;
  return `${reading.label}: ${numbers}: ${SAYS[reading.verdict](reading.reason)}`;
}

export function verdictOf(result: CheckResult, timeoutMs: number): Verdict {
  if (result.state === 'missing') return { outcome: 'errored', message: `The preview has no cell ${result.id}.` };
  // A check with no verdict in time is a failed test: a run of every test must end, and say which did not.
  if (result.state === 'timeout') return { outcome: 'failed', message: `The check had no verdict after ${Math.round(timeoutMs / 1000)} s, its time limit: its cell had not finished.` };
  if (result.state === 'rejected') return { outcome: 'errored', message: result.error ?? 'The cell failed.' };
  if (result.checks.length === 0) return { outcome: 'errored', message: 'The cell ran, but its value holds no theory check.' };
  const message = result.checks.map(describeReading).join('\n');
  const failed = result.checks.find((reading) => reading.verdict === 'disagrees');
  if (failed) return { outcome: 'failed', message, expected: allowance(failed), actual: shown(failed.measured) };
  if (result.checks.some((reading) => reading.verdict === 'undefined')) return { outcome: 'errored', message };
  if (result.checks.some((reading) => reading.verdict === 'outside')) return { outcome: 'skipped', message };
  return { outcome: 'passed', message };
}
