/*
 * The yardstick for `phasebook simulate`: the classical Runge–Kutta 3/8 rule
 * at a fixed step, with the analytic vector field of each benchmark model
 * written by hand. Compiled by bench/cli.ts with gcc -O2 at bench time.
 *
 *   rk38 default|kepler STEPS DT  →  the final state, one %.17g per value
 *
 * Step k starts at t = k·dt, computed rather than accumulated, as the CLI does.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_DIM 8

/*
 * The paper's default model, eq. 7:
 *   H = p²/2 + ω²(1 + u cos γt) q²/2 − f q cos(κt + β)
 *   q̇ = p,  ṗ = −ω²(1 + u cos γt) q + f cos(κt + β)
 */
static void default_model(double t, const double *x, double *dxdt) {
    const double u = 0.3, gamma = 21.7, beta = 0.2, kappa = 8, omega = 10, f = 20;
    dxdt[0] = x[1];
    dxdt[1] = -omega * omega * (1 + u * cos(gamma * t)) * x[0] + f * cos(kappa * t + beta);
}

/*
 * Paper 7.1, two bodies: H = Σ p² − k/|r1 − r2| with k = 500, state
 * (x1, y1, x2, y2, px1, py1, px2, py2):
 *   q̇ = 2p,  ṗ1 = −k (r1 − r2)/|r1 − r2|³ = −ṗ2
 */
static void kepler(double t, const double *x, double *dxdt) {
    (void)t;
    const double k = 500;
    double dx = x[0] - x[2], dy = x[1] - x[3];
    double r2 = dx * dx + dy * dy;
    double s = k / (r2 * sqrt(r2));
    for (int i = 0; i < 4; i++) dxdt[i] = 2 * x[4 + i];
    dxdt[4] = -s * dx;
    dxdt[5] = -s * dy;
    dxdt[6] = s * dx;
    dxdt[7] = s * dy;
}

typedef void (*field_t)(double, const double *, double *);

/* One RK 3/8 step (Hairer, Nørsett & Wanner, Solving ODEs I, table 1.2 of II.1). */
static inline void step(field_t f, int n, double t, double h, double *x) {
    double k1[MAX_DIM], k2[MAX_DIM], k3[MAX_DIM], k4[MAX_DIM], y[MAX_DIM];
    f(t, x, k1);
    for (int i = 0; i < n; i++) y[i] = x[i] + h * k1[i] / 3;
    f(t + h / 3, y, k2);
    for (int i = 0; i < n; i++) y[i] = x[i] + h * (k2[i] - k1[i] / 3);
    f(t + 2 * h / 3, y, k3);
    for (int i = 0; i < n; i++) y[i] = x[i] + h * (k1[i] - k2[i] + k3[i]);
    f(t + h, y, k4);
    for (int i = 0; i < n; i++) x[i] += h * (k1[i] + 3 * (k2[i] + k3[i]) + k4[i]) / 8;
}

int main(int argc, char **argv) {
    if (argc != 4) {
        fprintf(stderr, "usage: rk38 default|kepler STEPS DT\n");
        return 2;
    }
    long steps = atol(argv[2]);
    double dt = atof(argv[3]);
    double x[MAX_DIM];
    int n;
    if (strcmp(argv[1], "default") == 0) {
        n = 2;
        x[0] = 2, x[1] = 0;
        for (long k = 0; k < steps; k++) step(default_model, n, k * dt, dt, x);
    } else if (strcmp(argv[1], "kepler") == 0) {
        const double start[8] = {-3, -3, 3, 3, 2, -3, -2, 3};
        n = 8;
        memcpy(x, start, sizeof start);
        for (long k = 0; k < steps; k++) step(kepler, n, k * dt, dt, x);
    } else {
        fprintf(stderr, "rk38: unknown model %s\n", argv[1]);
        return 2;
    }
    for (int i = 0; i < n; i++) printf(i ? " %.17g" : "%.17g", x[i]);
    printf("\n");
    return 0;
}
