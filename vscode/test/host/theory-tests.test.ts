import { expect } from 'chai';
import * as vscode from 'vscode';
import { PREVIEW_VIEW_TYPE } from '../../src/host/preview/chapter-preview.ts';
import { children, diagnosticsOf, extensionApi, recordRun, waitFor, workspaceFile } from './support.ts';

/** The tabs of Phasebook previews, in every editor group. */
const previewTabs = () =>
  vscode.window.tabGroups.all.flatMap((group) => group.tabs).filter((tab) => tab.input instanceof vscode.TabInputWebview && tab.input.viewType.includes(PREVIEW_VIEW_TYPE));

describe('theory checks in the Test Explorer', () => {
  before(extensionApi);

  it("lists each chapter's theory checks, by label, at their cells", async () => {
    const { theoryTests } = await extensionApi();
    const items = theoryTests.controller.items;
    const pendulum = await waitFor('the pendulum chapter', () => items.get(workspaceFile('content/pendulum.mdx').toString()));
    expect(pendulum.label).to.equal('The pendulum');
    // Its exercises, beside the check, are exercises.test.ts's.
    expect(children(pendulum).map((c) => c.label)).to.deep.equal(['Period of the pendulum', 'Exercises']);
    const checks = items.get(workspaceFile('content/checks.mdx').toString())!;
    expect(children(checks).map((c) => [c.label, c.range?.start.line])).to.deep.equal([['Two plus two', 6], ['Pi, roughly', 10]]);
    // A chapter without checks has no item.
    expect(items.get(workspaceFile('content/unopened.mdx').toString())).to.equal(undefined);
  });

  it('runs them in the preview: passed, or failed with the measured and predicted values', async () => {
    const { theoryTests } = await extensionApi();
    const verdicts = await theoryTests.verdicts(workspaceFile('content/checks.mdx'));
    expect(verdicts.get('passing')).to.deep.include({ outcome: 'passed' });
    expect(verdicts.get('failing')).to.deep.include({ outcome: 'failed', expected: `${Math.PI} ± 1 %`, actual: '3' });
    expect(verdicts.get('failing')!.message).to.match(/^Pi, roughly: measured 3, predicted 3\.14159\d*; difference 4\.51 %, allowed 1 %: outside the expected error$/);
  });

  it('reports a run from the Test Explorer: passed, or failed with theory against simulation, at the cell', async () => {
    const { theoryTests } = await extensionApi();
    const checks = theoryTests.controller.items.get(workspaceFile('content/checks.mdx').toString())!;
    const outcomes = await recordRun(theoryTests.controller, () =>
      theoryTests.profile.runHandler(new vscode.TestRunRequest([checks]), new vscode.CancellationTokenSource().token),
    );
    expect(outcomes).to.deep.equal([
      'started Two plus two',
      'started Pi, roughly',
      'passed Two plus two',
      `failed Pi, roughly: expected ${Math.PI} ± 1 %, actual 3, at line 10`,
      'end',
    ]);
  });

  it("turns a cell's runtime error in the preview into a diagnostic on its line", async () => {
    const uri = workspaceFile('content/checks.mdx');
    const found = await waitFor('the runtime error', () => diagnosticsOf(uri, 'Phasebook preview')[0]);
    // The first line of the cell's code (its fence is on line 20).
    expect(found.range.start.line).to.equal(21);
    expect(found.message).to.match(/^SyntaxError: .*JSON/);
  });

  it('passes the template chapter\'s own check, which simulates the pendulum', async () => {
    const { theoryTests } = await extensionApi();
    const verdicts = await theoryTests.verdicts(workspaceFile('content/pendulum.mdx'));
    expect(verdicts.get('periodCheck')).to.deep.include({ outcome: 'passed' });
    expect(verdicts.get('periodCheck')!.message).to.match(/^Period of the pendulum: measured 3\.19\d+, predicted 3\.19\d+.*: agrees$/);
  });

  it('runs every check of the workspace in one preview, not one per chapter', async () => {
    const { theoryTests, previews } = await extensionApi();
    await vscode.window.tabGroups.close(previewTabs());
    await waitFor('the previews to close', () => previewTabs().length === 0 && !previews.get(workspaceFile('content/checks.mdx')));
    const stalled = theoryTests.controller.items.get(workspaceFile('content/stalled.mdx').toString())!;
    // The exercises run without a preview (exercises.test.ts runs them).
    const exercises: vscode.TestItem[] = [];
    theoryTests.controller.items.forEach((chapter) => exercises.push(...children(chapter).filter((c) => c.label === 'Exercises')));
    const panels = new Set<vscode.WebviewPanel>();
    const opened = previews.onDidOpen((preview) => panels.add(preview.panel));
    let outcomes: string[];
    try {
      // Every check but the one that never settles (the next test's): no item included means all.
      outcomes = await recordRun(theoryTests.controller, () =>
        theoryTests.profile.runHandler(new vscode.TestRunRequest(undefined, [stalled, ...exercises]), new vscode.CancellationTokenSource().token),
      );
    } finally {
      opened.dispose();
    }
    // The checks chapter, the pendulum, and the chapter the New chapter test made from the template.
    expect(outcomes.filter((o) => !o.startsWith('started') && o !== 'end').sort()).to.deep.equal([
      `failed Pi, roughly: expected ${Math.PI} ± 1 %, actual 3, at line 10`,
      'passed Period of the pendulum',
      'passed Period of the pendulum',
      'passed Two plus two',
    ]);
    expect(panels.size, 'webview panels the run opened').to.equal(1);
    expect(previewTabs(), 'preview tabs after the run').to.have.length(1);
  });

  it('fails a check that has no verdict within its time limit, saying so', async () => {
    const { theoryTests } = await extensionApi();
    const stalled = theoryTests.controller.items.get(workspaceFile('content/stalled.mdx').toString())!;
    const limit = theoryTests.timeoutMs;
    theoryTests.timeoutMs = 3000;
    let outcomes: string[];
    try {
      outcomes = await recordRun(theoryTests.controller, () =>
        theoryTests.profile.runHandler(new vscode.TestRunRequest([stalled]), new vscode.CancellationTokenSource().token),
      );
    } finally {
      theoryTests.timeoutMs = limit;
    }
    expect(outcomes).to.deep.equal([
      'started A simulation that never ends',
      'failed A simulation that never ends: The check had no verdict after 3 s, its time limit: its cell had not finished., at line 6',
      'end',
    ]);
  });
});
