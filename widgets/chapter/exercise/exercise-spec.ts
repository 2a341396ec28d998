/**
 * An exercise as its author declares it: a fenced block marked
 * ```` ```exercise ```` in a chapter's MDX, holding one JSON object. It is
 * static and parseable, so the build (site/lib/remark-exercises.mjs), the
 * progress page and tools outside the page (an LMS package, an editor's test
 * list) all read the same declaration, without running the chapter.
 *
 * Three kinds:
 * - `predict`: the reader enters a number, graded against a truth
 *   (truths.ts) within the tolerance the exercise states and justifies;
 * - `find`: the same, for a value found by exploring the chapter's cells;
 * - `code`: the reader edits the cell `code.cell`, and property checks
 *   (code-checks.ts) compare the model it defines with a reference.
 *
 * The public part (id, kind, title, prompt, unit) is shown as is; the rest
 * is sealed into the page (seal.ts).
 */

export type ExerciseKind = 'predict' | 'find' | 'code';

export const KIND_NAMES: Readonly<Record<ExerciseKind, string>> = {
  predict: 'Predict, then check',
  find: 'Find it',
  code: 'Write code',
};

export interface Tolerance {
  /** Allowed |answer − truth|, in the answer's unit. */
  readonly absolute?: number;
  /** Allowed |answer − truth|/|truth|. */
  readonly relative?: number;
  /** Why this much, in a sentence the verdict shows. */
  readonly why: string;
}

/** A plausible wrong answer: graded answers near it are told why it is wrong. */
export interface NumberMistake {
  readonly value: number;
  readonly why: string;
}

export interface NumberAnswer {
  /** The truth's name in truths.ts and its arguments. */
  readonly truth: { readonly name: string; readonly args: Readonly<Record<string, number>> };
  readonly tolerance: Tolerance;
  readonly mistakes: readonly NumberMistake[];
}

export type CodeCheck =
  | { readonly check: 'equations'; readonly box: readonly (readonly [number, number])[] }
  | { readonly check: 'returns'; readonly initial: readonly number[]; readonly period: number; readonly dt?: number; readonly tolerance?: number }
  | { readonly check: 'equationsInTime'; readonly box: readonly (readonly [number, number])[]; readonly time: readonly [number, number] };

export interface CodeAnswer {
  /** The name of the cell the reader edits: its value is their H (a math expression or a JS function). */
  readonly cell: string;
  readonly dof: number;
  readonly params: Readonly<Record<string, number>>;
  /** The reference H, as a math expression. */
  readonly reference: string;
  readonly checks: readonly CodeCheck[];
  /** Plausible wrong H's, each of which some check must fail (the tests run them). */
  readonly mistakes: readonly string[];
}

/** What is sealed into the page. */
export interface SealedParts {
  readonly answer?: NumberAnswer;
  readonly code?: CodeAnswer;
  readonly hints: readonly string[];
  readonly solution: string;
  /** Where the truth comes from, said with the verdict. */
  readonly source: string;
}

export interface Exercise extends SealedParts {
  readonly id: string;
  readonly kind: ExerciseKind;
  readonly title: string;
  /** Text with $…$ for math. */
  readonly prompt: string;
  /** The unit of the number asked for (predict and find). */
  readonly unit?: string;
  /** "Show me in the simulator": cell name → the source to set it to. */
  readonly simulate?: Readonly<Record<string, string>>;
}

/** What the page shows openly (the rest is sealed). */
export type PublicExercise = Pick<Exercise, 'id' | 'kind' | 'title' | 'unit' | 'simulate'> & { readonly hintCount: number };

export type Parsed = { readonly exercise: Exercise } | { readonly error: string };

const isRecord = (v: unknown): v is Record<string, unknown> => typeof v === 'object' && v !== null && !Array.isArray(v);
const isText = (v: unknown): v is string => typeof v === 'string' && v.trim() !== '';
const isNumber = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);

function numbers(value: unknown, what: string): Record<string, number> {
  if (value === undefined) return {};
  if (!isRecord(value) || !Object.values(value).every(isNumber)) throw new Error(`${what} must be an object of numbers`);
  return value as Record<string, number>;
}

function parseTolerance(value: unknown): Tolerance {
  if (!isRecord(value) || !isText(value.why)) throw new Error('answer.tolerance needs "why", a sentence that justifies it');
  const { absolute, relative } = value;
  if (absolute === undefined && relative === undefined) throw new Error('answer.tolerance needs "absolute" or "relative"');
  for (const [name, v] of [['absolute', absolute], ['relative', relative]] as const) {
    if (v !== undefined && !(isNumber(v) && v > 0)) throw new Error(`answer.tolerance.${name} must be a positive number`);
  }
  return { absolute: absolute as number | undefined, relative: relative as number | undefined, why: value.why };
}

function parseAnswer(value: unknown): NumberAnswer {
  if (!isRecord(value) || !isRecord(value.truth) || !isText(value.truth.name)) throw new Error('"answer" needs "truth": {"name", "args"}');
  const mistakes = value.mistakes ?? [];
  if (!Array.isArray(mistakes) || !mistakes.every((m) => isRecord(m) && isNumber(m.value) && isText(m.why))) {
    throw new Error('answer.mistakes must be a list of {"value": number, "why": sentence}');
  }
  return {
    truth: { name: value.truth.name, args: numbers(value.truth.args, 'answer.truth.args') },
    tolerance: parseTolerance(value.tolerance),
    mistakes: mistakes as NumberMistake[],
  };
}

