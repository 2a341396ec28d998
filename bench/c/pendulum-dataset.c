/*
 * The yardstick for `phasebook simulate` over many initial conditions: a
 * dataset of pendulum trajectories (H = p²/2 − cos q) by the classical
 * Runge–Kutta 3/8 rule at a fixed step, one trajectory after another, the
 * rows written as CSV with %.17g (trajectory, t, q, p, H), as a researcher
 * would write it in C. Compiled by bench/datasets.ts with gcc -O2.
 *
 *   pendulum-dataset INITIAL.csv STEPS DT EVERY  →  CSV on stdout
 *
 * INITIAL.csv holds "q,p" and a row per trajectory. Step k starts at
 * t = k·dt, computed rather than accumulated, as the CLI does.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static void field(const double *x, double *dxdt) {
    dxdt[0] = x[1];
    dxdt[1] = -sin(x[0]);
}

/* One RK 3/8 step (Hairer, Nørsett & Wanner, Solving ODEs I, table 1.2 of II.1). */
static void step(double h, double *x) {
    double k1[2], k2[2], k3[2], k4[2], y[2];
    field(x, k1);
    for (int i = 0; i < 2; i++) y[i] = x[i] + h * k1[i] / 3;
    field(y, k2);
    for (int i = 0; i < 2; i++) y[i] = x[i] + h * (k2[i] - k1[i] / 3);
    field(y, k3);
    for (int i = 0; i < 2; i++) y[i] = x[i] + h * (k1[i] - k2[i] + k3[i]);
    field(y, k4);
    for (int i = 0; i < 2; i++) x[i] += h * (k1[i] + 3 * (k2[i] + k3[i]) + k4[i]) / 8;
}

int main(int argc, char **argv) {
    if (argc != 5) {
        fprintf(stderr, "usage: pendulum-dataset INITIAL.csv STEPS DT EVERY\n");
        return 2;
    }
    FILE *in = fopen(argv[1], "r");
    if (!in) {
        perror(argv[1]);
        return 2;
    }
    long steps = atol(argv[2]), every = atol(argv[4]);
    double dt = atof(argv[3]);
    char header[256];
    if (!fgets(header, sizeof header, in)) return 2;
    double x[2];
    static char buffer[1 << 16];
    setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
    printf("trajectory,t,q,p,H\n");
    for (long j = 0; fscanf(in, "%lf,%lf", &x[0], &x[1]) == 2; j++) {
        for (long k = 0; k <= steps; k++) {
            if (k % every == 0) printf("%ld,%.17g,%.17g,%.17g,%.17g\n", j, k * dt, x[0], x[1], x[1] * x[1] / 2 - cos(x[0]));
            if (k < steps) step(dt, x);
        }
    }
    fclose(in);
    return 0;
}
