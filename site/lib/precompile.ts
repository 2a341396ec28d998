/**
 * The build's share of a chapter's work: run its cells once, as written,
 * headless (cells/headless.ts), and do ahead what the page would
 * otherwise do with its heaviest modules:
 *
 * - compile every model the cells define — through canonicalEquations, a
 *   simulator's `hamiltonian` option or a stability chart — into
 *   compiled-model data, so the page needs no mathjs (or acorn) until the
 *   reader changes H;
 * - typeset every formula they show — `equations(model)` and `tex(…)` —
 *   with KaTeX, so the page needs no KaTeX's JavaScript, and put the HTML
 *   of a cell whose value is a formula into the cell's output, so it is
 *   there at the first paint (and without JavaScript);
 * - reserve the box of every simulator a cell shows (simulator/reserve.ts),
 *   so that the widget appears without moving the text around it.
 *
 * Only the catalogue entries that lead to such work do anything here; the
 * others (widgets, simulations, analyses) fail with a note, and the cells
 * that need them simply have no value at build time. Nothing here decides
 * what the page shows: a stale or missing result makes the page do the work
 * itself, as it does for a reader's edit.
 */
import * as acorn from 'acorn';
import katex from 'katex';
import { nonHamiltonianRules, provideTermRules, compiledModelFor, canonicalEquations, type HamiltonianSpec, compileModel, methodChoice, pendulumAction, pendulumFrequency, pendulumPeriod, type CompiledModel, provideMathjs, provideAcorn, type Model } from '../../core/index.ts';
// The one module named past the core's front door: mathjs itself, handed over statically (see core/index.ts).
import { math } from '../../core/expression/mathjs-instance.ts';
import { memoryStore, PAGE_DATA_FORMAT, type PageData, equationsHtml, equationsLatex, katexOptions, texHtml, typesetKey, createLibrary, modelSpec, type ModelOptions, reserveHtml, simulatorPlan, type ReserveOptions } from '../../widgets/index.ts';
import { standardValues, runHeadless, type HeadlessCell } from '../../cells/index.ts';

const PRERENDERED = Symbol('phasebook.prerendered');

/** A cell value the build can show before any script runs, with the typeset formulas it holds. */
interface Prerendered {
  readonly [PRERENDERED]: { html: string; keys: string[] };
}

/** The text column's width for the `width` builtin; the page reports the real one. */
const BUILD_WIDTH = 640;

export interface ChapterWork {
  /** The page's data (chapter/models/page-data.ts), or null when the cells need nothing compiled or typeset. */
  readonly data: PageData | null;
  /** HTML for the outputs of cells whose value is a formula, by cell id. */
  readonly outputs: ReadonlyMap<string, string>;
  /** How each cell ended at build time, by cell id: for the build's report to authors (cell-failures.ts). */
  readonly outcomes: ReadonlyMap<string, BuildOutcome>;
}

/** How a cell ended when the build ran it. */
export type BuildOutcome =
  /** It gave a value. */
  | { readonly kind: 'ran' }
  /** Its own code failed: the page will fail the same way. */
  | { readonly kind: 'failed'; readonly message: string }
  /** An input failed; that cell's outcome says why. */
  | { readonly kind: 'input failed' }
  /** It needs the page (a widget, the DOM), directly or through an input, so the build did not run it. */
  | { readonly kind: 'page only' };

/** The error at the end of a chain of `cause`s: what first went wrong. */
function rootOf(error: Error): Error {
  let root = error;
  while (root.cause instanceof Error) root = root.cause;
  return root;
}

function outcomeOf(error: Error): BuildOutcome {
  const root = rootOf(error);
  if (root instanceof NotAtBuildTime) return { kind: 'page only' };
  if (root !== error) return { kind: 'input failed' };
  return { kind: 'failed', message: `${error.name}: ${error.message}` };
}

// Astro runs this from its config, whose module loader is closed by the time
// the cells run: everything the compiler would import on demand is imported here.
provideMathjs(math);
provideAcorn(acorn);
provideTermRules(nonHamiltonianRules);

class NotAtBuildTime extends Error {
  override name = 'NotAtBuildTime';
}

function prerendered(html: string, keys: string[]): Prerendered {
  return { [PRERENDERED]: { html, keys } };
}

function isPrerendered(value: unknown): value is Prerendered {
  return typeof value === 'object' && value !== null && PRERENDERED in value;
}

