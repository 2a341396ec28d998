/**
 * Memory budgets for trajectory records. Widgets size their records from a
 * byte budget rather than a row count because the row width (state plus
 * derived series) varies by model, and they report the budget in a note.
 */

const BYTES_PER_VALUE = Float64Array.BYTES_PER_ELEMENT;

/**
 * The largest capacity, in rows, whose storage fits in `bytes`. Never less
 * than 1, so a tiny budget still yields a usable record.
 */
export function capacityFor(bytes: number, width: number): number {
  if (!Number.isInteger(width) || width < 1) {
    throw new Error(`capacityFor: width must be a positive integer, got ${width}`);
  }
  if (!(Number.isFinite(bytes) && bytes >= 0)) throw new Error(`capacityFor: bytes must be a finite non-negative number, got ${bytes}`);
  return Math.max(1, Math.floor(bytes / (width * BYTES_PER_VALUE)));
}

/** Bytes of sample storage a record of this shape holds. */
export function bytesFor(capacity: number, width: number): number {
  return capacity * width * BYTES_PER_VALUE;
}
