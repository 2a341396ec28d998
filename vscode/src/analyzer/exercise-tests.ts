/**
 * An exercise's declaration as a test: does its answer key teach what it
 * says? The reference answer must pass and every wrong answer it lists must
 * fail, graded and checked by the book's own code (computeTruth,
 * gradeNumber, runCheck: the modules the exercise widget grades with), so a
 * truth or a check the book adds is run here as the page runs it. Pure but
 * for the model compiler, which runs the H's the declaration lists
 * (JavaScript among them): the host asks for a trusted workspace first.
 *
 * - a number (predict, find): the truth is a finite number and passes; it
 *   lists two wrong answers or more, and each lies beyond the tolerance
 *   (else the page would call it right) and is graded wrong with its own
 *   explanation;
 * - code: the reference H passes every check, and every listed wrong H
 *   fails at least one.
 */
import { canonicalEquations, type Model } from '../../../core/index.ts';
import type { Exercise } from '../../../widgets/index.ts';
import type { ChapterExercise } from './exercises.ts';

/**
 * The book's grading, the modules the page's exercise widget grades with,
 * loaded when an exercise first runs, as the page loads them. Imported
 * lazily, not through the widgets' front door: a static export there would
 * put them, and the truths' analysis, into every page's first chunk.
 */
async function loadGrading() {
  const [grade, checks, truths] = await Promise.all([
    import('../../../widgets/chapter/exercise/grade.ts'),
    import('../../../widgets/chapter/exercise/code-checks.ts'),
    import('../../../widgets/chapter/exercise/truths.ts'),
  ]);
  return { allowance: grade.allowance, gradeNumber: grade.gradeNumber, runCheck: checks.runCheck, computeTruth: truths.computeTruth };
}

type Grading = Awaited<ReturnType<typeof loadGrading>>;

/** A finding against the declaration, and the answer it is about (as the declaration writes it) to point at. */
export interface ExerciseFailure {
  readonly message: string;
  /** A string of the declaration: a wrong H, a mistake's explanation, the reference H or the truth's name. */
  readonly about?: string;
}

export interface ExerciseVerdict {
  readonly outcome: 'passed' | 'failed';
  /** What was checked and what came of it, a line per answer. */
  readonly report: readonly string[];
  readonly failures: readonly ExerciseFailure[];
}

/** The book asks every exercise for this many plausible wrong answers (issue 22's tests, and the book's own unit test). */
export const LEAST_MISTAKES = 2;

const digits = (x: number) => Number(x.toPrecision(6)).toString();
const said = (error: unknown) => (error instanceof Error ? error.message : String(error));
const checkName = (check: unknown, i: number) => `check ${i + 1} (${String((check as { check?: unknown }).check)})`;

function verdict(report: string[], failures: ExerciseFailure[]): ExerciseVerdict {
  return { outcome: failures.length ? 'failed' : 'passed', report, failures };
}

function fewMistakes(count: number, what: string): ExerciseFailure | null {
  if (count >= LEAST_MISTAKES) return null;
  return { message: `The exercise lists ${count} wrong ${what}${count === 1 ? '' : 's'}: give ${LEAST_MISTAKES} or more plausible ones (a factor of 2, a wrong sign, a formula outside its validity), so that the tests show the grading tells them from the truth.` };
}

function testNumber(exercise: Exercise, { allowance, computeTruth, gradeNumber }: Grading): ExerciseVerdict {
  const answer = exercise.answer!;
  const unit = exercise.unit ? ` ${exercise.unit}` : '';
  const { name, args } = answer.truth;
  const truth = computeTruth(name, args);
  if ('error' in truth) return verdict([], [{ message: `The truth cannot be computed: ${truth.error}.`, about: name }]);
  if (!Number.isFinite(truth.value)) {
    return verdict([], [{ message: `The truth ${name}(${JSON.stringify(args)}) is ${truth.value}, not a number: its arguments describe no such quantity.`, about: name }]);
  }
  const report: string[] = [];
  const failures: ExerciseFailure[] = [];
  const allowed = allowance(truth.value, answer.tolerance);
  const right = gradeNumber(truth.value, truth.value, answer.tolerance, answer.mistakes, exercise.unit);
  report.push(`The truth, ${digits(truth.value)}${unit} ± ${digits(allowed)} (${truth.method}): ${right.passed ? 'graded right' : 'graded WRONG'}.`);
  if (!right.passed) failures.push({ message: `The truth itself is graded wrong: ${right.message}`, about: name });
  const few = fewMistakes(answer.mistakes.length, 'answer');
  if (few) failures.push(few);
  for (const mistake of answer.mistakes) {
    const value = `${digits(mistake.value)}${unit}`;
    if (Math.abs(mistake.value - truth.value) <= allowed) {
      report.push(`Wrong answer ${value}: inside the tolerance, graded right.`);
      failures.push({
        message: `The wrong answer ${value} is within the tolerance of the truth ${digits(truth.value)}${unit} (± ${digits(allowed)}): the page would call it right. Tighten the tolerance, or drop this mistake.`,
        about: mistake.why,
      });
      continue;
    }
    const graded = gradeNumber(mistake.value, truth.value, answer.tolerance, answer.mistakes, exercise.unit);
    report.push(`Wrong answer ${value}: ${graded.passed ? 'graded right' : 'graded wrong'}: ${graded.message}`);
    if (graded.passed) failures.push({ message: `The wrong answer ${value} is graded right: ${graded.message}`, about: mistake.why });
    else if (!graded.message.includes(mistake.why)) {
      failures.push({
        message: `The wrong answer ${value} is graded wrong, but without its own explanation (another mistake lies within the tolerance of it): the page says “${graded.message}”`,
        about: mistake.why,
      });
    }
  }
  return verdict(report, failures);
}

