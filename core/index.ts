/**
 * The simulation core: DOM-free, shared by the widgets, the CLI and the tests.
 *
 * This is its one front door: code in widgets/ and the VS Code extension
 * imports the core from here, never a module inside it, so the core can
 * rearrange its modules without its clients noticing. Two kinds of import
 * name a module directly, on purpose:
 * - a dynamic `import()` of a part loaded on demand (the catalogue's lazy
 *   entries, the compile worker), so that the bundler splits that part off
 *   and a page fetches only what its cells use;
 * - tests and benchmarks, which exercise and time the parts one by one, and
 *   the build's precompiler, which hands mathjs over statically
 *   (expression/mathjs-instance.ts).
 *
 * Every module re-exported here is free of side effects at load, so a
 * bundle keeps only what its importer uses.
 */
export {
  type AnisotropicKepler,
  angularMomentum,
  DEVANEY_THRESHOLD,
  fromLeviCivita,
  keplerEnergy,
  massRatio,
  PAPER_INITIAL,
  PAPER_K,
  regularisedField,
  regularisedHamiltonian,
  regularisedJacobian,
  relativeMotion,
  toLeviCivita,
} from './analysis/anisotropic-kepler.ts';
export {
  type KeplerLyapunov,
  keplerLyapunov,
  type KeplerSection,
  keplerSection,
  maxReturn,
  regularisedOrbit,
  regularisedStart,
  sampleInterval,
  sectionLaunch,
  sectionScale,
} from './analysis/anisotropic-kepler-flow.ts';
export { type CheckInput } from './analysis/check-input.ts';
export { crossings, meanPeriod } from './analysis/crossings.ts';
export { boundedCheck, driftCheck, type DriftContext, type EnergyDrift, energyDrift, modifiedEnergyCheck } from './analysis/energy-drift.ts';
export { fastestRate, spectralRadius } from './analysis/fastest-rate.ts';
export { floquet, floquetGrid } from './analysis/floquet.ts';
export { henonHeiles } from './analysis/henon-heiles.ts';
export { keplerOrbit } from './analysis/kepler.ts';
export { peakError } from './analysis/leakage.ts';
export { fitLine, type LineFit } from './analysis/line-fit.ts';
export { largestLyapunov } from './analysis/lyapunov.ts';
export { verletCorrection } from './analysis/modified-hamiltonian.ts';
export { localSlopes, METHOD_ORDERS, orderCheck, orderStudy, type OrderStudyInput } from './analysis/order-study.ts';
export { completeEllipticE, completeEllipticK, pendulumAction, pendulumFrequency, pendulumPeriod } from './analysis/pendulum.ts';
export { loopAction } from './analysis/action.ts';
export { flowJacobian, symplecticCheck, symplecticDefect } from './analysis/flow-map.ts';
export { type ModelSection, modelSection } from './analysis/model-section.ts';
export { arcReturns, arcVisitBound, kacMeasurement, periodicWithin, recordReturns } from './analysis/recurrence.ts';
export { rk4Amplification, rk4StabilityLimit } from './analysis/rk-stability.ts';
export { turningPoint, wellPeriod } from './analysis/well-period.ts';
export { collinearQuintics, effectivePotential, jacobiConstant, type LagrangePoint, lagrangePoints, ROUTH_MU, triangularModes, type TriangularModes, zeroVelocityCurve } from './analysis/three-body.ts';
export {
  acceleratorMode,
  besselJ,
  CHIRIKOV_OVERLAP,
  type DiffusionMeasure,
  GREENE_K,
  type GreeneLevel,
  greeneLevels,
  type GreeneOrbit,
  greeneOrbit,
  greeneResidueAt,
  measureDiffusion,
  nearAcceleratorMode,
  orbitReading,
  type OrbitReading,
  quasilinearDiffusion,
  rechesterWhiteDiffusion,
  rechesterWhiteRemainder,
  residue,
} from './analysis/standard-map.ts';
export { type AreaPreservingMap, TWO_PI, wrapAngle } from './maps/area-preserving-map.ts';
export { iterateMap, MAX_ITERATES, mapRecord } from './maps/map-iteration.ts';
export { standardMap } from './maps/standard-map.ts';
export { type ExponentialGrowth, exponentialGrowth } from './analysis/exponential-growth.ts';
export { chaoticArea, type ChaoticArea, sectionBox } from './analysis/poincare-area.ts';
export { allowed, launchState, type Plane, planeIndices, section } from './analysis/poincare.ts';
export { angleBetween, deflectionFrom, outgoingDirection, rutherfordAngle } from './analysis/scattering.ts';
export { abortError, type BuildControl } from './model/build-control.ts';
export { type BuildOptions, canonicalEquations, compiledModelFor, type HamiltonianSpec } from './model/canonical-equations.ts';
export { bytesFor, capacityFor } from './capacity.ts';
export { compileModel } from './model/compile-model.ts';
export { type CompiledModel, type CompiledModelStore, type ModelKeySpec } from './model/compiled-model.ts';
export { csvHeader, csvRows, roundTripNumber, toCSV } from './tables/csv.ts';
export { csvNumber, type CsvRecord, csvRecords, parseCSV } from './tables/csv-read.ts';
export { BatchRun, rowColumns } from './dataset/batch-run.ts';
export { type Axis, type Range } from './dataset/box.ts';
export { fillInitial, type InitialSet, trajectoryCount } from './dataset/initial-set.ts';
export { MAX_SEED } from './dataset/philox.ts';
export { everyKSteps, listedTimes, type SampleTimes, stepsTo } from './dataset/sample-times.ts';
export { BlowUpError, InputError } from './errors.ts';
export { ParseError } from './tables/parse-error.ts';
export { type ExportMeta, methodMeta } from './tables/export-meta.ts';
export { type EvaluationFault, firstEvaluation } from './model/first-evaluation.ts';
export { checkName, stateNames, RESERVED_NAMES, type ReservedName } from './expression/names.ts';
export { provideMathjs } from './expression/mathjs.ts';
export { applyMethod } from './integrators/apply.ts';
export { DEFAULT_METHOD, methodChoice, type MethodChoice, type MethodName } from './integrators/methods.ts';
export { differenceJacobian } from './integrators/midpoint.ts';
export { evaluateAlong, relativeChange, relativeDrift, type StateFunction } from './invariants.ts';
export { isFunctionSource, MATH_NAMES, provideAcorn } from './js-function/function-source.ts';
export { type OpaqueHamiltonian } from './js-function/stencil.ts';
export { type Found, JsonExportReader, parseJSON } from './tables/json-read.ts';
export { type JsonValue, parseJsonValue } from './tables/json-scan.ts';
export { jsonHead, jsonNumber, jsonRows, jsonTail, toJSON } from './tables/json.ts';
export { MAX_BATCH, MAX_CELL_STEPS, MAX_DOF, MAX_DT, MAX_SPEED, MIN_DT, outside } from './limits.ts';
export { modelFromCompiled } from './model/model-from-compiled.ts';
export { findPeaks, type Peak } from './spectrum/peaks.ts';
export { readTable } from './tables/read-table.ts';
export { recordLayout, type RecordLayout, type RecordSeries, TrajectoryRecord } from './record.ts';
export { rk38 } from './integrators/rk38.ts';
export { DEFAULT_DT, type DerivedSeries, Simulation, type SimulationOptions } from './simulation.ts';
export { spectrum, type Spectrum } from './spectrum/spectrum.ts';
export { SUMMARY } from './summary.ts';
export { type Table } from './tables/table.ts';
export { type HamiltonianFunction, type Model, type Route, type Stepper, type VectorField } from './types.ts';
export { VERSION } from './version.ts';
export { checkWindowName, hamming, type WindowName } from './spectrum/window.ts';
export * from './ensemble/index.ts';
// The build hands canonicalEquations the terms' rules, which it would otherwise load on demand.
export { provideTermRules } from './model/canonical-equations.ts';
export * as nonHamiltonianRules from './model/non-hamiltonian.ts';
