/** A truth an exercise is graded against (truths.ts lists them by name). */
export interface Truth {
  /** What the arguments are, in order of use: the declaration must give every one, a number. */
  readonly args: readonly string[];
  /** The value; NaN when the arguments describe no such quantity (an unbound motion, say). */
  compute(args: Readonly<Record<string, number>>): number;
  /** How it is computed and on whose authority, for the verdict. */
  readonly method: string;
}
