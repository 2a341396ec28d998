/**
 * Turns a cell's source and {@link CellSpec} into the definition function the
 * Observable runtime calls, with the cell's inputs as parameters in order.
 *
 * Only sources that the Observable parser accepted reach this point, and the
 * spec's body offsets come from that parse, so the body slice is a complete
 * expression or block: text like `x = 1); alert(1); (2` never gets here.
 */
import { noteCellRun } from './cell-errors.ts';
import { LoopGuard } from './loop-guard.ts';
import type { CellSpec } from './spec.ts';

/** A cell's definition: called by the runtime with the values of its inputs. */
export type CellDefinition = (...inputs: never[]) => unknown;

type FunctionMaker = new (...parametersAndBody: string[]) => CellDefinition;

// Taken now, before any cell runs: the sandbox later puts guarded versions in the globals' place.
const PlainFunction = Function as unknown as FunctionMaker;
const AsyncFunction = Object.getPrototypeOf(async function () {}).constructor as FunctionMaker;
const GeneratorFunction = Object.getPrototypeOf(function* () {}).constructor as FunctionMaker;
const AsyncGeneratorFunction = Object.getPrototypeOf(async function* () {}).constructor as FunctionMaker;

function pickMaker(spec: CellSpec): FunctionMaker {
  if (spec.async && spec.generator) return AsyncGeneratorFunction;
  if (spec.async) return AsyncFunction;
  if (spec.generator) return GeneratorFunction;
  return PlainFunction;
}

/** The name the loop guard has inside a cell's code. */
const GUARD = '$pbLoop';

/** The cell's text with every loop iteration starting by asking the guard whether to break. */
function guardLoops(source: string, spec: CellSpec): string {
  const inserts: [number, string][] = [];
  for (const [start, end, block] of spec.loops ?? []) {
    if (block) {
      inserts.push([start + 1, `if (${GUARD}()) break;`]);
    } else {
      inserts.push([start, `{ if (${GUARD}()) break; `], [end, ' }']);
    }
  }
  let text = source;
  // From the end backwards, so earlier offsets stay valid.
  for (const [at, insert] of inserts.sort((a, b) => b[0] - a[0])) text = text.slice(0, at) + insert + text.slice(at);
  return text;
}

/** The function body: a block's inside, or `return` of the expression, loops guarded. */
export function cellBody(source: string, spec: CellSpec): string {
  const [start, end] = spec.body;
  if (start === end) return '';
  const guarded = guardLoops(source, spec);
  const body = guarded.slice(start, end + (guarded.length - source.length));
  // The newline before ")" keeps a trailing line comment from swallowing it.
  return spec.block ? body.slice(1, -1) : `return (\n${body}\n)`;
}

/** The page's loop guard (loop-guard.ts), shared by every cell. */
export const pageLoopGuard = new LoopGuard();

function isIterator(value: unknown): value is Iterator<unknown> & { [Symbol.iterator](): unknown } {
  return typeof value === 'object' && value !== null && typeof (value as Iterator<unknown>).next === 'function';
}

/**
 * The value a cell's code returned, made to fail with the guard's error when
 * a loop was stopped while it was computed — a broken-off loop leaves a
 * wrong value, which must never pass for the cell's result. A promise is
 * checked when it settles, a generator after each step.
 */
function checked(value: unknown, guard: LoopGuard, before: number): unknown {
  const fail = () => {
    const stop = guard.stoppedSince(before);
    if (stop) throw stop;
  };
  fail();
  if (value instanceof Promise) return value.then((v) => (fail(), v));
  if (isIterator(value)) {
    const next = value.next.bind(value);
    value.next = (...args: [] | [unknown]) => {
      const count = guard.count;
      const step = next(...args);
      if (step instanceof Promise) return step.then((s) => (guard.stoppedSince(count) && fail(), s)) as never;
      const stop = guard.stoppedSince(count);
      if (stop) throw stop;
      return step;
    };
  }
  return value;
}

/**
 * Names a cell's code sees in place of the page's globals of the same name
 * (the sandbox's guarded `Array`, say): reader code is compiled with them,
 * the chapter's own cells without.
 */
export type CellScope = Readonly<Record<string, unknown>>;

/**
 * The cell's function. With a scope, it is made inside a function whose
 * parameters are the scope's names, so that the cell's own declarations
 * (`const Array = …` in a block) shadow them rather than clash with them.
 */
function makeCode(spec: CellSpec, body: string, sourceUrl: string, scope: CellScope | undefined): (...args: unknown[]) => unknown {
  if (!scope) return new (pickMaker(spec))(...spec.inputs, GUARD, body + sourceUrl) as (...args: unknown[]) => unknown;
  const kind = `${spec.async ? 'async ' : ''}function${spec.generator ? '*' : ''}`;
  // The cell's body starts on the line it started on before, so positions in stack traces stay the same.
  const outer = new PlainFunction(...Object.keys(scope), `return ${kind} (${[...spec.inputs, GUARD].join(', ')}) {${body}\n}${sourceUrl}`);
  return (outer as unknown as (...values: unknown[]) => unknown)(...Object.values(scope)) as (...args: unknown[]) => unknown;
}

/**
 * Builds the definition. `id` names the cell in stack traces and in the
 * browser's debugger (via sourceURL), and to the loop guard; its name, when
 * it has one, is what the guard's message says. `scope` (reader code only)
 * replaces some globals, see {@link CellScope}.
 */
export function compileCell(source: string, spec: CellSpec, id: string, guard: LoopGuard = pageLoopGuard, scope?: CellScope): CellDefinition {
  const sourceUrl = `\n//# sourceURL=cell:${encodeURIComponent(id)}`;
  const code = makeCode(spec, cellBody(source, spec), sourceUrl, scope);
  const loop = guard.forCell(id, spec.name ? `cell ${spec.name}` : 'this cell');
  return ((...inputs: unknown[]) => {
    noteCellRun(id);
    const before = guard.count;
    return checked(code(...inputs, loop), guard, before);
  }) as CellDefinition;
}
