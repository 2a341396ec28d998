import { expect } from 'chai';
import * as vscode from 'vscode';
import { diagnosticsOf, extensionApi, waitFor, workspaceFile } from './support.ts';

const children = (item: vscode.TestItem) => {
  const found: vscode.TestItem[] = [];
  item.children.forEach((child) => found.push(child));
  return found;
};

/**
 * What a test run reports, recorded: the controller's runs are wrapped while `act` runs, since
 * an extension cannot read test results back from VS Code.
 */
async function recordRun(controller: vscode.TestController, act: () => Thenable<void> | void): Promise<string[]> {
  const outcomes: string[] = [];
  const create = controller.createTestRun;
  const first = (message: vscode.TestMessage | readonly vscode.TestMessage[]) => (Array.isArray(message) ? message[0] : message) as vscode.TestMessage;
  controller.createTestRun = (...args) => {
    const run = create.apply(controller, args);
    return {
      ...run,
      token: run.token,
      started: (item) => (outcomes.push(`started ${item.label}`), run.started(item)),
      passed: (item, duration) => (outcomes.push(`passed ${item.label}`), run.passed(item, duration)),
      failed: (item, message, duration) => {
        const m = first(message);
        outcomes.push(`failed ${item.label}: expected ${m.expectedOutput}, actual ${m.actualOutput}, at line ${m.location?.range.start.line}`);
        run.failed(item, message, duration);
      },
      errored: (item, message, duration) => (outcomes.push(`errored ${item.label}: ${first(message).message}`), run.errored(item, message, duration)),
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

describe('theory checks in the Test Explorer', () => {
  before(extensionApi);

  it("lists each chapter's theory checks, by label, at their cells", async () => {
    const { theoryTests } = await extensionApi();
    const items = theoryTests.controller.items;
    const pendulum = await waitFor('the pendulum chapter', () => items.get(workspaceFile('content/pendulum.mdx').toString()));
    expect(pendulum.label).to.equal('The pendulum');
    expect(children(pendulum).map((c) => c.label)).to.deep.equal(['Period of the pendulum']);
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
});
