/**
 * methodComparison({hamiltonian, params, initial, dt, tEnd, methods, order}):
 * the same model under several integrators side by side — the energy error
 * over a long run on a log axis, the phase portraits, the measured cost,
 * and an order study (global error at a fixed T against the step, on
 * log–log axes, with least-squares slopes). Everything is computed in a
 * worker (method-comparison-worker.ts), with a progress bar meanwhile; the
 * figures are the book's chart() and table(). The element's `results` is a
 * Promise of the checks (method-comparison-result.ts) for the chapter's
 * theory checks.
 *
 * Each method's model is compiled here, or taken from what the build
 * compiled (build.store), and sent to the worker as data. A method that
 * cannot run on this H (a splitting on an H that does not separate) is
 * reported in its place; the rest run.
 */
import { type BuildOptions, type CompiledModel, compiledModelFor, InputError, MAX_CELL_STEPS, methodChoice, type MethodChoice, type MethodName } from '../../../core/index.ts';
import { chart } from '../chart/chart.ts';
import type { ChartSeriesOptions } from '../chart/chart-options.ts';
import { ComparisonChecks, failed, type ComparisonResult, type MethodOutcome } from './method-comparison-result.ts';
import type { ComparisonRequest } from './method-comparison-worker.ts';
import { table } from '../table/table.ts';

export interface MethodComparisonOptions {
  /** H as a math expression (or JS function source) */
  hamiltonian: string;
  /** degrees of freedom (default 1) */
  dof?: number;
  params?: Record<string, number>;
  coordinates?: readonly string[];
  momenta?: readonly string[];
  /** [q…, p…] */
  initial: readonly number[];
  /** the step of the long run */
  dt: number;
  /** the long run's end time */
  tEnd: number;
  /** the methods compared (default rk38, verlet, yoshida4, midpoint) */
  methods?: readonly MethodName[];
  /** tolerances of the adaptive method, when it is among them */
  rtol?: number;
  atol?: number;
  /** the order study: errors at time T for each step, against `exact` (the true state at T) or, without it, a reference run of another method */
  order?: { T: number; steps: readonly number[]; exact?: readonly number[] };
}

export type MethodComparisonElement = HTMLElement & { results: Promise<ComparisonChecks> };

const NAMES: Record<MethodName, string> = {
  rk38: 'RK 3/8',
  verlet: 'Störmer–Verlet',
  yoshida4: 'Yoshida 4',
  midpoint: 'implicit midpoint',
  adaptive: 'Dormand–Prince',
};
const COLORS = { rk38: 'blue', verlet: 'orange', yoshida4: 'teal', midpoint: 'raspberry', adaptive: 'violet' } as const;

/** Steps × methods one comparison may take: the midpoint rule's Newton steps count 10×. */
const MAX_WORK = 2 * MAX_CELL_STEPS;

function check(options: MethodComparisonOptions): { methods: MethodChoice[]; steps: number } {
  if (typeof options !== 'object' || options === null) throw new InputError('methodComparison needs {hamiltonian, initial, dt, tEnd}');
  const { dt, tEnd, initial } = options;
  if (typeof options.hamiltonian !== 'string') throw new InputError('hamiltonian must be H as a string, e.g. "p^2/2 - cos(q)"');
  if (!Array.isArray(initial) || !initial.every((v) => typeof v === 'number' && Number.isFinite(v))) throw new InputError('initial must be a list of finite numbers [q…, p…]');
  if (!(typeof dt === 'number' && dt > 0 && Number.isFinite(dt))) throw new InputError(`dt must be a positive number, not ${String(dt)}`);
  if (!(typeof tEnd === 'number' && tEnd > dt && Number.isFinite(tEnd))) throw new InputError(`tEnd must be a number larger than dt, not ${String(tEnd)}`);
  const methods = (options.methods ?? ['rk38', 'verlet', 'yoshida4', 'midpoint']).map((name) =>
    name === 'adaptive' ? methodChoice(name, options.rtol, options.atol) : methodChoice(name),
  );
  if (methods.length === 0) throw new InputError('methods must name at least one method');
  const steps = Math.round(tEnd / dt);
  const order = options.order;
  if (order !== undefined) {
    if (!(order.T > 0) || !Array.isArray(order.steps) || order.steps.length < 3 || !order.steps.every((h) => h > 0 && h <= order.T)) {
      throw new InputError('order must be {T, steps: [three or more steps, each at most T], exact?}');
    }
    if (order.exact !== undefined && order.exact.length !== initial.length) throw new InputError(`order.exact must be a state like initial, ${initial.length} numbers`);
  }
  const orderSteps = order ? order.steps.reduce((n, h) => n + order.T / h, 0) : 0;
  const work = methods.reduce((n, m) => n + (m.name === 'midpoint' || m.name === 'adaptive' ? 10 : 1) * (2 * steps + orderSteps), 0);
  if (work > MAX_WORK) {
    throw new InputError(`this comparison asks for about ${work.toExponential(1)} steps of work, more than the ${MAX_WORK.toExponential(0)} the book lets one widget compute: take a larger dt or a shorter tEnd`);
  }
  return { methods, steps };
}

