/**
 * The book's named widgets and helpers, available to every code cell by bare
 * name (e.g. `simulator(...)` in a cell). Add entries here: each value is
 * handed to cells as is — a function stays a function the cell calls.
 *
 * widgets/cells/boot.ts passes this catalogue to the cell machinery, over the
 * standard builtins, so an entry here wins over a standard builtin of the
 * same name. A cell that defines the same name wins over both.
 *
 * Every entry is lazy: its module loads when a cell first names it, so a page
 * ships only the widgets its cells use, and none before its cells run. The
 * page's context (book/page-data.ts) carries what the build compiled and
 * typeset, so that the entries which build models or typeset math use it
 * instead of loading mathjs or KaTeX.
 */
import type { PageContext } from './book/page-data.ts';
import { lazy } from './cells/lazy-builtin.ts';
import { currentCellSignal } from './cells/runtime.ts';
import type { BuildOptions } from './core/canonical-equations.ts';
import { VIEW_MODULES } from './simulator/view-modules.ts';

/**
 * Starts fetching the modules a cell's widget will need, from what the
 * build left in its output: the simulator's module and its views' together,
 * rather than the views only once the simulator's module has run. Over a
 * slow network that is one round trip less before the widget is drawn.
 */
export function prefetchWidgets(cell: Element): void {
  const reserved = cell.querySelector<HTMLElement>('[data-reserve="simulator"]');
  if (!reserved) return;
  const views = (reserved.dataset.reserveViews ?? '').split(' ').filter((v): v is keyof typeof VIEW_MODULES => v in VIEW_MODULES);
  // Failures are the simulator's to report when it runs; here they would only be noise.
  for (const load of [() => import('./simulator/simulator.ts'), ...views.map((v) => VIEW_MODULES[v])]) load().catch(() => undefined);
}

export function createLibrary(page: PageContext): Record<string, unknown> {
  // The core's modules one by one, not its index: a page then loads only the parts its cells use.
  const spectrum = () => import('./core/spectrum.ts');
  const invariants = () => import('./core/invariants.ts');
  const analysis = () => import('./book/analysis.ts');
  const typesetting = () => import('./book/tex.ts').then((m) => m.typesetting(page.typeset));
  // New models compile in a worker (book/compile-worker.ts), reporting progress; an edit that supersedes the cell cancels its build.
  const build = (): BuildOptions => ({
    store: page.models,
    signal: currentCellSignal(),
    progress: (done, total) => document.dispatchEvent(new CustomEvent('phasebook:compiling', { detail: { fraction: done / total } })),
    compile: (spec, control) => import('./book/compile-client.ts').then((m) => m.compileInWorker(spec, control)),
  });

  return {
    // Widgets
    /** simulator({hamiltonian, initial, …}) → Promise of the widget's element */
    simulator: lazy(() => import('./simulator/simulator.ts').then((m) => (options: Parameters<typeof m.simulator>[0]) => m.simulator(options, build()))),
    /** Views (each has an `.element`), for composing a simulator by hand */
    timePlot: lazy(() => import('./plots/time-plot.ts').then((m) => m.timePlot)),
    trajectoryView: lazy(() => import('./plots/trajectory-view.ts').then((m) => m.trajectoryView)),
    phasePortrait: lazy(() => import('./plots/phase-portrait.ts').then((m) => m.phasePortrait)),
    spectrumView: lazy(() => import('./plots/spectrum-view.ts').then((m) => m.spectrumView)),
    /** theoryCheck({label, measured, predicted, errors: {formula, integration, measurement}, validity, missing, relative, unit, method, formula}) → element */
    theoryCheck: lazy(() => import('./book/theory-check.ts').then((m) => m.theoryCheck)),
    /** equations(model) → H and Hamilton's equations, typeset */
    equations: lazy(() => typesetting().then((t) => t.equations)),
    /** tex(source, {display}) → typeset LaTeX */
    tex: lazy(() => typesetting().then((t) => t.tex)),
    /** chart({label, x, y, series, rules}) → a figure: points, lines, formula curves and bands on linear or log axes, with legend, data table, PNG and CSV */
    chart: lazy(() => import('./book/chart.ts').then((m) => m.chart)),
    /** table({columns, rows, caption}) → a table of numbers that scrolls on a phone; rows may be a function, read again every `refresh` seconds */
    table: lazy(() => import('./book/table.ts').then((m) => m.table)),
    /** stabilityChart({hamiltonian, params, x, y, frequencyParam, boundaries, onSelect}) → Floquet chart computed in a worker */
    stabilityChart: lazy(() => import('./book/stability-chart.ts').then((m) => (options: Parameters<typeof m.stabilityChart>[0]) => m.stabilityChart(options, build()))),
    /** poincareSection({energies, energy, plane, orbits, crossings, onLaunch}) → Hénon–Heiles surface of section computed in a worker; click to launch an orbit */
    poincareSection: lazy(() => import('./book/poincare-section.ts').then((m) => m.poincareSection)),
    /** chaoticShare({energy, plane, grid, time}) → Promise of the section's chaotic share and its errors, computed in a worker */
    chaoticShare: lazy(() => import('./book/poincare-section.ts').then((m) => m.chaoticShare)),
    /** henonHeilesFig6: the chaotic share read off Hénon & Heiles (1964) Fig. 6 at E = 1/12, 1/8, 1/6, with its reading error */
    henonHeilesFig6: lazy(() => import('./core/analysis/poincare-area.ts').then((m) => m.HENON_HEILES_FIG6)),

    // The simulation core
    /** canonicalEquations({dof, hamiltonian, params}) → Promise of a Model */
    canonicalEquations: lazy(() =>
      import('./core/canonical-equations.ts').then((m) => (spec: Parameters<typeof m.canonicalEquations>[0]) => m.canonicalEquations(spec, build())),
    ),
    /** new Simulation(model, {initial, dt, every, derived}): integrate off-screen, e.g. for a theory check */
    Simulation: lazy(() => import('./book/cell-simulation.ts').then((m) => m.CellSimulation)),
    spectrum: lazy(() => spectrum().then((m) => m.spectrum)),
    findPeaks: lazy(() => spectrum().then((m) => m.findPeaks)),
    relativeDrift: lazy(() => invariants().then((m) => m.relativeDrift)),
    evaluateAlong: lazy(() => invariants().then((m) => m.evaluateAlong)),

    // Analysis for the chapters' theory checks
    crossings: lazy(() => analysis().then((m) => m.crossings)),
    meanPeriod: lazy(() => analysis().then((m) => m.meanPeriod)),
    floquet: lazy(() => analysis().then((m) => m.floquet)),
    /** peakError(spectrum, lines, line) → how far leakage and refinement can move a spectral peak */
    peakError: lazy(() => analysis().then((m) => m.peakError)),
    keplerOrbit: lazy(() => analysis().then((m) => m.keplerOrbit)),
    rutherfordAngle: lazy(() => analysis().then((m) => m.rutherfordAngle)),
    deflectionFrom: lazy(() => analysis().then((m) => m.deflectionFrom)),
    outgoingDirection: lazy(() => analysis().then((m) => m.outgoingDirection)),
    angleBetween: lazy(() => analysis().then((m) => m.angleBetween)),
  };
}
