/**
 * The chapters' theory checks and exercises in the Test Explorer: one item
 * per chapter that has either, one child per cell that makes a check, and
 * an "Exercises" group (exercise-items.ts) beside them. Running checks runs
 * the chapter in a preview (its own if open, else the one background
 * preview that test runs share, PreviewManager.forChecks) and reads each
 * check's readout: passed, failed with the measured and predicted values,
 * skipped when the formula's regime does not hold, or errored with the
 * cell's error or the reason a check has no verdict. A check that has no
 * readout within its time limit fails, saying so. Exercises run in the
 * extension host itself, without a preview.
 */
import * as vscode from 'vscode';
import { checkCells, verdictOf, type Verdict } from '../analyzer/theory-checks.ts';
import type { CheckResult } from '../shared/messages.ts';
import type { ChapterIndex } from './chapter-index.ts';
import type { PreviewManager } from './preview/preview-manager.ts';
import { exerciseGroup, exerciseOf, groupId, isExerciseItem, runExercise } from './exercise-items.ts';
import { rangeOf } from './problem-diagnostics.ts';

/** How long a chapter's checks may take to settle, the preview's loading included: models compile and simulations run first. */
const CHECK_TIMEOUT_MS = 60_000;

/** What a check that had no answer in time gives: a timeout, whatever the preview is doing (loading, or hung). */
const timedOut = (ids: readonly string[]): CheckResult[] => ids.map((id) => ({ id, state: 'timeout', checks: [] }));

export class TheoryTests implements vscode.Disposable {
  readonly controller: vscode.TestController;
  readonly profile: vscode.TestRunProfile;
  /** Each check's time limit; the in-host tests shorten it to see it fire. */
  timeoutMs = CHECK_TIMEOUT_MS;
  readonly #index: ChapterIndex;
  readonly #previews: PreviewManager;

