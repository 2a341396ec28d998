/**
 * Solves A·x = b in place by Gaussian elimination with partial pivoting
 * (Golub & Van Loan, *Matrix Computations*, §3.4): A is n×n, row-major, and
 * is overwritten by its factors; b becomes x. Returns false when a pivot is
 * zero or not finite (A singular, or not a matrix of numbers).
 */
export function solveInPlace(a: Float64Array, b: Float64Array, n: number): boolean {
  for (let col = 0; col < n; col++) {
    let pivot = col;
    let largest = Math.abs(a[col * n + col]);
    for (let r = col + 1; r < n; r++) {
      const v = Math.abs(a[r * n + col]);
      if (v > largest) {
        largest = v;
        pivot = r;
      }
    }
    if (!(largest > 0) || !Number.isFinite(largest)) return false;
    if (pivot !== col) {
      for (let j = col; j < n; j++) {
        const tmp = a[col * n + j];
        a[col * n + j] = a[pivot * n + j];
        a[pivot * n + j] = tmp;
      }
      const tb = b[col];
      b[col] = b[pivot];
      b[pivot] = tb;
    }
    const d = a[col * n + col];
    for (let r = col + 1; r < n; r++) {
      const factor = a[r * n + col] / d;
      if (factor === 0) continue;
      for (let j = col + 1; j < n; j++) a[r * n + j] -= factor * a[col * n + j];
      b[r] -= factor * b[col];
    }
  }
  for (let r = n - 1; r >= 0; r--) {
    let s = b[r];
    for (let j = r + 1; j < n; j++) s -= a[r * n + j] * b[j];
    b[r] = s / a[r * n + r];
  }
  return true;
}
