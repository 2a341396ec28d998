/**
 * The widgets' front door: what the cells (the page's boot), the site's build
 * and the VS Code extension use of widgets/. Inside, the layers are
 * controls → plots → exports → simulator → chapter → the catalogue; a cell
 * reaches each widget through the catalogue, which loads it when first
 * called.
 *
 * Only re-exports: the build follows the names imported through here one by
 * one (site/lib/chunks.mjs), so importing one never brings the rest into a
 * page's first load.
 */
export { createLibrary, loadExerciseWidget, prefetchWidgets, WIDGET_NAMES } from './catalogue.ts';
export type { ExerciseHost, ProgressView } from './chapter/exercise/exercise.ts';
export { exercisesInText, type Exercise, KIND_NAMES, parseExercise, publicPart, sealedPart } from './chapter/exercise/exercise-spec.ts';
export { seal } from './chapter/exercise/seal.ts';
export { memoryStore, PAGE_DATA_ATTRIBUTE, PAGE_DATA_FORMAT, pageContext, type PageContext, type PageData } from './chapter/models/page-data.ts';
export { equationsHtml, equationsLatex, katexOptions, texHtml, typesetKey } from './chapter/math/typeset.ts';
export { downloadText } from './exports/download.ts';
export { PROVENANCE_EVENT, type ProvenanceRequest } from './exports/provenance.ts';
export { INPUT_EVENT, type WidgetInput } from './controls/widget-input.ts';
export { modelSpec, type ModelOptions } from './simulator/options.ts';
export { reserveHtml, simulatorPlan, type ReserveOptions } from './simulator/reserve.ts';