const rounded = (x: number, digits = 3) => (Number.isFinite(x) ? Number(x.toPrecision(digits)) : NaN);

/** The figures and tables of a finished comparison. */
function figures(result: ComparisonResult, checks: ComparisonChecks, options: MethodComparisonOptions): HTMLElement[] {
  const runs = result.runs.filter((r): r is Exclude<MethodOutcome, { error: string }> => !failed(r));
  const out: HTMLElement[] = [];
  out.push(
    chart({
      label: 'Relative energy error against time',
      x: { label: 'time t' },
      // The largest in each of 400 stretches of the run: an oscillating error keeps its peaks at any width.
      y: { label: '|ΔH/H₀|, largest per 1/400 of the run', scale: 'log' },
      // An energy error of exactly 0 (a conserved H kept to the last bit) has no place on a log axis.
      series: runs
        .filter((r) => r.drift.binned.e.some((e) => e > 0))
        .map((r) => ({
          label: NAMES[r.method],
          color: COLORS[r.method],
          x: r.drift.binned.t.filter((_, i) => r.drift.binned.e[i] > 0),
          y: r.drift.binned.e.filter((e) => e > 0),
          mark: 'line' as const,
          width: 1.5,
        })),
    }),
  );
  out.push(
    chart({
      label: 'Phase portraits of the long run',
      x: { label: 'q' },
      y: { label: 'p' },
      height: 320,
      series: runs.map((r) => ({ label: NAMES[r.method], color: COLORS[r.method], x: r.portrait.q, y: r.portrait.p, mark: 'dots' as const, radius: 1 })),
    }),
  );
  out.push(
    table({
      caption: `Cost over ${result.steps} steps of dt = ${result.dt}, measured in this browser`,
      columns: ['method', { label: 'steps per second', digits: 3 }, { label: 'field evaluations per step', digits: 3 }, { label: 'evaluations per second', digits: 3 }, { label: 'largest |ΔH/H₀|', digits: 2 }],
      rows: result.runs.map((r) =>
        failed(r) ? [NAMES[r.method], NaN, NaN, NaN, NaN] : [NAMES[r.method], rounded(r.stepsPerSecond), rounded(r.evaluationsPerStep), rounded(r.evaluationsPerSecond), Math.max(r.drift.first, r.drift.second)],
      ),
    }),
  );
  const order = result.order;
  if (order) {
    const series: ChartSeriesOptions[] = [];
    const rows: unknown[][] = [];
    for (const study of order.studies) {
      const points = order.steps.map((h, i) => [h, study.errors[i]] as [number, number]).filter(([, e]) => e > 0 && Number.isFinite(e));
      if (points.length === 0) continue;
      const fit = checks.order(study.method);
      series.push({ label: NAMES[study.method], color: COLORS[study.method], points, mark: 'dots', radius: 4 });
      // The fitted power law through the points' centre, dashed.
      const logs = points.map(([h, e]) => [Math.log(h), Math.log(e)]);
      const mx = logs.reduce((s, [a]) => s + a, 0) / logs.length;
      const my = logs.reduce((s, [, b]) => s + b, 0) / logs.length;
      const slope = fit.measured;
      if (Number.isFinite(slope)) series.push({ color: COLORS[study.method], formula: (h) => Math.exp(my + slope * (Math.log(h) - mx)), dash: true, width: 1 });
      rows.push([NAMES[study.method], rounded(slope, 4), fit.predicted]);
    }
    if (series.length) {
      out.push(
        chart({
          label: `Global error at T = ${rounded(order.T, 6)} against the step`,
          x: { label: 'step h', scale: 'log' },
          y: { label: `error at T (against ${order.referenceName})`, scale: 'log' },
          series,
        }),
      );
    }
    out.push(table({ caption: 'Fitted slopes of log error against log h', columns: ['method', { label: 'fitted order', digits: 4 }, 'theory'], rows }));
  }
  return out;
}