async function testCode(exercise: Exercise, { runCheck }: Grading): Promise<ExerciseVerdict> {
  const code = exercise.code!;
  const build = (hamiltonian: string) => canonicalEquations({ dof: code.dof, hamiltonian, params: code.params });
  let reference: Model;
  try {
    reference = await build(code.reference);
  } catch (error) {
    return verdict([], [{ message: `The reference H “${code.reference}” cannot be turned into Hamilton’s equations: ${said(error)}`, about: code.reference }]);
  }
  const report: string[] = [];
  const failures: ExerciseFailure[] = [];
  /** Each check's verdict on `reader`, a throw counted as a failure, as the page counts it. */
  const judge = (reader: Model) =>
    code.checks.map((check, i) => {
      try {
        return { name: checkName(check, i), ...runCheck(check, reader, reference, i + 1) };
      } catch (error) {
        return { name: checkName(check, i), passed: false, message: `it threw: ${said(error)}` };
      }
    });
  for (const check of judge(reference)) {
    report.push(`Reference H, ${check.name}: ${check.passed ? 'passed' : 'FAILED'}: ${check.message}`);
    if (!check.passed) failures.push({ message: `The reference H “${code.reference}” fails ${check.name}: ${check.message}`, about: code.reference });
  }
  const few = fewMistakes(code.mistakes.length, 'H');
  if (few) failures.push(few);
  for (const wrong of code.mistakes) {
    let reader: Model;
    try {
      reader = await build(wrong);
    } catch (error) {
      report.push(`Wrong H “${wrong}”: does not compile: ${said(error)}`);
      failures.push({ message: `The wrong H “${wrong}” cannot be turned into Hamilton’s equations (${said(error)}): list H’s the checks must tell from the reference.`, about: wrong });
      continue;
    }
    const failed = judge(reader).filter((check) => !check.passed);
    if (failed.length) {
      report.push(`Wrong H “${wrong}”: fails ${failed.map((check) => check.name).join(', ')}: ${failed[0].message}`);
    } else {
      report.push(`Wrong H “${wrong}”: passes every check.`);
      failures.push({ message: `The wrong H “${wrong}” passes every check: the checks cannot tell it from the reference “${code.reference}”. Add a check that does.`, about: wrong });
    }
  }
  return verdict(report, failures);
}

/** Runs the answer key of one declaration; never throws (a failure inside a check is reported as the check's). */
export async function testExercise(exercise: Exercise): Promise<ExerciseVerdict> {
  try {
    const grading = await loadGrading();
    if (exercise.code) return await testCode(exercise, grading);
    if (exercise.answer) return testNumber(exercise, grading);
    return verdict([], [{ message: 'The exercise has neither "answer" nor "code": nothing to check.' }]);
  } catch (error) {
    // A truth that throws, say: the declaration's arguments are where to look.
    return verdict([], [{ message: `The check itself failed: ${said(error)}` }]);
  }
}

/** A fence of the chapter as a test: a declaration that does not parse fails with the parser's message, one that does runs its answer key. */
export async function testDeclaration(found: ChapterExercise): Promise<ExerciseVerdict> {
  if ('error' in found.parsed) {
    const message = `The declaration does not parse: ${found.parsed.error}.`;
    return verdict([message], [{ message }]);
  }
  return testExercise(found.parsed.exercise);
}
