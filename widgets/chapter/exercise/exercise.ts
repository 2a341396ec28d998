/**
 * An exercise on the page: the build rendered its title, prompt and sealed
 * parts (site/lib/remark-exercises.mjs); this fills in the answer field or
 * the code check, the hints, the worked solution and "show me in the
 * simulator", and grades. It loads when an exercise first comes near the
 * view (cells/boot.ts), never with a chapter's first paint.
 *
 * What it needs of the page comes through an {@link ExerciseHost}: the
 * cells' values and sources (the reader's code runs as a cell, under the
 * cells' sandbox and loop guard, and its errors show under that cell), a
 * model builder, and the progress store.
 */
import type { HamiltonianSpec, Model } from '../../../core/index.ts';
import { runCheck } from './code-checks.ts';
import type { CodeAnswer, NumberAnswer, PublicExercise, SealedParts } from './exercise-spec.ts';
import { gradeNumber, readNumber, type Verdict } from './grade.ts';
import { unseal } from './seal.ts';
import { computeTruth } from './truths.ts';

export interface ProgressView {
  readonly status: 'solved' | 'attempted';
  readonly attempts: number;
  readonly solutionShown: boolean;
  readonly answer: string;
}

export interface ExerciseHost {
  /** The value the cell named `name` has now; rejects with what it failed with. */
  cellValue(name: string): Promise<unknown>;
  /** Sets cells to these sources and runs them; the undo puts back what they were. */
  setCells(sources: Readonly<Record<string, string>>): { undo(): void } | { error: string };
  /** Hamilton's equations of an H, built as a cell's canonicalEquations builds them. */
  model(spec: HamiltonianSpec): Promise<Model>;
  load(id: string): ProgressView | null;
  /** Keeps a result; returns a sentence when it could not be kept. */
  attempt(id: string, passed: boolean, answer: string): string | null;
  solutionShown(id: string): string | null;
}

export const EXERCISE_ATTRIBUTE = 'data-exercise';

function element<K extends keyof HTMLElementTagNameMap>(tag: K, props: Partial<HTMLElementTagNameMap[K]> = {}, ...children: (Node | string)[]): HTMLElementTagNameMap[K] {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
}

function button(text: string, onClick: () => void): HTMLButtonElement {
  const b = element('button', { type: 'button', className: 'exercise-button', textContent: text });
  b.addEventListener('click', onClick);
  return b;
}

function statusText(progress: ProgressView | null): string {
  if (!progress || progress.attempts === 0) return progress?.solutionShown ? 'Solution shown, not yet checked.' : '';
  const tries = `${progress.attempts} check${progress.attempts > 1 ? 's' : ''}`;
  const shown = progress.solutionShown ? ', solution shown' : '';
  return progress.status === 'solved' ? `Solved (${tries}${shown}).` : `Not solved yet (${tries}${shown}).`;
}

/** The reader's H from their cell's value: a math expression or a JS function; anything else is said. */
function asHamiltonian(value: unknown, cell: string): string | ((...args: never[]) => unknown) {
  if (typeof value === 'string' || typeof value === 'function') return value as string;
  throw new Error(`the cell ${cell} holds ${value === null ? 'null' : typeof value}, not an H: write it as a math expression in quotes, such as "p^2/2 + q^2/2"`);
}

/** Makes one exercise live. */
export function startExercise(root: HTMLElement, host: ExerciseHost): void {
  if (root.dataset.exerciseLive !== undefined) return;
  root.dataset.exerciseLive = '';
  const body = root.querySelector<HTMLElement>('[data-exercise-body]');
  const info = JSON.parse(root.dataset.exercisePublic ?? 'null') as PublicExercise | null;
  if (!body || !info) return;
  unseal(root.dataset.exerciseSealed ?? '', info.id).then(
    (sealed) => buildExercise(root, body, info, sealed as SealedParts, host),
    () => body.replaceChildren(element('p', { className: 'exercise-problem', textContent: 'This exercise’s answer could not be read from the page (it was damaged in transit): reload the page.' })),
  );
}