  constructor(index: ChapterIndex, previews: PreviewManager) {
    this.#index = index;
    this.#previews = previews;
    this.controller = vscode.tests.createTestController('phasebook.theoryChecks', 'Phasebook checks and exercises');
    this.profile = this.controller.createRunProfile('Run checks and exercises', vscode.TestRunProfileKind.Run, (request, token) => this.#run(request, token), true);
    this.controller.refreshHandler = async () => {
      await index.ready;
      this.#refreshAll();
    };
    index.onDidChange((uri) => this.#refresh(uri));
    void index.ready.then(() => this.#refreshAll());
  }

  dispose(): void {
    this.controller.dispose();
  }

  /**
   * Runs the chapter's checks (those of `cellIds`, or all) in a preview: a
   * verdict per cell id. Each check not read within {@link timeoutMs} of
   * the start (the preview's loading counts) has timed out; a cancelled
   * `token` ends the wait the same way.
   */
  async verdicts(uri: vscode.Uri, cellIds?: readonly string[], token?: vscode.CancellationToken): Promise<Map<string, Verdict>> {
    const timeoutMs = this.timeoutMs;
    const analysis = this.#index.known(uri) ?? this.#index.analysisOf(await vscode.workspace.openTextDocument(uri));
    const ids = cellIds ?? checkCells(analysis.cells).map(({ cell }) => cell.id);
    const answer = this.#previews.forChecks(uri).then((preview) => preview.checks(ids, timeoutMs));
    // An answer that comes after the deadline has nobody waiting for it, and its failure nobody to tell.
    answer.catch(() => undefined);
    let timer: ReturnType<typeof setTimeout> | undefined;
    let cancelled: vscode.Disposable | undefined;
    const deadline = new Promise<readonly CheckResult[]>((resolve) => {
      timer = setTimeout(() => resolve(timedOut(ids)), timeoutMs);
      cancelled = token?.onCancellationRequested(() => resolve(timedOut(ids)));
    });
    try {
      const results = await Promise.race([answer, deadline]);
      return new Map(ids.map((id) => [id, verdictOf(results.find((r) => r.id === id) ?? { id, state: 'missing', checks: [] }, timeoutMs)]));
    } finally {
      clearTimeout(timer);
      cancelled?.dispose();
    }
  }

  #refreshAll(): void {
    for (const { uri } of this.#index.chapters()) this.#refresh(uri);
  }

  /** The chapter's item, its checks and its exercises, from its latest analysis (removed when it has neither). */
  #refresh(uri: vscode.Uri): void {
    const analysis = this.#index.known(uri);
    const checks = analysis ? checkCells(analysis.cells) : [];
    const id = uri.toString();
    if (!analysis || (checks.length === 0 && analysis.exercises.length === 0)) {
      this.controller.items.delete(id);
      return;
    }
    const label = analysis.frontMatter.title ?? uri.path.slice(uri.path.lastIndexOf('/') + 1);
    const chapter = this.controller.items.get(id) ?? this.controller.createTestItem(id, label, uri);
    chapter.label = label;
    const exercises = exerciseGroup(this.controller, id, uri, analysis, chapter.children.get(groupId(id)));
    chapter.children.replace([
      ...checks.map(({ cell, label: checkLabel }) => {
        const item = this.controller.createTestItem(`${id}#${cell.id}`, checkLabel, uri);
        item.range = rangeOf(analysis.lines, cell.start, cell.end);
        item.description = cell.name ?? undefined;
        return item;
      }),
      ...(exercises ? [exercises] : []),
    ]);
    this.controller.items.add(chapter);
  }

  /** Runs exercises' answer keys, each against its chapter's latest text; they need a trusted workspace, as they run the H's they list. */
  async #runExercises(run: vscode.TestRun, items: readonly vscode.TestItem[], token: vscode.CancellationToken): Promise<void> {
    for (const item of items) {
      if (token.isCancellationRequested) {
        run.skipped(item);
        continue;
      }
      run.started(item);
      if (!vscode.workspace.isTrusted) {
        run.errored(item, new vscode.TestMessage('An exercise’s check runs the H’s it lists, which may be JavaScript: trust the workspace to run it.'));
        continue;
      }
      const uri = vscode.Uri.parse(exerciseOf(item).chapter);
      try {
        const analysis = this.#index.known(uri) ?? this.#index.analysisOf(await vscode.workspace.openTextDocument(uri));
        await runExercise(run, item, uri, analysis);
      } catch (error) {
        run.errored(item, new vscode.TestMessage(`The exercise could not be checked: ${(error as Error).message}.`));
      }
    }
  }

  async #run(request: vscode.TestRunRequest, token: vscode.CancellationToken): Promise<void> {
    const run = this.controller.createTestRun(request);
    const byChapter = new Map<string, vscode.TestItem[]>();
    const exercises: vscode.TestItem[] = [];
    const add = (item: vscode.TestItem) => {
      if (request.exclude?.includes(item)) return;
      if (item.children.size) item.children.forEach(add);
      else if (isExerciseItem(item)) exercises.push(item);
      else if (item.parent) byChapter.set(item.parent.id, [...(byChapter.get(item.parent.id) ?? []), item]);
    };
    if (request.include) request.include.forEach(add);
    else this.controller.items.forEach(add);
    try {
      // First, as they take a moment where the checks wait for a preview.
      await this.#runExercises(run, exercises, token);
      for (const [chapter, items] of byChapter) {
        if (token.isCancellationRequested) break;
        items.forEach((item) => run.started(item));
        const started = Date.now();
        const cellIds = items.map((item) => item.id.slice(chapter.length + 1));
        let verdicts: Map<string, Verdict>;
        try {
          verdicts = await this.verdicts(vscode.Uri.parse(chapter), cellIds, token);
        } catch (error) {
          // No preview (an untrusted workspace, a chapter that cannot be read): every check of the chapter errs, saying why.
          items.forEach((item) => run.errored(item, new vscode.TestMessage(`The checks could not run: ${(error as Error).message}.`)));
          continue;
        }
        // A run stopped from the Test Explorer: the checks it was waiting for judged nothing.
        if (token.isCancellationRequested) {
          items.forEach((item) => run.skipped(item));
          break;
        }
        const duration = Date.now() - started;
        items.forEach((item, i) => {
          const verdict = verdicts.get(cellIds[i])!;
          run.appendOutput(`${item.label}\r\n${verdict.message.replace(/\n/g, '\r\n')}\r\n\r\n`, undefined, item);
          if (verdict.outcome === 'passed') {
            run.passed(item, duration);
            return;
          }
          // Outside the formula's regime a check judges nothing; the output above says which condition fails.
          if (verdict.outcome === 'skipped') {
            run.skipped(item);
            return;
          }
          const message = verdict.expected !== undefined && verdict.actual !== undefined
            ? vscode.TestMessage.diff(verdict.message, verdict.expected, verdict.actual)
            : new vscode.TestMessage(verdict.message);
          if (item.uri && item.range) message.location = new vscode.Location(item.uri, item.range);
          if (verdict.outcome === 'failed') run.failed(item, message, duration);
          else run.errored(item, message, duration);
        });
      }
    } finally {
      run.end();
    }
  }
}
