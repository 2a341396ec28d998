/**
 * Sweeps every chapter's theory checks across and beyond their formula's
 * regime, a handful of values each: inside, near the edge, and outside. At
 * each value the test edits the chapter's cell as a reader does and asserts
 * the verdict the page shows (✓ agrees, ✗ disagrees, outside the formula's
 * validity, or no verdict) against the verdict computed here from the
 * formula and an independent reference (sweep-physics.mjs: closed forms,
 * conservation laws, a period integral, classical RK4, never the page's own
 * numbers), by the rule of {@link expectedVerdict}. It also asserts that
 * the page's measurement lies within its own stated measurement and
 * integration errors of that reference, that the formula error it states is
 * the one the chapter's text derives, and that no NaN is shown.
 *
 * One chapter per `describe`, each on a fresh page; the points run in order
 * on that page, so each edit starts from the previous one.
 */
import assert from 'node:assert/strict';
import { describe, test } from 'node:test';
import { assertNoNaNShown, assertSumOfTerms, editAndReadChecks, useChapter } from './chapter-checks.mjs';
import {
  SMALL,
  adiabaticExcursion,
  adiabaticWobble,
  anharmonic,
  closestApproach,
  defaultModel,
  exactDeflection,
  expectedVerdict,
  firstOrderRegime,
  hyperbolic,
  keplerElements,
  lindstedt,
  mathieuFloquet,
  pendulum,
  rampChange,
  rk38,
  rk4,
  rutherford,
  suddenLimit,
  twoStars,
  windowedAmplitude,
} from './sweep-physics.mjs';

/**
 * Asserts a check's verdict against the one computed here. `expect` gives
 * the test's own judgement of the regime (`valid`), the truth for the
 * measured quantity (`reference`), the formula's value and its error as the
 * chapter derives them (`predicted`, `formula`), and `neither` when a value
 * may be missing instead of the regime failing (the page then gives no
 * verdict, with its reason), and `chaotic` when the motion is, so that the
 * page's measurement cannot be compared with another integration's. Returns
 * the verdict.
 */
function assertVerdict(check, { valid, reference, predicted, formula, relative = false, neither = false, chaotic = false }, where) {
  const about = `${where}: ${JSON.stringify({ verdict: check.verdict, reason: check.reason, measured: check.measured, predicted: check.predicted, error: check.error, tolerance: check.tolerance, formula: check.errorFormula, integration: check.errorIntegration, measurement: check.errorMeasurement })}`;
  if (!valid) {
    const allowed = neither ? ['outside', 'undefined'] : ['outside'];
    assert.ok(allowed.includes(check.verdict), `expected ${allowed.join(' or ')}; ${about}`);
    assert.ok(check.reason, `a check outside its validity says why; ${about}`);
    report(check, where);
    return check.verdict;
  }
  assertSumOfTerms(check);
  const scale = relative ? Math.abs(predicted) : 1;
  assert.ok(Math.abs(check.predicted - predicted) <= 1e-9 * Math.max(1, Math.abs(predicted)), `the formula's value, here ${predicted}; ${about}`);
  assert.ok(Math.abs(check.errorFormula - formula) <= 1e-9 * Math.max(formula, 1e-300) + 1e-300, `the formula's error, here ${formula}; ${about}`);
  // The page's measurement is within its own stated errors of the truth (not to be had for a chaotic
  // motion, where any two integrations part exponentially: the verdict must then be clear regardless).
  const slack = check.errorIntegration + check.errorMeasurement;
  if (!chaotic) assert.ok(Math.abs(check.measured - reference) / scale <= slack, `measured within ${slack} of the reference ${reference}; ${about}`);
  const expected = expectedVerdict({ valid, reference, predicted, formula, slack, relative });
  assert.notEqual(expected, 'ambiguous', `this point's verdict depends on where the measurement falls: choose another; ${about}`);
  assert.equal(check.verdict, expected, about);
  report(check, where);
  return check.verdict;
}

/** One line per point on the test's output: the sweep's range of each verdict, for the record. */
function report(check, where) {
  console.log(`sweep | ${check.text.split('\n')[0].slice(0, 60)} | ${where} | ${check.verdict}`);
}

/** The one theory check of a cell, after an edit, from editAndReadChecks' result. */
const only = (checks, id) => {
  assert.equal(checks[id].length, 1, `one check in ${id}`);
  return checks[id][0];
};

