"""
The scipy side of `npm run bench`'s dataset benchmark: the pendulum
H = p^2/2 - cos q from the initial states in INITIAL.csv (q,p), sampled at
t = 0, 0.1, ..., T, by scipy.integrate.solve_ivp.

  pendulum_scipy.py MODE INITIAL.csv T SAMPLES RTOL OUT.npy [COUNT]

MODE: 'each' solves one trajectory per call (DOP853), as a researcher loops;
'batch' solves the whole set as one vectorised system (DOP853); 'reference'
is DOP853 per trajectory at RTOL with atol 1e-15, the accuracy yardstick.
COUNT limits the trajectories (the per-trajectory mode is slow). Writes the
states, shape (M, SAMPLES, 2), and prints the seconds spent integrating:
wall-clock, then CPU (this process's), on one line.
"""
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp


def field(t, x):
    # x is (2,) or, for a batch, (2M,) laid out as all q then all p.
    n = x.shape[0] // 2
    return np.concatenate([x[n:], -np.sin(x[:n])])


def main():
    mode, initial_file, t_end, samples, rtol, out = sys.argv[1:7]
    count = int(sys.argv[7]) if len(sys.argv) > 7 else None
    x0 = np.loadtxt(initial_file, delimiter=',', skiprows=1, ndmin=2)
    if count is not None:
        x0 = x0[:count]
    t_end, samples, rtol = float(t_end), int(samples), float(rtol)
    t_eval = np.linspace(0.0, t_end, samples)
    atol = 1e-15 if mode == 'reference' else rtol * 1e-3
    start = time.perf_counter()
    start_cpu = time.process_time()
    if mode == 'batch':
        m = x0.shape[0]
        y0 = np.concatenate([x0[:, 0], x0[:, 1]])
        sol = solve_ivp(field, (0.0, t_end), y0, method='DOP853', t_eval=t_eval, rtol=rtol, atol=atol)
        states = np.stack([sol.y[:m], sol.y[m:]], axis=-1)
    else:
        states = np.empty((x0.shape[0], samples, 2))
        for j, y0 in enumerate(x0):
            sol = solve_ivp(field, (0.0, t_end), y0, method='DOP853', t_eval=t_eval, rtol=rtol, atol=atol)
            states[j] = sol.y.T
    seconds = time.perf_counter() - start
    cpu = time.process_time() - start_cpu
    np.save(out, states)
    print(seconds, cpu)


if __name__ == '__main__':
    main()