/** Does the chapter's work ahead: see the module comment. */
export async function precompileChapter(cells: readonly HeadlessCell[]): Promise<ChapterWork> {
  const models: CompiledModel[] = [];
  const store = memoryStore([]);
  const recording = {
    get: (key: string) => store.get(key),
    put(model: CompiledModel) {
      models.push(model);
      store.put?.(model);
    },
  };
  const build = { store: recording, compile: compileModel };
  const typeset = new Map<string, string>();
  const typesetOnce = (source: string, display: boolean): string => {
    const key = typesetKey(source, display);
    let html = typeset.get(key);
    if (html === undefined) typeset.set(key, (html = katex.renderToString(source, katexOptions(display))));
    return html;
  };
  const compile = async (spec: HamiltonianSpec) => {
    if (spec.hamiltonian !== undefined && !spec.vectorField && !spec.gradient) {
      await compiledModelFor({ ...spec, hamiltonian: spec.hamiltonian }, build);
    }
  };

  const catalogue: Record<string, unknown> = {};
  for (const name of Object.keys(createLibrary({ models: store, typeset: new Map() }))) {
    // A plain function, so that `new Simulation(…)` fails with this message too.
    catalogue[name] = function notHere() {
      throw new NotAtBuildTime(`${name} runs in the page, not at build time`);
    };
  }
  Object.assign(catalogue, {
    canonicalEquations: async (spec: HamiltonianSpec) => {
      // Another method's stepper is applied by a module loaded on demand, which the closed loader cannot load:
      // its code is compiled here, and the page builds the model from it.
      if (spec.method && spec.method.name !== 'rk38') {
        await compile(spec);
        throw new NotAtBuildTime(`a model run by ${spec.method.name} is built in the page`);
      }
      return canonicalEquations(spec, build);
    },
    // The simulator runs in the page; here it leaves the box it will fill (simulator/reserve.ts).
    simulator: async (options: ModelOptions & ReserveOptions & { model?: Model }) => {
      const model = options.model ?? (await canonicalEquations(modelSpec(options), build));
      return prerendered(reserveHtml(simulatorPlan(options, model)), []);
    },
    // Pure arithmetic, wanted by the cells that define a comparison's order study, and by the action–angle
    // chapter's closed forms, which its simulator's spectrum marks: so that simulator's box is reserved too.
    pendulumPeriod,
    pendulumAction,
    pendulumFrequency,
    // The comparison runs in the page; here each method's model is compiled, so the page needs no mathjs.
    methodComparison: async (options: { hamiltonian: string; dof?: number; params?: Record<string, number>; methods?: string[]; coordinates?: string[]; momenta?: string[] }) => {
      const methods = new Set((options.methods ?? ['rk38', 'verlet', 'yoshida4', 'midpoint']).map((m) => (m === 'adaptive' ? 'rk38' : m)).concat('rk38'));
      for (const name of methods) {
        const spec = { dof: options.dof ?? 1, hamiltonian: options.hamiltonian, params: options.params, coordinates: options.coordinates, momenta: options.momenta };
        // A method that cannot run on this H (a splitting on an H that does not separate) is the page's to report.
        await compile({ ...spec, method: name === 'rk38' ? undefined : methodChoice(name) }).catch(() => undefined);
      }
      throw new NotAtBuildTime('methodComparison runs in the page');
    },
    stabilityChart: async (options: { hamiltonian: string; params: Record<string, number> }) => {
      await compile({ dof: 1, hamiltonian: options.hamiltonian, params: options.params });
      throw new NotAtBuildTime('stabilityChart runs in the page');
    },
    equations: async (model: Model | Promise<Model>) => {
      const m = await model;
      if (!m.latex) throw new NotAtBuildTime('nothing to typeset');
      const source = equationsLatex(m.latex);
      return prerendered(equationsHtml(source, typesetOnce(source, true), m.accuracy), [typesetKey(source, true)]);
    },
    tex: (source: string, options: { display?: boolean } = {}) => {
      const display = options.display !== false;
      const text = String(source);
      return prerendered(texHtml(typesetOnce(text, display), display, text), [typesetKey(text, display)]);
    },
  });
  const builtins = {
    ...standardValues(),
    ...catalogue,
    html: () => {
      throw new NotAtBuildTime('html builds DOM in the page');
    },
    width: BUILD_WIDTH,
    now: 0,
  };

  const results = await runHeadless(cells, builtins, { timeoutMs: 20_000 });
  const outputs = new Map<string, string>();
  const outcomes = new Map<string, BuildOutcome>();
  for (const [id, result] of results) {
    outcomes.set(id, 'error' in result ? outcomeOf(result.error) : { kind: 'ran' });
    if ('value' in result && isPrerendered(result.value)) {
      const { html, keys } = result.value[PRERENDERED];
      outputs.set(id, html);
      // The page finds these formulas in the cell's output; the table need not carry them twice.
      for (const key of keys) typeset.delete(key);
    }
  }
  const data: PageData | null =
    models.length || typeset.size ? { format: PAGE_DATA_FORMAT, models, typeset: Object.fromEntries(typeset) } : null;
  return { data, outputs, outcomes };
}
