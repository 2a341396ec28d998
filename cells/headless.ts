/**
 * Runs a chapter's cells once, without a page: the build uses it to learn
 * what the cells compute as written (which models they define, which
 * equations they typeset) so that work is done ahead of the reader.
 *
 * It follows the runtime's rules where they matter for values — a cell runs
 * once its inputs have values, a name no cell defines comes from the
 * builtins or is an error, a repeated name is an error, a promise is
 * awaited — and simplifies the rest: a generator gives its first value, and
 * nothing re-runs.
 */
import { compileCell } from './cell-definition.ts';
import type { CellSpec } from './spec.ts';

export interface HeadlessCell {
  readonly id: string;
  readonly source: string;
  readonly spec: CellSpec;
}

export type HeadlessResult = { readonly value: unknown } | { readonly error: Error };

export interface HeadlessOptions {
  /** The longest a cell's promise may take before it counts as failed. */
  timeoutMs?: number;
  /** The value of `invalidation` for each cell: by default a promise that never settles. */
  invalidation?: () => Promise<unknown>;
}

class HeadlessError extends Error {
  override name = 'RuntimeError';
}

function withTimeout<T>(promise: Promise<T>, ms: number, what: string): Promise<T> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const timeout = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new HeadlessError(`${what} took longer than ${ms} ms`)), ms);
  });
  return Promise.race([promise, timeout]).finally(() => clearTimeout(timer));
}

function isIterator(value: unknown): value is Iterator<unknown> | AsyncIterator<unknown> {
  return typeof value === 'object' && value !== null && typeof (value as { next?: unknown }).next === 'function'
    && (Symbol.iterator in value || Symbol.asyncIterator in value);
}

/**
 * Evaluates `cells` with `builtins` (plain values; a function-valued builtin
 * is passed as the function). Returns each cell's value or error by id.
 */
export async function runHeadless(
  cells: readonly HeadlessCell[],
  builtins: Readonly<Record<string, unknown>>,
  options: HeadlessOptions = {},
): Promise<Map<string, HeadlessResult>> {
  const { timeoutMs = 10_000, invalidation = () => new Promise<never>(() => {}) } = options;
  const byName = new Map<string, HeadlessCell[]>();
  for (const cell of cells) {
    if (cell.spec.name) byName.set(cell.spec.name, [...(byName.get(cell.spec.name) ?? []), cell]);
  }
  const results = new Map<string, Promise<unknown>>();

  const valueOf = (cell: HeadlessCell, path: readonly string[]): Promise<unknown> => {
    const known = results.get(cell.id);
    if (known) return known;
    const running = (async () => {
      const { name } = cell.spec;
      if (name && (byName.get(name)?.length ?? 0) > 1) throw new HeadlessError(`${name} is defined more than once`);
      // Boxed, so that `invalidation` (a promise the cell receives as such) is not awaited with the rest.
      const boxes = await Promise.all(cell.spec.inputs.map((input) => inputValue(input, [...path, name ?? cell.id])));
      const inputs = boxes.map((box) => box.value);
      const definition = compileCell(cell.source, cell.spec, cell.id) as (...args: unknown[]) => unknown;
      let value = definition(...inputs);
      if (isIterator(value)) value = (await value.next()).value;
      return await withTimeout(Promise.resolve(value), timeoutMs, `cell ${name ?? cell.id}`);
    })();
    results.set(cell.id, running);
    return running;
  };

  const inputValue = async (input: string, path: readonly string[]): Promise<{ value: unknown }> => {
    if (input === 'invalidation') return { value: invalidation() };
    const definers = byName.get(input);
    if (definers) {
      if (path.includes(input)) throw new HeadlessError(`circular definition of ${input}`);
      try {
        return { value: await valueOf(definers[0], path) };
      } catch (error) {
        // The cause travels along, so that the build can tell a cell's own failure from its input's.
        throw new HeadlessError(`input ${input} failed: ${(error as Error)?.message ?? String(error)}`, { cause: error });
      }
    }
    if (Object.hasOwn(builtins, input)) return { value: builtins[input] };
    throw new HeadlessError(`${input} is not defined`);
  };

  const settled = new Map<string, HeadlessResult>();
  await Promise.all(
    cells.map(async (cell) => {
      try {
        settled.set(cell.id, { value: await valueOf(cell, []) });
      } catch (error) {
        settled.set(cell.id, { error: error instanceof Error ? error : new HeadlessError(String(error)) });
      }
    }),
  );
  return settled;
}
