/**
 * A chapter's exercises in the Test Explorer: an "Exercises" group under
 * the chapter, beside its theory checks, with an item per ```exercise
 * fence (labelled by its title, its kind as the description, its range the
 * fence). Running one runs its answer key in the extension host
 * (analyzer/exercise-tests.ts, no preview needed, nothing Node-only): a
 * failure is a message per wrong answer, at the line where the
 * declaration lists it.
 */
import * as vscode from 'vscode';
import type { ChapterAnalysis } from '../analyzer/analyze.ts';
import { testDeclaration } from '../analyzer/exercise-tests.ts';
import { rangeOf } from './problem-diagnostics.ts';

/** The group's id under a chapter's id, and the mark of an exercise's id: `<chapter>#:exercise:<key>` (no cell's id, which is a name, has a colon). */
const GROUP = '#:exercises';
const EXERCISE = '#:exercise:';

export const groupId = (chapterId: string): string => chapterId + GROUP;

export const isExerciseItem = (item: vscode.TestItem): boolean => item.id.includes(EXERCISE);

/** The chapter's id and the exercise's key, from an exercise item's id. */
export function exerciseOf(item: vscode.TestItem): { chapter: string; key: string } {
  const at = item.id.lastIndexOf(EXERCISE);
  return { chapter: item.id.slice(0, at), key: item.id.slice(at + EXERCISE.length) };
}

/** The chapter's "Exercises" group, filled from its latest analysis; null when it declares none. */
export function exerciseGroup(controller: vscode.TestController, chapterId: string, uri: vscode.Uri, analysis: ChapterAnalysis, existing?: vscode.TestItem): vscode.TestItem | null {
  if (analysis.exercises.length === 0) return null;
  const group = existing ?? controller.createTestItem(groupId(chapterId), 'Exercises', uri);
  group.children.replace(
    analysis.exercises.map((found) => {
      const item = controller.createTestItem(chapterId + EXERCISE + found.key, found.label, uri);
      item.description = found.description;
      item.range = rangeOf(analysis.lines, found.start, found.end);
      return item;
    }),
  );
  return group;
}

/** Runs one exercise's answer key and reports it on `item`: passed, or failed with a message per finding, at the answer it is about (else at the fence). */
export async function runExercise(run: vscode.TestRun, item: vscode.TestItem, uri: vscode.Uri, analysis: ChapterAnalysis): Promise<void> {
  const started = Date.now();
  const { key } = exerciseOf(item);
  const found = analysis.exercises.find((exercise) => exercise.key === key);
  if (!found) {
    run.errored(item, new vscode.TestMessage('The chapter no longer declares this exercise.'));
    return;
  }
  const verdict = await testDeclaration(found);
  const duration = Date.now() - started;
  run.appendOutput(`${item.label}\r\n${verdict.report.join('\r\n')}\r\n\r\n`, undefined, item);
  if (verdict.outcome === 'passed') {
    run.passed(item, duration);
    return;
  }
  const messages = verdict.failures.map((failure) => {
    const place = (failure.about !== undefined && found.locate(failure.about)) || found;
    const message = new vscode.TestMessage(failure.message);
    message.location = new vscode.Location(uri, rangeOf(analysis.lines, place.start, place.end));
    return message;
  });
  run.failed(item, messages, duration);
}