/** Builds a live exercise in `body` from what the page shows openly and what it sealed. */
function buildExercise(root: HTMLElement, body: HTMLElement, info: PublicExercise, sealed: SealedParts, host: ExerciseHost): void {
  const id = info.id;
  const feedback = element('div', { className: 'exercise-feedback' });
  feedback.setAttribute('role', 'status');
  feedback.setAttribute('aria-live', 'polite');
  feedback.dataset.exerciseFeedback = '';
  const status = element('p', { className: 'exercise-status' });
  status.dataset.exerciseStatus = '';
  const storageNote = element('p', { className: 'exercise-problem', hidden: true });
  storageNote.setAttribute('role', 'alert');
  storageNote.dataset.exerciseStorage = '';
  let attempted = false;

  const showStatus = () => {
    const progress = host.load(id);
    status.textContent = statusText(progress);
    root.dataset.exerciseState = progress?.status === 'solved' ? 'solved' : progress && progress.attempts > 0 ? 'attempted' : 'new';
    attempted ||= (progress?.attempts ?? 0) > 0;
  };
  const kept = (problem: string | null) => {
    storageNote.hidden = problem === null;
    storageNote.textContent = problem ?? '';
  };
  const report = (verdicts: readonly Verdict[], answer: string) => {
    const passed = verdicts.length > 0 && verdicts.every((v) => v.passed);
    attempted = true;
    kept(host.attempt(id, passed, answer));
    showStatus();
    root.dataset.exerciseResult = passed ? 'passed' : 'failed';
    if (verdicts.length === 1) {
      feedback.replaceChildren(element('p', { className: passed ? 'exercise-pass' : 'exercise-fail', textContent: verdicts[0].message }));
    } else {
      const list = element('ul', { className: 'exercise-checks' }, ...verdicts.map((v) =>
        element('li', { className: v.passed ? 'exercise-pass' : 'exercise-fail' }, element('strong', { textContent: v.passed ? 'Passed: ' : 'Failed: ' }), v.message)));
      feedback.replaceChildren(element('p', { textContent: passed ? `All ${verdicts.length} checks passed.` : `${verdicts.filter((v) => !v.passed).length} of ${verdicts.length} checks failed.` }), list);
    }
  };
  const say = (message: string) => {
    root.dataset.exerciseResult = 'problem';
    feedback.replaceChildren(element('p', { className: 'exercise-problem', textContent: message }));
  };

  const answerArea = sealed.answer ? numberAnswer(info, sealed, sealed.answer, host, report, say) : sealed.code ? codeAnswer(sealed.code, host, report, say) : element('p');
  body.replaceChildren(answerArea, feedback, status, storageNote, extras(info, sealed, host, () => attempted, kept, showStatus));
  showStatus();
}

function numberAnswer(info: PublicExercise, sealed: SealedParts, answer: NumberAnswer, host: ExerciseHost, report: (v: Verdict[], a: string) => void, say: (m: string) => void): HTMLElement {
  const inputId = `exercise-${info.id}-answer`;
  const input = element('input', { type: 'text', id: inputId, className: 'exercise-input', autocomplete: 'off', spellcheck: false });
  input.inputMode = 'decimal';
  input.value = host.load(info.id)?.answer ?? '';
  const label = element('label', { htmlFor: inputId, textContent: `Your answer${info.unit ? `, in ${info.unit}` : ''}` });
  const check = () => {
    const read = readNumber(input.value);
    if ('error' in read) {
      say(read.error);
      input.focus();
      return;
    }
    const truth = computeTruth(answer.truth.name, answer.truth.args);
    if ('error' in truth) {
      say(`This exercise cannot be graded: ${truth.error} (tell the author).`);
      return;
    }
    const verdict = gradeNumber(read.value, truth.value, answer.tolerance, answer.mistakes, info.unit);
    report([verdict.passed ? { ...verdict, message: `${verdict.message} The truth: ${sealed.source}.` } : verdict], input.value.trim());
  };
  input.addEventListener('keydown', (event) => {
    if (event.key === 'Enter') {
      event.preventDefault();
      check();
    }
  });
  return element('div', { className: 'exercise-answer' }, label, input, button('Check', check));
}

