import { expect } from 'chai';
import * as vscode from 'vscode';
import { diagnosticsOf, extensionApi, waitFor, workspaceFile } from './support.ts';

const children = (item: vscode.TestItem) => {
  const found: vscode.TestItem[] = [];
  item.children.forEach((child) => found.push(child));
  return found;
};

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
