/**
 * The book's named widgets and helpers, available to every code cell by bare
 * name (e.g. `simulator(...)` in a cell). Add entries here: each entry is a
 * loader, and the value it resolves to is handed to cells as is — a function
 * stays a function the cell calls.
 *
 * cells/boot.ts passes this catalogue to the cell machinery, over the
 * standard builtins, so an entry here wins over a standard builtin of the
 * same name. A cell that defines the same name wins over both.
 *
 * Every entry is a loader because the cell machinery calls it only when a
 * cell first names it: a page ships only the widgets its cells use, and none
 * before its cells run. The
 * page's context (chapter/models/page-data.ts) carries what the build compiled and
 * typeset, so that the entries which build models or typeset math use it
 * instead of loading mathjs or KaTeX.
 */
import type { BuildOptions } from '../core/index.ts';
import type { PageContext } from './chapter/models/page-data.ts';
import { VIEW_MODULES } from './simulator/view-modules.ts';

/**
 * The catalogue's names that draw a widget: a cell that calls one shows a
 * figure a reader can look at on its own, which is what the book offers to
 * embed (site/pages/embed/). `equations` and `tex` typeset, and the core's
 * names compute: neither is a widget.
 */
export const WIDGET_NAMES: readonly string[] = [
  'simulator',
  'timePlot',
  'trajectoryView',
  'phasePortrait',
  'spectrumView',
  'theoryCheck',
  'chart',
  'table',
  'stabilityChart',
  'poincareSection',
  'methodComparison',
  'standardMap',
  'ensemble',
];

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

/** The exercises' widget (chapter/exercise/exercise.ts), loaded when an exercise first comes near the view. */
export const loadExerciseWidget = () => import('./chapter/exercise/exercise.ts');

/**
 * The catalogue: each name's loader, called once, when a cell first names it
 * (cells/builtins.ts takes it as its `Loaders`). Its return type is left to
 * inference so that every entry keeps the type of what it loads, which the
 * VS Code extension reads for completions (vscode/build/catalogue.ts).
 *
 * `cellSignal` is the cell machinery's signal for the cell whose code is
 * running, which aborts when that cell is defined again (cells/runtime.ts):
 * a model build started by a cell stops when an edit makes it obsolete.
 */