describe('introduction: the drive line (f, γ) and the order of RK 3/8 (dt)', () => {
  let page;
  useChapter('/introduction/', (opened) => ({ page } = opened));
  const base = { u: 0.3, gamma: 21.7, beta: 0.2, kappa: 8, omega: 10, f: 20 };
  const source = (p) => `params = (${JSON.stringify(p).replaceAll('"', '')})`;
  const CHECKS = ['driveCheck', 'orderCheck'];

  /**
   * The drive line's regime, judged here: a drive, a bounded free motion
   * (the Floquet trace by RK4), a stable step, and a forced line that stands
   * out from the free lines' leakage at κ/2π. The forced part is the
   * difference of two runs, with and without the force (the equation is
   * linear); its windowed amplitude at κ/2π is set against the free run's.
   * Returns 'valid', 'lost' (the page may say outside or give no verdict),
   * 'outside', or 'ambiguous'.
   */
  function driveRegime(p, dt = 5e-4) {
    if (p.f === 0) return 'outside';
    if (!mathieuFloquet(p).stable) return 'outside';
    if (p.omega * Math.sqrt(1 + p.u) * dt >= 2 * Math.sqrt(2)) return 'outside';
    const every = Math.max(1, Math.round(0.01 / dt));
    const sampled = (force) => {
      const q = [2];
      rk4(defaultModel({ ...p, f: force }), [2, 0], 0, dt, Math.round(40 / dt), (t, x) => {
        if (Math.round(t / dt) % every === 0) q.push(x[0]);
      });
      return q;
    };
    const forced = sampled(p.f);
    const free = sampled(0);
    const drive = windowedAmplitude(forced.map((v, i) => v - free[i]), every * dt, p.kappa / (2 * Math.PI));
    const floor = windowedAmplitude(free, every * dt, p.kappa / (2 * Math.PI));
    if (drive > 10 * floor) return 'valid';
    if (drive < floor / 10) return 'lost';
    return 'ambiguous';
  }

  const DRIVE = [
    { f: 500 }, // a strong drive
    { f: 20 }, // the paper's: inside
    { f: 2 }, // a weak drive, still resolved
    { f: 0.005 }, // lost among the free lines
    { f: 0 }, // no drive at all
    { f: 20, gamma: 21.3 }, // the free motion grows
  ];
  for (const point of DRIVE) {
    test(`drive line at ${JSON.stringify(point)}`, async () => {
      const p = { ...base, ...point };
      const checks = await editAndReadChecks(page, 'params', source(p), CHECKS);
      const regime = driveRegime(p);
      assert.notEqual(regime, 'ambiguous', 'choose another f');
      const kappa = p.kappa / (2 * Math.PI);
      // The forced response of a linear equation is exactly at κ (Landau & Lifshitz §22).
      assertVerdict(only(checks, 'driveCheck'), { valid: regime === 'valid', neither: regime === 'lost', reference: kappa, predicted: kappa, formula: 0 }, JSON.stringify(point));
      // No drive, no marker: the spectrum's dashed line and its comparison go with the premise.
      const marked = await page.locator('[data-cell="sim"] [data-widget="spectrum"] canvas[aria-label]').getAttribute('aria-label');
      assert.equal(/dashed line: drive κ\/2π/.test(marked ?? ''), p.f !== 0, `drive marker with f = ${p.f}: ${marked}`);
      await assertNoNaNShown(page);
    });
  }

  /**
   * The true error ratio of RK 3/8 when dt halves, computed here: the 3/8 rule
   * written out in sweep-physics.mjs, against a classical RK4 reference at
   * dt/16 (whose own error is (1/16)⁴ of the coarse one's, far below it).
   * The regime: ΩΔt ≤ 1/3 with Ω the fastest rate in H, and the fine run's
   * error at least three times the rounding floor, √N·2⁻⁵³ of the state.
   */
  function stepRatio(p, dt) {
    const steps = Math.max(1, Math.round(2 / dt));
    const rate = defaultModel(p);
    const end = (method, h, n) => method(rate, [2, 0], 0, h, n);
    const a = end(rk38, dt, steps);
    const b = end(rk38, dt / 2, 2 * steps);
    const ref = end(rk4, dt / 16, 16 * steps);
    const error = (x) => Math.hypot(x[0] - ref[0], (x[1] - ref[1]) / p.omega);
    const coarse = error(a);
    const size = Math.max(Math.abs(ref[0]), Math.abs(ref[1]) / p.omega);
    const floor = coarse / 8 ** 4 + 2 ** -53 * size * (Math.sqrt(2 * steps) + Math.sqrt(8 * steps));
    const fastest = Math.max(p.omega * Math.sqrt(1 + Math.abs(p.u)), Math.abs(p.gamma), Math.abs(p.kappa));
    return { ratio: coarse / error(b), valid: fastest * dt <= SMALL && coarse / 16 >= 3 * floor, formula: 8 * fastest * dt };
  }

  for (const dt of [0.01, 5e-4, 0.05, 1e-4]) {
    test(`RK 3/8 order at dt = ${dt}`, async () => {
      if (dt === 0.01) await editAndReadChecks(page, 'params', source(base), CHECKS);
      const checks = await editAndReadChecks(page, 'dt', `dt = ${dt}`, CHECKS);
      const truth = stepRatio(base, dt);
      assertVerdict(only(checks, 'orderCheck'), { valid: truth.valid, reference: truth.ratio, predicted: 16, formula: truth.formula }, `dt = ${dt}`);
      await assertNoNaNShown(page);
    });
  }
});

