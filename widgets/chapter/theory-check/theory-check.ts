/**
 * A live readout that sets a measured value beside the formula's, with the
 * errors the chapter allows and why, and its verdict: agrees (✓), outside the
 * expected error (✗), outside the formula's validity, or no verdict because a
 * value is missing (see check-verdict.ts for the rules). Its root carries the
 * numbers as data attributes, so that the end-to-end tests assert the same
 * verdict the reader sees:
 *
 * - data-verdict: agrees | disagrees | outside | undefined
 * - data-agrees: 'true' exactly when the verdict is agrees
 * - data-measured, data-predicted, data-error (the difference as compared):
 *   absent when not a number
 * - data-tolerance (= data-allowed): the sum of the errors allowed
 * - data-error-formula, data-error-integration, data-error-measurement: each term
 * - data-validity: holds | fails; data-reason: the failed condition or what is missing
 */
import { judge, type Condition, type ErrorSource, type ErrorTerm, type Judgement } from './check-verdict.ts';

export interface TheoryCheckOptions {
  /** what is compared, e.g. "Period of the orbit" */
  label: string;
  measured: number;
  predicted: number;
  /**
   * The errors allowed, each computed from the current parameters, with a
   * one-line reason: `{formula: {value, why}, integration: {…}, measurement: {…}}`.
   * Absolute, or fractions of |predicted| when `relative`.
   */
  errors?: Partial<Record<ErrorSource, ErrorTerm | number | null>>;
  /** an allowance without an error model (older cells); not with `errors` */
  tolerance?: number;
  relative?: boolean;
  /** the formula's regime, e.g. {holds: tau <= limit, condition: `the ramp is short: …`} */
  validity?: Condition | readonly Condition[];
  /** why measured or predicted is not a number, when it is not */
  missing?: string;
  /** e.g. "time units" */
  unit?: string;
  /** how the measured value was obtained, e.g. "from the spectral peak" */
  method?: string;
  /** the formula, as plain text or a short LaTeX-free expression */
  formula?: string;
  /** significant digits shown */
  digits?: number;
}

/** A number in a theory check's verdict: never "NaN" or "Infinity" (the verdict says why a value is missing). */
export function verdictNumber(x: number, digits: number): string {
  if (!Number.isFinite(x)) return '—';
  if (x === 0) return '0';
  if (x !== 0 && (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e6)) return x.toExponential(Math.max(0, digits - 1));
  return x.toPrecision(Math.max(1, digits));
}

const MARKS = { agrees: '✓', disagrees: '✗', outside: '○', undefined: '–' } as const;

function verdictText(j: Judgement): string {
  switch (j.verdict) {
    case 'agrees':
      return 'agrees: the difference is inside the errors allowed';
    case 'disagrees':
      return 'outside the expected error: the difference is larger than the errors allowed';
    case 'outside':
      return `outside the formula’s validity: ${j.reason}`;
    default:
      return `no verdict: ${j.reason}`;
  }
}

function setNumber(root: HTMLElement, name: string, value: number): void {
  if (Number.isFinite(value)) root.dataset[name] = String(value);
  else delete root.dataset[name];
}

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text = ''): HTMLElementTagNameMap[K] {
  const node = document.createElement(tag);
  if (className) node.className = className;
  node.textContent = text;
  return node;
}

export function theoryCheck(options: TheoryCheckOptions): HTMLElement {
  const { label, measured, predicted, relative = false, unit = '', method, formula, digits = 6 } = options;
  for (const [name, value] of Object.entries({ measured, predicted })) {
    if (typeof value !== 'number') throw new TypeError(`theoryCheck: ${name} must be a number, not ${String(value)}`);
  }
  const judgement = judge(options);
  const { verdict, error, allowed, terms } = judgement;

  const root = document.createElement('figure');
  root.className = `pb-theory-check pb-verdict-${verdict}`;
  root.classList.toggle('pb-disagrees', verdict === 'disagrees');
  root.dataset.widget = 'theory-check';
  setNumber(root, 'measured', measured);
  setNumber(root, 'predicted', predicted);
  setNumber(root, 'error', error);
  setNumber(root, 'tolerance', allowed);
  setNumber(root, 'allowed', allowed);
  for (const term of terms) if (term.source !== 'allowance') setNumber(root, `error${term.source[0].toUpperCase()}${term.source.slice(1)}`, term.value);
  Object.assign(root.dataset, {
    relative: String(relative),
    verdict,
    agrees: String(verdict === 'agrees'),
    validity: verdict === 'outside' ? 'fails' : 'holds',
  });
  if (judgement.reason) root.dataset.reason = judgement.reason;

  const u = unit ? ` ${unit}` : '';
  // Two digits for errors: they are estimates, and more would claim a precision they do not have.
  const size = (x: number) => (relative ? `${verdictNumber(x * 100, 2)} %` : `${verdictNumber(x, 2)}${u}`);

  const caption = element('figcaption', '');
  const mark = element('span', 'pb-check-mark', MARKS[verdict]);
  mark.setAttribute('aria-hidden', 'true');
  caption.append(mark, ' ', element('strong', '', label));

  const list = element('dl', '');
  const row = (name: string, className: string, text: string) => list.append(element('dt', '', name), element('dd', className, text));
  const value = (x: number, about?: string) => `${verdictNumber(x, digits)}${Number.isFinite(x) ? u : ''}${about ? ` (${about})` : ''}`;
  row('Simulation', 'pb-measured', value(measured, method));
  row('Theory', 'pb-predicted', value(predicted, formula));
  root.append(caption, list);

  // The comparison and its errors mean something only when the check is judged.
  const judged = verdict === 'agrees' || verdict === 'disagrees';
  if (judged) {
    row('Difference', 'pb-error', size(error));
    row('Allowed', 'pb-allowed', `≤ ${size(allowed)}${terms.length > 1 ? ', the sum of' : ''}`);
    const sources = element('ul', 'pb-error-terms');
    for (const term of terms) {
      const item = element('li', '');
      item.dataset.source = term.source;
      item.append(element('span', 'pb-term-name', term.source), ' ', element('span', 'pb-term-value', size(term.value)));
      if (term.why) item.append(element('span', 'pb-term-why', ` — ${term.why}`));
      sources.append(item);
    }
    root.append(sources);
  }
  root.append(element('p', 'pb-verdict', verdictText(judgement)));
  // Announced when it changes; a <figure> may not take the status role, so it is a live region instead.
  root.setAttribute('aria-live', 'polite');
  root.dataset.ready = '';
  return root;
}