export function methodComparison(options: MethodComparisonOptions, build: BuildOptions = {}): MethodComparisonElement {
  const { methods, steps } = check(options);
  const root = document.createElement('figure') as MethodComparisonElement;
  root.className = 'pb-method-comparison';
  root.dataset.widget = 'method-comparison';
  const status = document.createElement('figcaption');
  const progress = document.createElement('progress');
  progress.max = 1;
  progress.value = 0;
  const stage = document.createElement('span');
  stage.textContent = ' compiling the models…';
  status.append(progress, stage);
  status.setAttribute('aria-live', 'polite');
  root.append(status);

  const worker = new Worker(new URL('./method-comparison-worker.ts', import.meta.url), { type: 'module' });
  const spec = {
    dof: options.dof ?? 1,
    hamiltonian: options.hamiltonian,
    params: options.params ?? {},
    coordinates: options.coordinates,
    momenta: options.momenta,
  };
  const problems: MethodOutcome[] = [];

  root.results = new Promise<ComparisonChecks>((resolve, reject) => {
    const fail = (message: string) => {
      status.textContent = `Could not compare the methods: ${message}`;
      status.className = 'pb-error';
      worker.terminate();
      root.dataset.ready = '';
      reject(new Error(message));
    };
    worker.onerror = (event) => fail(event.message || 'the worker failed');
    worker.onmessage = (event: MessageEvent<{ progress?: number; stage?: string; result?: ComparisonResult; error?: string }>) => {
      const m = event.data;
      if (m.error) return fail(m.error);
      if (m.progress !== undefined) {
        progress.value = m.progress;
        stage.textContent = ` computing: ${m.stage === 'order study' ? 'the order study' : NAMES[m.stage as MethodName] ?? m.stage}…`;
      }
      if (m.result) {
        worker.terminate();
        // The methods refused before the run, in the order asked for.
        const result: ComparisonResult = { ...m.result, runs: methods.map((c) => m.result!.runs.find((r) => r.method === c.name) ?? problems.find((r) => r.method === c.name)!) };
        const checks = new ComparisonChecks(result);
        const notes = result.runs.filter(failed).map((r) => `${NAMES[r.method]}: ${r.error}`);
        status.textContent = `${methods.length} methods, ${steps} steps each${notes.length ? `. Not run — ${notes.join('; ')}` : ''}.`;
        root.dataset.steps = String(steps);
        try {
          root.append(...figures(result, checks, options));
        } catch (error) {
          return fail((error as Error).message);
        }
        root.dataset.ready = '';
        resolve(checks);
      }
    };
    const compiling = new Map<string, Promise<CompiledModel>>();
    const compile = (choice: MethodChoice): Promise<CompiledModel> => {
      // The adaptive method needs only the field, which RK 3/8's compiled code carries.
      const method = choice.name === 'adaptive' ? 'rk38' : choice.name;
      if (!compiling.has(method)) compiling.set(method, compiledModelFor({ ...spec, method: method === 'rk38' ? undefined : method }, build));
      return compiling.get(method)!;
    };
    Promise.all([compile({ name: 'rk38' }), ...methods.map((c) => compile(c).then((compiled) => ({ choice: c, compiled }), (error: Error) => ({ choice: c, error })))]).then(
      ([base, ...compiled]) => {
        const models: ComparisonRequest['models'] = [];
        for (const c of compiled) {
          if ('error' in c) problems.push({ method: c.choice.name, error: c.error.message });
          else models.push(c);
        }
        const request: ComparisonRequest = {
          models,
          base,
          params: spec.params,
          initial: [...options.initial],
          dt: options.dt,
          steps,
          order: options.order && { T: options.order.T, steps: [...options.order.steps], exact: options.order.exact && [...options.order.exact] },
        };
        stage.textContent = ' computing…';
        worker.postMessage(request);
      },
      (error: Error) => fail(error.message),
    );
  });
  // A cell that reads `results` shows the failure itself; unread, it must not surface as an unhandled rejection.
  root.results.catch(() => undefined);
  // Part of a cell's output: when the cell re-runs and this element is dropped, so is its worker.
  let seen = false;
  new MutationObserver((_, observer) => {
    seen ||= root.isConnected;
    if (seen && !root.isConnected) {
      worker.terminate();
      observer.disconnect();
    }
  }).observe(document.body, { childList: true, subtree: true });
  return root;
}
