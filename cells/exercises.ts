/**
 * Connects the chapter's exercises to its cells: loaded by boot.ts when an
 * exercise first comes near the view, it hands each exercise its host (the
 * cells' values and sources, the model builder, this browser's progress)
 * and loads the exercise widget, whose code a chapter's first paint never
 * carries.
 */
import { type ExerciseHost, loadExerciseWidget } from '../widgets/index.ts';
import type { LiveCell } from './cell.ts';
import { loadFailure } from './load-failure.ts';
import { EXERCISE_RESULT_EVENT, type ExerciseResult, ProgressStore, type WriteResult } from './progress.ts';
import type { Notebook } from './runtime.ts';

export interface ExercisePage {
  readonly notebook: Notebook;
  readonly cells: () => readonly LiveCell[];
  /** Asks the scheduler to define a cell now, whether or not it is near the view. */
  readonly want: (cell: LiveCell) => void;
  readonly model: ExerciseHost['model'];
}

function problem(write: WriteResult): string | null {
  if (write.ok) return null;
  return write.reason === 'full'
    ? 'This browser’s storage is full: your result holds for this visit only, and the progress page will not show it.'
    : 'This browser keeps nothing for this site (private mode, or storage switched off): your result holds for this visit only.';
}

export function exerciseHost(page: ExercisePage, store = new ProgressStore(), path = location.pathname): ExerciseHost {
  const named = (name: string) => page.cells().find((cell) => cell.name === name);
  return {
    cellValue: async (name) => {
      const cell = named(name);
      if (!cell) throw new Error(`this chapter has no cell named ${name}`);
      page.want(cell);
      await cell.start();
      // "Check my code" checks the code the reader sees: text typed but not run is run first, and a Run still
      // compiling (the parser and the sandbox load on a first edit) is waited for, else the old code would be graded.
      if (cell.hasUnrunEdit) await cell.run();
      await cell.applied;
      if (cell.hasUnrunEdit) throw new Error('its text did not compile, so the code that runs is not what you wrote');
      // A cell being started is defined once its code is compiled: until then the runtime does not know the name.
      for (let tries = 0; ; tries++) {
        try {
          return await page.notebook.value(name);
        } catch (error) {
          if (page.notebook.isCell(name) || tries >= 50) throw error;
          await new Promise((resolve) => setTimeout(resolve, 100));
        }
      }
    },
    setCells: (sources) => {
      const targets = Object.entries(sources).map(([name, source]) => ({ cell: named(name), name, source }));
      const missing = targets.filter((t) => !t.cell).map((t) => t.name);
      if (missing.length) return { error: `The simulator could not be set up: this chapter has no cell named ${missing.join(', ')}.` };
      const before = targets.map(({ cell }) => ({ cell: cell!, edit: cell!.edit }));
      for (const { cell, source } of targets) {
        page.want(cell!);
        void cell!.setSource(source);
      }
      return {
        undo: () => {
          for (const { cell, edit } of before) {
            if (edit) void cell.setSource(edit.running);
            else cell.reset();
          }
        },
      };
    },
    model: page.model,
    load: (id) => store.load(path, id),
    attempt: (id, passed, answer) => {
      const { record, write } = store.attempt(path, id, passed, answer);
      const detail: ExerciseResult = { id, passed, solved: record.status === 'solved' };
      document.dispatchEvent(new CustomEvent(EXERCISE_RESULT_EVENT, { detail }));
      return problem(write);
    },
    solutionShown: (id) => problem(store.solutionShown(path, id).write),
  };
}

/** Starts every exercise in `elements` with the widget, or says under each why it could not load. */
export async function startExercises(elements: readonly HTMLElement[], page: ExercisePage): Promise<void> {
  const host = exerciseHost(page);
  try {
    const { startExercise } = await loadExerciseWidget();
    for (const element of elements) startExercise(element, host);
  } catch {
    const message = loadFailure('This exercise').message;
    for (const element of elements) {
      const body = element.querySelector('[data-exercise-body]');
      const line = document.createElement('p');
      line.setAttribute('role', 'alert');
      line.textContent = message;
      body?.replaceChildren(line);
    }
  }
}
