/**
 * A problem with what the user gave (an H that does not parse, an unknown
 * name, a wrong number of values). Its message is one line meant for the
 * user, so callers show it as it is, with no stack trace.
 */
export class InputError extends Error {
  override name = 'InputError';
}

/**
 * The state stopped being finite: two Kepler bodies met, or dt is too large
 * for the motion. Says when and in which component it happened.
 */
export class BlowUpError extends Error {
  override name = 'BlowUpError';
  constructor(
    readonly t: number,
    readonly component: string,
    readonly value: number,
    /** the trajectory's index within a batch, when there is a batch */
    readonly trajectory?: number,
  ) {
    const which = trajectory !== undefined ? ` of trajectory ${trajectory}` : '';
    super(`the state became ${value} at t = ${t} in ${component}${which}; the motion is singular there or dt is too large`);
  }
}
