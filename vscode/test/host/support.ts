/** Helpers of the in-host suite: the extension's API, the test workspace's files, and waiting for things to happen. */
import * as vscode from 'vscode';
import type { PhasebookApi } from '../../src/extension.ts';
import type { ChapterPreview } from '../../src/host/preview/chapter-preview.ts';
import type { PreviewMessage } from '../../src/shared/messages.ts';

export async function extensionApi(): Promise<PhasebookApi> {
  const extension = vscode.extensions.getExtension<PhasebookApi>('phasebook.phasebook');
  if (!extension) throw new Error('the Phasebook extension is not installed in this host');
  const api = await extension.activate();
  await api.index.ready;
  return api;
}

/** A file of the test workspace (test/driver/run.ts assembles it: the fixtures, the template, the template as content/pendulum.mdx). */
export function workspaceFile(relative: string): vscode.Uri {
  const folder = vscode.workspace.workspaceFolders?.[0];
  if (!folder) throw new Error('the suite needs the test workspace open');
  return vscode.Uri.joinPath(folder.uri, relative);
}

/** Polls `probe` until it returns something truthy, or fails after `timeoutMs` with `what`. */
export async function waitFor<T>(what: string, probe: () => T | undefined | null | false, timeoutMs = 20_000): Promise<T> {
  const deadline = Date.now() + timeoutMs;
  for (;;) {
    const value = probe();
    if (value) return value;
    if (Date.now() > deadline) throw new Error(`timed out waiting for ${what}`);
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
}

/** The next message from a preview that satisfies `match`. */
export function nextMessage<T extends PreviewMessage['type']>(
  preview: ChapterPreview,
  type: T,
  match: (message: Extract<PreviewMessage, { type: T }>) => boolean = () => true,
  timeoutMs = 45_000,
): Promise<Extract<PreviewMessage, { type: T }>> {
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => {
      listener.dispose();
      reject(new Error(`timed out waiting for a "${type}" message from the preview`));
    }, timeoutMs);
    const listener = preview.onMessage((message) => {
      if (message.type !== type || !match(message as Extract<PreviewMessage, { type: T }>)) return;
      clearTimeout(timer);
      listener.dispose();
      resolve(message as Extract<PreviewMessage, { type: T }>);
    });
  });
}

/** The diagnostics of one source (Phasebook, or Phasebook preview) on a file. */
export function diagnosticsOf(uri: vscode.Uri, source: string): vscode.Diagnostic[] {
  return vscode.languages.getDiagnostics(uri).filter((d) => d.source === source);
}

/** `code line:character` of a diagnostic's start, for compact comparisons. */
export function placeOf(diagnostic: vscode.Diagnostic): string {
  const code = typeof diagnostic.code === 'object' ? diagnostic.code.value : diagnostic.code;
  return `${code} ${diagnostic.range.start.line}:${diagnostic.range.start.character}`;
}

/** The list, or undefined when it is empty (for {@link waitFor}). */
export function nonEmpty<T>(list: readonly T[]): readonly T[] | undefined {
  return list.length ? list : undefined;
}

export function pause(ms: number): Promise<void> {
  return new Promise((resolve) => setTimeout(resolve, ms));
}

export function children(item: vscode.TestItem): vscode.TestItem[] {
  const found: vscode.TestItem[] = [];
  item.children.forEach((child) => found.push(child));
  return found;
}

/**
 * What a test run reports, recorded: the controller's runs are wrapped while `act` runs, since
 * an extension cannot read test results back from VS Code. A failure lists each of its messages
 * with the line it is shown at.
 */
export async function recordRun(controller: vscode.TestController, act: () => Thenable<void> | void): Promise<string[]> {
  const outcomes: string[] = [];
  const create = controller.createTestRun;
  const all = (message: vscode.TestMessage | readonly vscode.TestMessage[]) => (Array.isArray(message) ? message : [message]) as vscode.TestMessage[];
  controller.createTestRun = (...args) => {
    const run = create.apply(controller, args);
    return {
      ...run,
      token: run.token,
      started: (item) => (outcomes.push(`started ${item.label}`), run.started(item)),
      passed: (item, duration) => (outcomes.push(`passed ${item.label}`), run.passed(item, duration)),
      failed: (item, message, duration) => {
        const said = all(message).map((m) => {
          const text = m.expectedOutput === undefined ? String(m.message) : `expected ${m.expectedOutput}, actual ${m.actualOutput}`;
          return `${text}, at line ${m.location?.range.start.line}`;
        });
        outcomes.push(`failed ${item.label}: ${said.join('; ')}`);
        run.failed(item, message, duration);
      },
      errored: (item, message, duration) => (outcomes.push(`errored ${item.label}: ${all(message)[0].message}`), run.errored(item, message, duration)),
      skipped: (item) => (outcomes.push(`skipped ${item.label}`), run.skipped(item)),
      appendOutput: (...output) => run.appendOutput(...output),
      end: () => (outcomes.push('end'), run.end()),
    } as vscode.TestRun;
  };
  try {
    await act();
  } finally {
    controller.createTestRun = create;
  }
  return outcomes;
}
