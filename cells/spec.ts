/**
 * The shape of a parsed cell, shared by the build (site/lib/remark-cells.mjs,
 * which parses the chapter's cells once) and the browser (cell-source.ts, which
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
  /**
   * The bodies of the loops in the cell, as source offsets [start, end) and
   * whether each is a `{ … }` block: cell-definition.ts starts each iteration with
   * the page's loop guard (loop-guard.ts). Absent in specs of older builds.
   */
  readonly loops?: readonly (readonly [number, number, boolean])[];
}

/** An ESTree node as the parser gives it: a type, offsets and child nodes among its fields. */
interface SyntaxNode {
  readonly type: string;
  readonly start: number;
  readonly end: number;
  readonly body?: SyntaxNode;
  readonly [field: string]: unknown;
}

/** The subset of an @observablehq/parser cell that {@link describeCell} reads. */
export interface ParsedCell {
  id: { type: string; name?: string } | null;
  body: SyntaxNode | null;
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
    loops: cell.body ? loopBodies(cell.body) : [],
  };
}

const LOOPS = new Set(['ForStatement', 'ForInStatement', 'ForOfStatement', 'WhileStatement', 'DoWhileStatement']);

function isNode(value: unknown): value is SyntaxNode {
  return typeof value === 'object' && value !== null && typeof (value as SyntaxNode).type === 'string' && typeof (value as SyntaxNode).start === 'number';
}

/** Every loop's body in the tree, functions' loops included (a function defined in a cell loops in it). */
function loopBodies(root: SyntaxNode): [number, number, boolean][] {
  const found: [number, number, boolean][] = [];
  const visit = (node: SyntaxNode): void => {
    if (LOOPS.has(node.type) && node.body) found.push([node.body.start, node.body.end, node.body.type === 'BlockStatement']);
    for (const value of Object.values(node)) {
      if (Array.isArray(value)) value.forEach((item) => isNode(item) && visit(item));
      else if (isNode(value)) visit(value);
    }
  };
  visit(root);
  return found;
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
