/**
 * The shape of a parsed cell, shared by the build (src/lib/remark-cells.mjs,
 * which parses the chapter's cells once) and the browser (parse.ts, which
 * parses a reader's edit). Keeping one description means the page can compile
 * the author's cells without shipping the parser.
 */

/** What the runtime needs to know about a cell besides its source text. */
export interface CellSpec {
  /** The name the cell defines, or null for an anonymous cell. */
  readonly name: string | null;
  /** Names the cell reads from other cells or builtins, without repeats. */
  readonly inputs: readonly string[];
  readonly async: boolean;
  readonly generator: boolean;
  /** Source offsets [start, end) of the body; [0, 0] for an empty cell. */
  readonly body: readonly [number, number];
  /** True when the body is a `{ … }` block rather than an expression. */
  readonly block: boolean;
}

/** The subset of an @observablehq/parser cell that {@link describeCell} reads. */
export interface ParsedCell {
  id: { type: string; name?: string } | null;
  body: { type: string; start: number; end: number } | null;
  references: ReadonlyArray<{ type: string; name?: string }>;
  async: boolean;
  generator: boolean;
}

/** A cell the book cannot run although it parses, such as `viewof x = …`. */
export class UnsupportedCellError extends SyntaxError {
  constructor(message: string) {
    super(message);
    this.name = 'SyntaxError';
  }
}

/**
 * Turns a parse tree into a {@link CellSpec}. Observable features the book
 * does not offer (imports, `viewof`, `mutable`) are rejected here so the
 * reader sees why, instead of a confusing runtime error later.
 */
export function describeCell(cell: ParsedCell): CellSpec {
  if (cell.body?.type === 'ImportDeclaration') {
    throw new UnsupportedCellError('import cells are not supported');
  }
  if (cell.id && cell.id.type !== 'Identifier') {
    throw new UnsupportedCellError(`${keyword(cell.id.type)} cells are not supported`);
  }
  const inputs = new Set<string>();
  for (const reference of cell.references) {
    if (reference.type !== 'Identifier' || !reference.name) {
      throw new UnsupportedCellError(`${keyword(reference.type)} references are not supported`);
    }
    inputs.add(reference.name);
  }
  return {
    name: cell.id?.name ?? null,
    inputs: [...inputs],
    async: cell.async,
    generator: cell.generator,
    body: cell.body ? [cell.body.start, cell.body.end] : [0, 0],
    block: cell.body?.type === 'BlockStatement',
  };
}

function keyword(nodeType: string): string {
  if (nodeType === 'ViewExpression') return 'viewof';
  if (nodeType === 'MutableExpression') return 'mutable';
  return nodeType;
}

/**
 * One line for the reader: the parser already puts "(line:column)" at the end
 * of its messages, e.g. "SyntaxError: Unexpected token (1:7)".
 */
export function formatError(error: unknown): string {
  if (error instanceof Error) return `${error.name}: ${error.message}`;
  return `Error: ${String(error)}`;
}
