/**
 * The classical fourth-order Runge–Kutta step, written out here so that the
 * truths' tests check them against an integration that shares no code with
 * the book's own integrator (RK 3/8, core/).
 */
export type Field = (t: number, x: readonly number[]) => number[];

export function rk4Step(f: Field, t: number, x: readonly number[], dt: number): number[] {
  const shifted = (k: readonly number[], h: number) => x.map((v, i) => v + h * k[i]);
  const k1 = f(t, x);
  const k2 = f(t + dt / 2, shifted(k1, dt / 2));
  const k3 = f(t + dt / 2, shifted(k2, dt / 2));
  const k4 = f(t + dt, shifted(k3, dt));
  return x.map((v, i) => v + (dt / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
}

/** Integrates from (t0, x0) in steps of dt until `stop` holds of the state just reached (or `limit` steps); returns the last two states and times. */
export function integrateUntil(f: Field, t0: number, x0: readonly number[], dt: number, stop: (x: readonly number[], t: number) => boolean, limit = 1e7) {
  let [t, x, before] = [t0, [...x0], [...x0]];
  for (let k = 0; k < limit && !(k > 0 && stop(x, t)); k++) {
    before = x;
    x = rk4Step(f, t, x, dt);
    t += dt;
  }
  return { t, x, before };
}