function parseCheck(value: unknown): CodeCheck {
  if (!isRecord(value)) throw new Error('each of code.checks must be an object');
  if (value.check === 'equations') {
    const box = value.box;
    if (!Array.isArray(box) || !box.every((r) => Array.isArray(r) && r.length === 2 && r.every(isNumber) && r[0] < r[1])) {
      throw new Error('an "equations" check needs "box": a [low, high] range per component of the state');
    }
    return { check: 'equations', box: box as [number, number][] };
  }
  if (value.check === 'returns') {
    if (!Array.isArray(value.initial) || !value.initial.every(isNumber) || !isNumber(value.period) || !(value.period > 0)) {
      throw new Error('a "returns" check needs "initial" (a state) and "period" (a positive number)');
    }
    if (value.dt !== undefined && !(isNumber(value.dt) && value.dt > 0)) throw new Error('a "returns" check’s "dt" must be a positive number');
    if (value.tolerance !== undefined && !(isNumber(value.tolerance) && value.tolerance > 0)) throw new Error('a "returns" check’s "tolerance" must be a positive number');
    return { check: 'returns', initial: value.initial as number[], period: value.period, dt: value.dt as number | undefined, tolerance: value.tolerance as number | undefined };
  }
  if (value.check === 'equationsInTime') {
    const { box } = parseCheck({ check: 'equations', box: value.box }) as { readonly box: readonly (readonly [number, number])[] };
    const time = value.time;
    if (!Array.isArray(time) || time.length !== 2 || !time.every(isNumber) || !(time[0] < time[1])) {
      throw new Error('an "equationsInTime" check needs "time": the [earliest, latest] t to compare the equations at');
    }
    return { check: 'equationsInTime', box, time: [time[0], time[1]] };
  }
  throw new Error(`unknown check ${JSON.stringify(value.check)}: use "equations", "equationsInTime" or "returns"`);
}

function parseCode(value: unknown): CodeAnswer {
  if (!isRecord(value) || !isText(value.cell) || !isText(value.reference)) throw new Error('"code" needs "cell" (the cell the reader edits) and "reference" (an H)');
  const dof = value.dof ?? 1;
  if (!(Number.isInteger(dof) && (dof as number) >= 1)) throw new Error('code.dof must be a whole number ≥ 1');
  if (!Array.isArray(value.checks) || value.checks.length === 0) throw new Error('code.checks must list at least one check');
  const mistakes = value.mistakes ?? [];
  if (!Array.isArray(mistakes) || !mistakes.every(isText)) throw new Error('code.mistakes must be a list of H’s');
  const checks = value.checks.map(parseCheck);
  for (const c of checks) {
    const size = c.check === 'returns' ? c.initial.length : c.box.length;
    if (size !== 2 * (dof as number)) throw new Error(`a "${c.check}" check must give ${2 * (dof as number)} components, one per q and p`);
  }
  return { cell: value.cell, dof: dof as number, params: numbers(value.params, 'code.params'), reference: value.reference, checks, mistakes: mistakes as string[] };
}

/**
 * Reads a declaration; never throws. An error names the first thing wrong,
 * in words an author can act on (the build shows it in the page).
 */
export function parseExercise(text: string): Parsed {
  let raw: unknown;
  try {
    raw = JSON.parse(text);
  } catch (error) {
    return { error: `an exercise is one JSON object: ${(error as Error).message}` };
  }
  try {
    if (!isRecord(raw)) throw new Error('an exercise is one JSON object');
    const { id, kind, title, prompt, hints = [], solution, source, unit, simulate } = raw;
    if (!isText(id) || !/^[a-z0-9][a-z0-9-]*$/.test(id)) throw new Error('"id" must be lower-case letters, digits and dashes: progress is kept under it');
    if (kind !== 'predict' && kind !== 'find' && kind !== 'code') throw new Error(`"kind" must be "predict", "find" or "code"`);
    if (!isText(title) || !isText(prompt)) throw new Error('"title" and "prompt" are needed');
    if (!Array.isArray(hints) || hints.length > 3 || !hints.every(isText)) throw new Error('"hints" is a list of at most three sentences');
    if (!isText(solution)) throw new Error('"solution", the worked solution, is needed');
    if (!isText(source)) throw new Error('"source", where the truth comes from, is needed');
    if (unit !== undefined && !isText(unit)) throw new Error('"unit" must be text');
    if (simulate !== undefined && !(isRecord(simulate) && Object.values(simulate).every(isText))) throw new Error('"simulate" maps cell names to their new source');
    const numeric = kind !== 'code';
    if (numeric && raw.answer === undefined) throw new Error(`a "${kind}" exercise needs "answer"`);
    if (!numeric && raw.code === undefined) throw new Error('a "code" exercise needs "code"');
    const exercise: Exercise = {
      id, kind, title, prompt, unit, source, solution, hints: hints as string[],
      simulate: simulate as Record<string, string> | undefined,
      ...(numeric ? { answer: parseAnswer(raw.answer) } : { code: parseCode(raw.code) }),
    };
    return { exercise };
  } catch (error) {
    return { error: (error as Error).message };
  }
}

export function publicPart(exercise: Exercise): PublicExercise {
  const { id, kind, title, unit, simulate, hints } = exercise;
  return { id, kind, title, unit, simulate, hintCount: hints.length };
}

export function sealedPart(exercise: Exercise): SealedParts {
  const { answer, code, hints, solution, source } = exercise;
  return { answer, code, hints, solution, source };
}

/** Every exercise declared in an MDX text, in order, for pages that list them (the progress page) without rendering the chapter. */
export function exercisesInText(mdx: string): Parsed[] {
  return [...mdx.matchAll(/^```exercise[^\n]*\n([\s\S]*?)^```\s*$/gm)].map((m) => parseExercise(m[1]));
}