export function createLibrary(page: PageContext, cellSignal: () => AbortSignal | undefined = () => undefined) {
  // The core's modules one by one, not its index: a page then loads only the parts its cells use.
  const spectrum = () => import('../core/spectrum/spectrum.ts');
  const invariants = () => import('../core/invariants.ts');
  const analysis = () => import('./chapter/analysis/analysis.ts');
  const threeBody = () => import('../core/analysis/three-body.ts');
  const standardMapAnalysis = () => import('../core/analysis/standard-map.ts');
  const liouville = () => import('./chapter/ensemble/liouville-library.ts');
  const typesetting = () => import('./chapter/math/tex.ts').then((m) => m.typesetting(page.typeset));
  // New models compile in a worker (chapter/models/compile-worker.ts), reporting progress; an edit that supersedes the cell cancels its build.
  const build = (): BuildOptions => ({
    store: page.models,
    signal: cellSignal(),
    progress: (done, total) => document.dispatchEvent(new CustomEvent('phasebook:compiling', { detail: { fraction: done / total } })),
    compile: (spec, control) => import('./chapter/models/compile-client.ts').then((m) => m.compileInWorker(spec, control)),
  });

  return {
    // Widgets
    /** simulator({hamiltonian, initial, …}) → Promise of the widget's element */
    simulator: () => import('./simulator/simulator.ts').then((m) => (options: Parameters<typeof m.simulator>[0]) => m.simulator(options, build())),
    /** Views (each has an `.element`), for composing a simulator by hand */
    timePlot: () => import('./plots/time/time-plot.ts').then((m) => m.timePlot),
    trajectoryView: () => import('./plots/plane/trajectory-view.ts').then((m) => m.trajectoryView),
    phasePortrait: () => import('./plots/plane/phase-portrait.ts').then((m) => m.phasePortrait),
    spectrumView: () => import('./plots/spectrum/spectrum-view.ts').then((m) => m.spectrumView),
    /** theoryCheck({label, measured, predicted, errors: {formula, integration, measurement}, validity, missing, relative, unit, method, formula}) → element */
    theoryCheck: () => import('./chapter/theory-check/theory-check.ts').then((m) => m.theoryCheck),
    /** equations(model) → H and Hamilton's equations, typeset */
    equations: () => typesetting().then((t) => t.equations),
    /** tex(source, {display}) → typeset LaTeX */
    tex: () => typesetting().then((t) => t.tex),
    /** chart({label, x, y, series, rules}) → a figure: points, lines, formula curves and bands on linear or log axes, with legend, data table, PNG and CSV; a cell that runs again updates its figure in place */
    chart: () => import('./chapter/chart/chart.ts').then((m) => (options: Parameters<typeof m.chart>[0]) => m.chart(options, cellSignal())),
    /** table({columns, rows, caption}) → a table of numbers that scrolls on a phone; rows may be a function, read again every `refresh` seconds */
    table: () => import('./chapter/table/table.ts').then((m) => m.table),
    /** stabilityChart({hamiltonian, params, x, y, frequencyParam, boundaries, onSelect}) → Floquet chart computed in a worker */
    stabilityChart: () => import('./chapter/stability-chart/stability-chart.ts').then((m) => (options: Parameters<typeof m.stabilityChart>[0]) => m.stabilityChart(options, build())),
    /** poincareSection({energies, energy, plane, orbits, crossings, onLaunch}) → Hénon–Heiles surface of section computed in a worker; click to launch an orbit; {system: 'anisotropic-kepler', factor} for the paper's chaotic Kepler variant */
    poincareSection: () => import('./chapter/poincare-section/poincare-section.ts').then((m) => m.poincareSection),
    /** chaoticShare({energy, plane, grid, time}) → Promise of the section's chaotic share and its errors, computed in a worker */
    chaoticShare: () => import('./chapter/poincare-section/poincare-section.ts').then((m) => m.chaoticShare),
    /** anisotropicKeplerRun({factor, time}) → Promise of the paper's orbit in the anisotropic Kepler problem, regularised, at two tolerances: period, energy error, exponent */
    anisotropicKeplerRun: () => import('./chapter/poincare-section/poincare-section.ts').then((m) => m.anisotropicKeplerRun),
    /** henonHeilesFig6: the chaotic share read off Hénon & Heiles (1964) Fig. 6 at E = 1/12, 1/8, 1/6, with its reading error */
    henonHeilesFig6: () => import('../core/analysis/poincare-area.ts').then((m) => m.HENON_HEILES_FIG6),
    /** methodComparison({hamiltonian, params, initial, dt, tEnd, methods, order}) → the same model under several integrators, computed in a worker: energy error, phase portraits, cost, order study; its `results` is a Promise of the checks */
    methodComparison: () =>
      import('./chapter/method-comparison/method-comparison.ts').then((m) => (options: Parameters<typeof m.methodComparison>[0]) => m.methodComparison(options, build())),
    /** pendulumPeriod(q0, p0, omega) → the exact period 4K(k)/ω of H = p²/2 − ω² cos q, from the complete elliptic integral */
    pendulumPeriod: () => import('../core/analysis/pendulum.ts').then((m) => m.pendulumPeriod),

    /** pendulumAction(q0, p0, omega) → the action J = (1/2π)∮p dq of H = p²/2 − ω² cos q, (8ω/π)[E(k) − (1 − k²)K(k)]; NaN unless it librates */
    pendulumAction: () => import('../core/analysis/pendulum.ts').then((m) => m.pendulumAction),
    /** pendulumFrequency(q0, p0, omega) → ω(J) = ∂H/∂J = πω/2K(k) of the pendulum's libration */
    pendulumFrequency: () => import('../core/analysis/pendulum.ts').then((m) => m.pendulumFrequency),
    /** completeEllipticE(k) → E(k), the complete elliptic integral of the second kind */
    completeEllipticE: () => import('../core/analysis/pendulum.ts').then((m) => m.completeEllipticE),
    /** loopAction(q, p, t) → {action, period, loops}: (1/2π)∮p dq over the whole loops of a sampled 1-DOF orbit, or null */
    loopAction: () => import('../core/analysis/action.ts').then((m) => m.loopAction),
    /** flowJacobian(flow, x0, epsilon) → the Jacobian ∂x(T)/∂x(0) of a flow map by central differences, row-major */
    flowJacobian: () => import('../core/analysis/flow-map.ts').then((m) => m.flowJacobian),
    /** symplecticDefect(M, n) → the largest entry of MᵀΩM − Ω */
    symplecticDefect: () => import('../core/analysis/flow-map.ts').then((m) => m.symplecticDefect),
    /** symplecticCheck(flow, x0, epsilon) → {defect, defectHalf, truncation}: the flow map's symplectic defect at ε and ε/2, and the central differences' error from the two */
    symplecticCheck: () => import('../core/analysis/flow-map.ts').then((m) => m.symplecticCheck),

    /** lagrangePoints(mu) → the five equilibria of the restricted three-body problem's rotating frame, [{name, x, y, jacobi}]: L1–L3 from their quintics, L4 and L5 in closed form */
    lagrangePoints: () => threeBody().then((m) => m.lagrangePoints),
    /** collinearQuintics(mu) → {L1, L2, L3}: the coefficients, highest power first, of the quintic whose root is each collinear point's distance from its nearer primary */
    collinearQuintics: () => threeBody().then((m) => m.collinearQuintics),
    /** triangularModes(mu) → {stable, libration, epicycle, growth, rotation}: the roots of λ⁴ + λ² + (27/4)μ(1 − μ) = 0 about L4 */
    triangularModes: () => threeBody().then((m) => m.triangularModes),
    /** routhMu: (1 − √(23/27))/2 ≈ 0.0385, below which L4 and L5 are linearly stable */
    routhMu: () => threeBody().then((m) => m.ROUTH_MU),
    /** jacobiConstant([x, y, px, py], mu) → C = −2H of the restricted three-body problem in the rotating frame */
    jacobiConstant: () => threeBody().then((m) => m.jacobiConstant),
    /** effectivePotential(x, y, mu) → Ω = (x² + y²)/2 + (1 − μ)/r1 + μ/r2 */
    effectivePotential: () => threeBody().then((m) => m.effectivePotential),
    /** zeroVelocityCurve(mu, C, {half, n, coarse}) → {curve, forbidden}: points of 2Ω = C and grid points where 2Ω < C */
    zeroVelocityCurve: () => threeBody().then((m) => m.zeroVelocityCurve),
    /** standardMap({K, kMax, orbits, iterations, height, onLaunch}) → the standard map p' = p + K sin q, q' = q + p' on the torus, redrawn as K moves; click to launch an orbit and read its rotation number and Lyapunov exponent */
    standardMap: () => import('./chapter/standard-map/standard-map.ts').then((m) => m.standardMap),
    /** greeneLevels(depth, first) → [{level, m, n, K}]: for each Fibonacci orbit m/n, the K at which its residue is 1/4 (Greene's criterion for the golden circle) */
    greeneLevels: () => standardMapAnalysis().then((m) => m.greeneLevels),
    /** greeneK: 0.971635406, the K at which the standard map's last invariant circle breaks (Greene 1979, MacKay 1983) */
    greeneK: () => standardMapAnalysis().then((m) => m.GREENE_K),
    /** measureDiffusion(K, {orbits, iterations, seed}) → {D, standardError, halfRunD, orbits, iterations}: ⟨(p_n − p_0)²⟩/n over orbits from random points of the torus */
    measureDiffusion: () => standardMapAnalysis().then((m) => m.measureDiffusion),
    /** quasilinearDiffusion(K) → K²/2, the diffusion of p for independent phases */
    quasilinearDiffusion: () => standardMapAnalysis().then((m) => m.quasilinearDiffusion),
    /** rechesterWhiteDiffusion(K) → (K²/2)[1 − 2J₂ − 2J₁² + 2J₂² + 2J₃²] (Rechester & White 1980) */
    rechesterWhiteDiffusion: () => standardMapAnalysis().then((m) => m.rechesterWhiteDiffusion),
    /** rechesterWhiteRemainder(K) → 6(2/πK)^{3/2}: the terms Rechester and White leave out, as a fraction of K²/2 */
    rechesterWhiteRemainder: () => standardMapAnalysis().then((m) => m.rechesterWhiteRemainder),
    /** acceleratorMode(K) → m ≥ 1 when 2πm ≤ K ≤ √((2πm)² + 16), where islands carry p by 2πm a kick; else 0 */
    acceleratorMode: () => standardMapAnalysis().then((m) => m.acceleratorMode),
    /** nearAcceleratorMode(K) → whether K is in or near an accelerator band, where sticky islands bias the diffusion */
    nearAcceleratorMode: () => standardMapAnalysis().then((m) => m.nearAcceleratorMode),
    /** chirikovOverlap: {primary: π²/4, withSecondary: (√(4 + 2π) − 2)²}, Chirikov's overlap estimates of the last circle's breakup */
    chirikovOverlap: () => standardMapAnalysis().then((m) => m.CHIRIKOV_OVERLAP),
    /** besselJ(n, x) → the Bessel function J_n(x) of integer order */
    besselJ: () => standardMapAnalysis().then((m) => m.besselJ),
    /** orbitReading(K, [q, p], iterations) → {rotation, lyapunov, pMin, pMax, crossed} of a standard-map orbit */
    orbitReading: () => standardMapAnalysis().then((m) => m.orbitReading),
    /** ensemble({model, center, radius, points, dt, speed, until, view, onFrame}) → a disc of initial conditions of a 1-DOF model carried by its flow in a worker: a cloud of points and the disc's boundary, refined where it stretches, with its area read out */
    ensemble: () => liouville().then((m) => m.ensemble),
    /** flowArea(model, {center, radius, dt, span, maxSegment}) → {area, polygonError, initialArea, vertices, saturated, unresolved, failed}: the area of a disc's boundary carried span time units by the model */
    flowArea: () => liouville().then((m) => m.flowArea),
    /** modelSection(model, start, {dt, count, index}) → {states, times, count}: the upward crossings of x_index = 0, by Hénon's trick */
    modelSection: () => liouville().then((m) => m.modelSection),
    /** recordReturns(phases) → [{n, distance}]: the crossings at which a phase (in turns) came closer to its start than ever before */
    recordReturns: () => liouville().then((m) => m.recordReturns),
    /** kacMeasurement(phases, halfStepPhases, alpha, width) → {mean, returns, span, visitBound, phaseError, rotationSpread, periodic}: returns to an arc of width turns, with the Denjoy–Koksma bound */
    kacMeasurement: () => liouville().then((m) => m.kacMeasurement),
    /** exponentialGrowth(t, size, from, to) → {rate, bound, span, samples}: the rate a of a size growing as e^{at} times an oscillation, from a line through ln(size), with the bound the oscillation puts on it */
    exponentialGrowth: () => import('../core/analysis/exponential-growth.ts').then((m) => m.exponentialGrowth),

    // The simulation core
    /** canonicalEquations({dof, hamiltonian, params}) → Promise of a Model */
    canonicalEquations: () =>
      import('../core/model/canonical-equations.ts').then((m) => (spec: Parameters<typeof m.canonicalEquations>[0]) => m.canonicalEquations(spec, build())),
    /** new Simulation(model, {initial, dt, every, derived}): integrate off-screen, e.g. for a theory check */
    Simulation: () => import('./chapter/models/cell-simulation.ts').then((m) => m.CellSimulation),
    spectrum: () => spectrum().then((m) => m.spectrum),
    findPeaks: () => import('../core/spectrum/peaks.ts').then((m) => m.findPeaks),
    relativeDrift: () => invariants().then((m) => m.relativeDrift),
    evaluateAlong: () => invariants().then((m) => m.evaluateAlong),

    // Analysis for the chapters' theory checks
    crossings: () => analysis().then((m) => m.crossings),
    meanPeriod: () => analysis().then((m) => m.meanPeriod),
    floquet: () => analysis().then((m) => m.floquet),
    /** peakError(spectrum, lines, line) → how far leakage and refinement can move a spectral peak */
    peakError: () => analysis().then((m) => m.peakError),
    keplerOrbit: () => analysis().then((m) => m.keplerOrbit),
    rutherfordAngle: () => analysis().then((m) => m.rutherfordAngle),
    deflectionFrom: () => analysis().then((m) => m.deflectionFrom),
    outgoingDirection: () => analysis().then((m) => m.outgoingDirection),
    angleBetween: () => analysis().then((m) => m.angleBetween),
  };
}