function codeAnswer(code: CodeAnswer, host: ExerciseHost, report: (v: Verdict[], a: string) => void, say: (m: string) => void): HTMLElement {
  const link = element('a', { href: `#cell-${code.cell}`, textContent: code.cell });
  let checking = false;
  const run = async () => {
    if (checking) return;
    checking = true;
    say('Checking your code…');
    try {
      let value: unknown;
      try {
        value = await host.cellValue(code.cell);
      } catch (error) {
        say(`Your cell ${code.cell} stopped with an error, shown under it: ${(error as Error)?.message ?? String(error)}`);
        return;
      }
      let reader: Model;
      try {
        reader = await host.model({ dof: code.dof, hamiltonian: asHamiltonian(value, code.cell) as HamiltonianSpec['hamiltonian'], params: code.params });
      } catch (error) {
        say(`Your H could not be turned into Hamilton’s equations: ${(error as Error)?.message ?? String(error)}`);
        return;
      }
      const reference = await host.model({ dof: code.dof, hamiltonian: code.reference, params: code.params });
      const verdicts = code.checks.map((check, i) => {
        try {
          return runCheck(check, reader, reference, i + 1);
        } catch (error) {
          return { passed: false, message: `Your H threw while it was checked: ${(error as Error)?.message ?? String(error)}` };
        }
      });
      report(verdicts, '');
    } catch (error) {
      say(`The check itself failed: ${(error as Error)?.message ?? String(error)}`);
    } finally {
      checking = false;
    }
  };
  return element('div', { className: 'exercise-answer' },
    element('p', {}, 'Write your answer in the cell ', link, ', then check it (the check runs it first).'),
    button('Check my code', () => void run()));
}

/** Hints one at a time, the worked solution with a confirmation before any attempt, and the simulator's setup with its undo. */
function extras(info: PublicExercise, sealed: SealedParts, host: ExerciseHost, attempted: () => boolean, kept: (p: string | null) => void, showStatus: () => void): HTMLElement {
  const bar = element('div', { className: 'exercise-actions' });
  const hints = element('ol', { className: 'exercise-hints' });
  hints.setAttribute('aria-live', 'polite');
  const shown = element('div', { className: 'exercise-solution', hidden: true });
  const confirmRow = element('p', { className: 'exercise-confirm', hidden: true });
  const area = element('div', {}, bar, confirmRow, hints, shown);

  if (sealed.hints.length) {
    const next = button(`Hint 1 of ${sealed.hints.length}`, () => {
      const k = hints.children.length;
      if (k >= sealed.hints.length) return;
      const item = element('li');
      item.innerHTML = sealed.hints[k];
      hints.append(item);
      if (k + 1 < sealed.hints.length) next.textContent = `Hint ${k + 2} of ${sealed.hints.length}`;
      else {
        next.textContent = 'No more hints';
        next.disabled = true;
      }
    });
    bar.append(next);
  }

  const reveal = () => {
    shown.innerHTML = `<p><strong>Worked solution.</strong></p>${sealed.solution}<p class="exercise-source">Truth: ${escapeText(sealed.source)}.</p>`;
    shown.hidden = false;
    confirmRow.hidden = true;
    solution.disabled = true;
    kept(host.solutionShown(info.id));
    showStatus();
    shown.tabIndex = -1;
    shown.focus();
  };
  const solution = button('Show the solution', () => {
    if (attempted()) return reveal();
    confirmRow.replaceChildren('You have not checked an answer yet: trying first is how it sticks. Show the worked solution anyway? ',
      button('Show it', reveal), ' ', button('Not yet', () => {
        confirmRow.hidden = true;
        solution.focus();
      }));
    confirmRow.hidden = false;
    (confirmRow.querySelector('button') as HTMLButtonElement).focus();
  });
  bar.append(solution);

  if (info.simulate) {
    const setup = info.simulate;
    let undo: (() => void) | null = null;
    const problem = element('p', { className: 'exercise-problem', hidden: true });
    problem.setAttribute('role', 'alert');
    const say = (text: string | null) => {
      problem.hidden = text === null;
      problem.textContent = text ?? '';
    };
    area.append(problem);
    const simulate = button('Show me in the simulator', () => {
      if (undo) {
        undo();
        undo = null;
        simulate.textContent = 'Show me in the simulator';
        say(null);
        return;
      }
      const result = host.setCells(setup);
      if ('error' in result) {
        say(result.error);
        return;
      }
      undo = result.undo;
      simulate.textContent = 'Undo: put the cells back';
      say(null);
    });
    simulate.dataset.exerciseSimulate = '';
    bar.append(simulate);
  }
  return area;
}

function escapeText(text: string): string {
  return text.replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);
}