describe('parametric resonance: the growth rate against the first-order formula and the Floquet multiplier (u)', () => {
  let page;
  useChapter('/parametric-resonance/', (opened) => ({ page } = opened));
  // γ = 21.3 throughout: u = 0.26 puts it on the band's edge, which the sweep crosses.
  for (const u of [0.5, 0.3, 0.1, 0.25, 0.27, 0.265, 1.2]) {
    test(`u = ${u}, γ = 21.3`, async () => {
      const p = { u, gamma: 21.3, omega: 10 };
      const checks = await editAndReadChecks(page, 'params', `params = ({u: ${u}, gamma: 21.3, beta: 0.2, kappa: 8, omega: 10, f: 0})`, ['formulaCheck', 'floquetCheck']);
      const regime = firstOrderRegime(p);
      const exact = mathieuFloquet(p);
      // The first-order formula of Landau & Lifshitz §27, judged against the exact Floquet rate.
      assertVerdict(only(checks, 'formulaCheck'), { valid: regime.valid, reference: exact.growth, predicted: regime.s, formula: regime.neglected }, `u = ${u}`);
      // The Floquet rate is exact; the fit measures it while the decaying solution has faded to a third.
      assert.ok(exact.stable || Math.abs(exact.decaying - SMALL) > 0.05, `ρ = ${exact.decaying} is too near 1/3: choose another u`);
      assertVerdict(only(checks, 'floquetCheck'), { valid: !exact.stable && exact.decaying <= SMALL, reference: exact.growth, predicted: exact.growth, formula: 0 }, `u = ${u}`);
      await assertNoNaNShown(page);
    });
  }
});

describe('nonlinear oscillator: the frequency against Lindstedt’s series, and the spectral peak against the crossings (b)', () => {
  let page;
  useChapter('/nonlinear-oscillator/', (opened) => ({ page } = opened));
  const PARAMS = { omega0: 10, alpha: -2, beta: -3 };
  for (const b of [0.1, 1, 2, 2.4, -1.9, 2.7]) {
    test(`b = ${b}`, async () => {
      const checks = await editAndReadChecks(page, 'b', `b = ${b}`, ['frequencyCheck', 'peakCheck']);
      const exact = anharmonic(PARAMS, b);
      const series = lindstedt(PARAMS, b);
      // Small amplitude: the terms the series leaves out at most a third of the correction it keeps.
      const valid = exact.bound && series.neglected <= series.kept * SMALL;
      assertVerdict(only(checks, 'frequencyCheck'), { valid, reference: exact.omega, predicted: series.omega, formula: series.neglected }, `b = ${b}`);
      // Two measurements of one frequency: each within its own error of the exact one, so they agree.
      const pair = only(checks, 'peakCheck');
      if (!exact.bound) {
        assert.ok(['outside', 'undefined'].includes(pair.verdict), JSON.stringify(pair));
      } else {
        assert.equal(pair.verdict, 'agrees', JSON.stringify(pair));
        const apart = (Math.abs(pair.measured - exact.omega) + Math.abs(pair.predicted - exact.omega)) / pair.predicted;
        assert.ok(apart <= pair.errorMeasurement, `peak and crossings ${apart} from the exact frequency, allowed ${pair.errorMeasurement}`);
      }
      await assertNoNaNShown(page);
    });
  }
});

