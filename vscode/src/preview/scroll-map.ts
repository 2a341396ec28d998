/**
 * Source lines ↔ vertical positions in the preview, from each block's
 * lines and box: within a block, lines are spread evenly over its height.
 */
export interface BlockBox {
  /** First and last source line (from 0). */
  readonly line: number;
  readonly endLine: number;
  /** Top and height in page pixels. */
  readonly top: number;
  readonly height: number;
}

/** The page position that shows `line`: in the last block starting at or before it. */
export function offsetOfLine(blocks: readonly BlockBox[], line: number): number {
  let block: BlockBox | undefined;
  for (const b of blocks) if (b.line <= line) block = b;
  if (!block) return 0;
  const span = block.endLine + 1 - block.line;
  const fraction = Math.min(1, Math.max(0, (line - block.line) / span));
  return block.top + fraction * block.height;
}

/** The source line shown at page position `y` (fractional), or null before the first block. */
export function lineAtOffset(blocks: readonly BlockBox[], y: number): number | null {
  let block: BlockBox | undefined;
  for (const b of blocks) if (b.top <= y) block = b;
  if (!block) return blocks.length ? blocks[0].line : null;
  const fraction = block.height > 0 ? Math.min(1, (y - block.top) / block.height) : 0;
  return block.line + fraction * (block.endLine + 1 - block.line);
}
