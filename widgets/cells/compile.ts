/**
 * Turns a cell's source and {@link CellSpec} into the definition function the
 * Observable runtime calls, with the cell's inputs as parameters in order.
 *
 * Only sources that the Observable parser accepted reach this point, and the
 * spec's body offsets come from that parse, so the body slice is a complete
 * expression or block: text like `x = 1); alert(1); (2` never gets here.
 */
import type { CellSpec } from './spec.ts';

/** A cell's definition: called by the runtime with the values of its inputs. */
export type CellDefinition = (...inputs: never[]) => unknown;

type FunctionMaker = new (...parametersAndBody: string[]) => CellDefinition;

const AsyncFunction = Object.getPrototypeOf(async function () {}).constructor as FunctionMaker;
const GeneratorFunction = Object.getPrototypeOf(function* () {}).constructor as FunctionMaker;
const AsyncGeneratorFunction = Object.getPrototypeOf(async function* () {}).constructor as FunctionMaker;

function pickMaker(spec: CellSpec): FunctionMaker {
  if (spec.async && spec.generator) return AsyncGeneratorFunction;
  if (spec.async) return AsyncFunction;
  if (spec.generator) return GeneratorFunction;
  return Function as unknown as FunctionMaker;
}

/** The function body: a block's inside, or `return` of the expression. */
export function cellBody(source: string, spec: CellSpec): string {
  const [start, end] = spec.body;
  if (start === end) return '';
  const body = source.slice(start, end);
  // The newline before ")" keeps a trailing line comment from swallowing it.
  return spec.block ? body.slice(1, -1) : `return (\n${body}\n)`;
}

/**
 * Builds the definition. `label` names the cell in stack traces and in the
 * browser's debugger (via sourceURL).
 */
export function compileCell(source: string, spec: CellSpec, label: string): CellDefinition {
  const Maker = pickMaker(spec);
  const sourceUrl = `\n//# sourceURL=cell:${encodeURIComponent(label)}`;
  return new Maker(...spec.inputs, cellBody(source, spec) + sourceUrl);
}
