/**
 * The cells' front door: what the site's build (which runs the cells once,
 * headless, and highlights their code) and the VS Code extension (whose
 * preview runs them and whose analyzer reads them) use of cells/. The page
 * itself enters through boot.ts, the build's entry script.
 */
export { asParsableBlock } from './block-syntax.ts';
export { createBuiltins } from './builtins.ts';
export { compileCell } from './cell-definition.ts';
export { CellView } from './cell-view.ts';
export { BROWSER_GLOBALS, JAVASCRIPT_GLOBALS, mathByName, standardValues } from './globals.ts';
export { runHeadless, type HeadlessCell } from './headless.ts';
export { currentCellSignal, Notebook, type CellVariable } from './runtime.ts';
export { describeCell, formatError, type CellSpec, type ParsedCell } from './spec.ts';
export { type ChapterExercises, EXERCISE_RESULT_EVENT, type ExerciseRecord, type ExerciseResult, ProgressStore } from './progress.ts';