describe('Kepler: the period, L and the direction of A (k, and a broken symmetry)', () => {
  let page;
  useChapter('/kepler/', (opened) => ({ page } = opened));
  const START = [-3, -3, 3, 3, 2, -3, -2, 3];
  const KEPLER = 'H = (t, [x1, y1, x2, y2, px1, py1, px2, py2]) => px1**2 + py1**2 + px2**2 + py2**2 - k / hypot(x1 - x2, y1 - y2)';
  const POINTS = [
    { k: 2000 }, // tight and eccentric: τp = 0.008, the integrator's error large but resolved
    { k: 400 },
    { k: 200 }, // unbound
    { k: 5000 }, // the step no longer resolves the pericentre
    { k: 500, c: 1.5 }, // the paper's broken symmetry: L and A are no longer conserved
  ];
  for (const point of POINTS) {
    test(`k = ${point.k}${point.c ? `, ${point.c}·x1 − x2` : ''}`, async () => {
      if (point.c) await editAndReadChecks(page, 'k', `k = ${point.k}`, ['keplerChecks']);
      const [cellId, text] = point.c ? ['H', KEPLER.replace('x1 - x2', `${point.c} * x1 - x2`)] : ['k', `k = ${point.k}`];
      const checks = await editAndReadChecks(page, cellId, text, ['keplerChecks']);
      const [period, momentum, lenz] = checks.keplerChecks;
      const orbit = keplerElements(START, point.k);
      const valid = orbit.E < 0 && orbit.T < 15 && 5e-4 <= orbit.tauP / 3;
      const chaotic = point.c !== undefined;
      // Kepler's third law (Landau & Lifshitz §15) and the conservation of L and A: exact, formula error 0,
      // so the closed form is the truth. With the symmetry broken, the truth is an integration of the
      // perturbed problem (RK4 in sweep-physics.mjs), far from the closed form.
      const truth = !valid ? {} : chaotic ? twoStars({ k: point.k, c: point.c }, START, 4.2 * orbit.T) : { period: orbit.T, L: orbit.L, angle: orbit.angle };
      const where = JSON.stringify(point);
      assertVerdict(period, { valid, reference: truth.period, predicted: orbit.T, formula: 0, relative: true, chaotic }, where);
      assertVerdict(momentum, { valid, reference: truth.L, predicted: orbit.L, formula: 0, relative: true, chaotic }, where);
      assertVerdict(lenz, { valid, reference: truth.angle, predicted: orbit.angle, formula: 0, chaotic }, where);
      if (point.c) for (const check of [period, momentum, lenz]) assert.equal(check.verdict, 'disagrees', 'the broken symmetry fails every check');
      await assertNoNaNShown(page);
    });
  }
});

describe('adiabatic invariants: the slow ramp (ε) and the fast one (τ)', () => {
  let page;
  useChapter('/adiabatic-invariants/', (opened) => ({ page } = opened));
  for (const epsilon of [0.01, 0.5, 1, -0.1]) {
    test(`slow ramp, ε = ${epsilon}`, async () => {
      const checks = await editAndReadChecks(page, 'params', `params = ({omega0: 4, epsilon: ${epsilon}})`, ['slowCheck']);
      const ramp = { omega0: 4, epsilon };
      const wobble = adiabaticWobble(ramp, [1, 0]);
      const valid = wobble.positive && wobble.neglected <= SMALL;
      const reference = valid ? adiabaticExcursion(ramp, [1, 0]) : NaN;
      assertVerdict(only(checks, 'slowCheck'), { valid, reference, predicted: wobble.predicted, formula: wobble.neglected, relative: true }, `ε = ${epsilon}`);
      await assertNoNaNShown(page);
    });
  }
  for (const tau of [0.01, 0.1, 0.2, 1, 5]) {
    test(`fast ramp from 4 to 8, τ = ${tau}`, async () => {
      const ramp = { omega0: 4, omega1: 8, t1: 3, T_r: tau };
      const checks = await editAndReadChecks(page, 'ramp', `ramp = ({omega0: 4, omega1: 8, t1: 3, T_r: ${tau}})`, ['fastCheck']);
      const { sudden, neglected } = suddenLimit(ramp);
      assertVerdict(only(checks, 'fastCheck'), { valid: neglected <= sudden * SMALL, reference: rampChange(ramp), predicted: sudden, formula: neglected }, `τ = ${tau}`);
      await assertNoNaNShown(page);
    });
  }
});

