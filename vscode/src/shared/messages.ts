/**
 * The messages between the extension (host) and a chapter's preview
 * webview. Lines count from 0, as in VS Code; a cell is named by the id the
 * page gives it (its name, `name-dupN` or `cell-N`).
 */

/**
 * A theory check's verdict (widgets/chapter/theory-check/check-verdict.ts): `outside` when the formula's regime
 * does not hold, `undefined` when a value is missing.
 */
export type CheckVerdict = 'agrees' | 'disagrees' | 'outside' | 'undefined';

/** A theory check's readout, as widgets/chapter/theory-check/theory-check.ts writes it on its element; a missing number is NaN. */
export interface TheoryCheckReading {
  readonly label: string;
  readonly measured: number;
  readonly predicted: number;
  /** The error allowed (the sum of the terms the check allows). */
  readonly tolerance: number;
  readonly relative: boolean;
  /** The difference as compared (relative to the prediction for a relative check). */
  readonly error: number;
  readonly verdict: CheckVerdict;
  /** Why there is no verdict, or which condition of the formula's regime fails. */
  readonly reason: string;
  /** The readout's own lines: Simulation …, Theory …, Difference … */
  readonly text: string;
}

export interface CheckResult {
  readonly id: string;
  /** `timeout`: the cell had not settled in time. */
  readonly state: 'fulfilled' | 'rejected' | 'timeout' | 'missing';
  readonly error?: string;
  readonly checks: readonly TheoryCheckReading[];
}

export interface CellReport {
  readonly id: string;
  readonly line: number;
  readonly endLine: number;
  readonly state: 'waiting' | 'pending' | 'fulfilled' | 'rejected';
  /** The cell's own runtime error (not one that came through an input), as the page shows it. */
  readonly error?: string;
}

export type HostMessage =
  | { readonly type: 'render'; readonly version: number; readonly text: string }
  /** Runs one cell again (by id), or all of them (null). */
  | { readonly type: 'run'; readonly cell: string | null }
  | { readonly type: 'reveal'; readonly line: number }
  | { readonly type: 'checks'; readonly request: number; readonly cells: readonly string[]; readonly timeoutMs: number };

export type PreviewMessage =
  | { readonly type: 'ready' }
  | {
      readonly type: 'rendered';
      readonly version: number;
      /** Cells whose element (and widget) was kept, created, or redefined with new source. */
      readonly kept: readonly string[];
      readonly created: readonly string[];
      readonly changed: readonly string[];
      readonly removed: readonly string[];
    }
  | { readonly type: 'cells'; readonly version: number; readonly cells: readonly CellReport[] }
  | { readonly type: 'scrolled'; readonly line: number }
  | { readonly type: 'open'; readonly line: number }
  | { readonly type: 'checks'; readonly request: number; readonly results: readonly CheckResult[] };
