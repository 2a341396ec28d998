/**
 * A live readout that sets a measured value beside the formula's, with the
 * error the chapter says to expect. Its root carries the numbers as data
 * attributes so the end-to-end tests assert the same agreement the reader sees.
 */
export interface TheoryCheckOptions {
  /** what is compared, e.g. "Period of the orbit" */
  label: string;
  measured: number;
  predicted: number;
  /** the agreement the chapter promises: |measured − predicted| ≤ tolerance (absolute), or relative when `relative` */
  tolerance: number;
  relative?: boolean;
  /** e.g. "time units" */
  unit?: string;
  /** how the measured value was obtained, e.g. "from the spectral peak" */
  method?: string;
  /** the formula, as plain text or a short LaTeX-free expression */
  formula?: string;
  /** significant digits shown */
  digits?: number;
}

export function agreement(o: Pick<TheoryCheckOptions, 'measured' | 'predicted' | 'tolerance' | 'relative'>) {
  const difference = Math.abs(o.measured - o.predicted);
  const error = o.relative ? difference / Math.abs(o.predicted) : difference;
  return { difference, error, agrees: Number.isFinite(error) && error <= o.tolerance };
}

const format = (x: number, digits: number) =>
  !Number.isFinite(x) ? String(x) : Math.abs(x) !== 0 && (Math.abs(x) < 1e-3 || Math.abs(x) >= 1e6) ? x.toExponential(digits - 1) : x.toPrecision(digits);

export function theoryCheck(options: TheoryCheckOptions): HTMLElement {
  const { label, measured, predicted, tolerance, relative = false, unit = '', method, formula, digits = 6 } = options;
  for (const [name, value] of Object.entries({ measured, predicted, tolerance })) {
    if (typeof value !== 'number') throw new Error(`theoryCheck: ${name} must be a number, not ${String(value)}`);
  }
  const { error, agrees } = agreement(options);
  const root = document.createElement('figure');
  root.className = 'pb-theory-check';
  root.dataset.widget = 'theory-check';
  Object.assign(root.dataset, {
    measured: String(measured),
    predicted: String(predicted),
    tolerance: String(tolerance),
    relative: String(relative),
    error: String(error),
    agrees: String(agrees),
  });
  const u = unit ? ` ${unit}` : '';
  const errorText = relative ? `${format(error * 100, 2)} %` : `${format(error, 2)}${u}`;
  const toleranceText = relative ? `${format(tolerance * 100, 2)} %` : `${format(tolerance, 2)}${u}`;
  root.innerHTML = `
    <figcaption><span class="pb-check-mark" aria-hidden="true">${agrees ? '✓' : '✗'}</span> <strong></strong></figcaption>
    <dl>
      <dt>Simulation</dt><dd class="pb-measured"></dd>
      <dt>Theory</dt><dd class="pb-predicted"></dd>
      <dt>Difference</dt><dd class="pb-error"></dd>
    </dl>`;
  root.querySelector('strong')!.textContent = label;
  root.querySelector('.pb-measured')!.textContent = `${format(measured, digits)}${u}${method ? ` (${method})` : ''}`;
  root.querySelector('.pb-predicted')!.textContent = `${format(predicted, digits)}${u}${formula ? ` (${formula})` : ''}`;
  root.querySelector('.pb-error')!.textContent = `${errorText}, expected ≤ ${toleranceText} — ${agrees ? 'agrees' : 'outside the expected error'}`;
  root.classList.toggle('pb-disagrees', !agrees);
  root.setAttribute('role', 'status');
  root.dataset.ready = '';
  return root;
}
