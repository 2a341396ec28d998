/**
 * A plain, straightforward implementation of the paper's algorithm, as its
 * section 3 describes it: ordinary arrays, new arrays every step, and
 * canonicalEquation(dof, H) taking the gradient by a 2-point central
 * difference with a fixed h = 1e-6. The baseline the benchmark compares with.
 */
export type PlainHamiltonian = (t: number, x: number[]) => number;

export function canonicalEquation(dof: number, H: PlainHamiltonian) {
  const h = 1e-6;
  return (t: number, x: number[]): number[] => {
    const gradient = x.map((_, i) => {
      const plus = x.slice();
      const minus = x.slice();
      plus[i] += h;
      minus[i] -= h;
      return (H(t, plus) - H(t, minus)) / (2 * h);
    });
    return x.map((_, i) => (i < dof ? gradient[i + dof] : -gradient[i - dof]));
  };
}

export function plainRk38(f: (t: number, x: number[]) => number[], x0: number[], dt: number, steps: number): number[] {
  let x = x0.slice();
  for (let k = 0; k < steps; k++) {
    const t = k * dt;
    const k1 = f(t, x);
    const k2 = f(t + dt / 3, x.map((v, i) => v + (dt * k1[i]) / 3));
    const k3 = f(t + (2 * dt) / 3, x.map((v, i) => v + dt * (k2[i] - k1[i] / 3)));
    const k4 = f(t + dt, x.map((v, i) => v + dt * (k1[i] - k2[i] + k3[i])));
    x = x.map((v, i) => v + (dt * (k1[i] + 3 * k2[i] + 3 * k3[i] + k4[i])) / 8);
  }
  return x;
}