describe('scattering: the deflection against the exact orbit and against Rutherford (impact, α)', () => {
  let page;
  useChapter('/scattering/', (opened) => ({ page } = opened));
  const [X0, P0, MASS] = [-20, 4, 0.5];
  const POINTS = [
    { impact: 0.3 },
    { impact: 5 },
    { impact: 10 }, // the start is no longer far from the axis for Rutherford
    { impact: 40 },
    { impact: 0 }, // head on: turned straight back
    { impact: 1.5, alpha: 300 }, // a strong field: the start holds too much potential energy
    { impact: 40, alpha: -30 }, // attractive, far out: the straight-line tail is longest here
    { impact: 0.15, alpha: -30 }, // attractive, aimed close: the step cannot follow the passage
  ];
  const CHECKS = ['orbitCheck', 'rutherfordCheck'];
  let field = 30;
  for (const point of POINTS) {
    test(`impact = ${point.impact}, α = ${point.alpha ?? 30}`, async () => {
      const alpha = point.alpha ?? 30;
      if (alpha !== field) {
        await editAndReadChecks(page, 'params', `params = ({alpha: ${alpha}})`, CHECKS);
        field = alpha;
      }
      const checks = await editAndReadChecks(page, 'impact', `impact = ${point.impact}`, CHECKS);
      const b = point.impact;
      const { E, tau } = closestApproach(X0, b, P0, alpha, MASS);
      const resolved = E > 0 && 2e-3 <= tau / 3;
      const exact = exactDeflection(X0, b, P0, 0, alpha, MASS);
      const where = JSON.stringify(point);
      // The Laplace–Runge–Lenz orbit from the actual start (Goldstein §3.9): exact.
      assertVerdict(only(checks, 'orbitCheck'), { valid: resolved, reference: exact, predicted: exact, formula: 0 }, where);
      // Rutherford (Landau & Lifshitz §19), from infinity with E0 = p0²/2m: the start must be far.
      const E0 = (P0 * P0) / (2 * MASS);
      const r0 = Math.hypot(X0, b);
      const held = Math.abs(alpha) / (r0 * E0);
      const aside = Math.abs(b / X0);
      const thetaR = rutherford(b, E0, alpha);
      const shortfall = (Math.sin(thetaR) / 2) * Math.log(1 + alpha / (r0 * E0)) + (Math.abs(alpha) * Math.abs(b)) / (4 * X0 * X0 * E0);
      assertVerdict(
        only(checks, 'rutherfordCheck'),
        { valid: resolved && held <= SMALL && aside <= SMALL, reference: exact, predicted: thetaR, formula: Math.abs(shortfall) * (1 + held + aside) },
        where,
      );
      await assertNoNaNShown(page);
    });
  }
});

describe('special relativity: the position and the largest speed against the closed form (F)', () => {
  let page;
  useChapter('/special-relativity/', (opened) => ({ page } = opened));
  const M = Math.sqrt(10);
  for (const F of [0, 0.8, 20, 2000]) {
    test(`F = ${F}`, async () => {
      const checks = await editAndReadChecks(page, 'params', `params = ({m: sqrt(10), F: ${F}})`, ['positionCheck', 'speedCheck']);
      const position = only(checks, 'positionCheck');
      // The check compares at the moment of the largest difference, which it names (to the step, 1e-3).
      const at = Number(/at t = ([\d.]+)/.exec(position.text)?.[1]);
      const q = hyperbolic({ m: M, F }, [-10, -10], at).q;
      // Hyperbolic motion (Landau & Lifshitz, Fields §20) is exact; the step must resolve the turn, m/F.
      assertVerdict(position, { valid: F === 0 || 1e-3 <= M / F / 3, reference: q, predicted: q, formula: 0 }, `F = ${F}`);
      const fastest = Math.max(...[0, 40].map((t) => Math.abs(hyperbolic({ m: M, F }, [-10, -10], t).v)));
      assertVerdict(only(checks, 'speedCheck'), { valid: true, reference: fastest, predicted: fastest, formula: 0 }, `F = ${F}`);
      await assertNoNaNShown(page);
    });
  }
});

describe('the chapter template (for teachers): the pendulum’s period against the series to θ0² (the start)', () => {
  let page;
  useChapter('/for-teachers/', (opened) => ({ page } = opened));
  for (const start of [[0.1, 0], [1.5, 0], [0, 1], [2.5, 0], [3.1, 0], [0, 4.2]]) {
    test(`start ${JSON.stringify(start)}`, async () => {
      const checks = await editAndReadChecks(page, 'pendulumStart', `pendulumStart = ${JSON.stringify(start).replace(',', ', ')}`, ['periodCheck']);
      const swing = pendulum(2, start);
      // The exact period 4K(sin θ0/2)/ω0 (Landau & Lifshitz §11), by the AGM.
      assertVerdict(only(checks, 'periodCheck'), { valid: swing.valid, reference: swing.exact, predicted: swing.predicted, formula: swing.neglected, relative: true }, JSON.stringify(start));
      await assertNoNaNShown(page);
    });
  }
});
