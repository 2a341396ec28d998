import { expect } from 'chai';
import * as vscode from 'vscode';
import { diagnosticsOf, extensionApi, nonEmpty, placeOf, waitFor, workspaceFile } from './support.ts';

describe('diagnostics', () => {
  before(extensionApi);

  it('come for every chapter of the workspace, opened or not', async () => {
    const unopened = workspaceFile('content/unopened.mdx');
    expect(vscode.workspace.textDocuments.some((d) => d.uri.toString() === unopened.toString())).to.equal(false);
    const found = await waitFor('diagnostics of the unopened chapter', () => nonEmpty(diagnosticsOf(unopened, 'Phasebook')));
    expect(found.map(placeOf)).to.deep.equal(['unknown-name 7:8']);
    expect(found[0].message).to.match(/`undefinedSpeed` is not defined/);
  });

  it('report every problem of a broken chapter at its place, with the duplicate order against the pendulum chapter', async () => {
    const uri = workspaceFile('content/broken.mdx');
    await vscode.window.showTextDocument(uri);
    const found = await waitFor('diagnostics of broken.mdx', () => (diagnosticsOf(uri, 'Phasebook').length >= 7 ? diagnosticsOf(uri, 'Phasebook') : undefined));
    expect(found.map(placeOf)).to.deep.equal([
      'front-matter 0:0',
      'duplicate-name 9:0',
      'duplicate-name 13:0',
      'cell-syntax 17:12',
      'unnamed-cell 21:0',
      'unknown-name 25:7',
      'duplicate-order 2:0',
    ]);
    const order = found.find((d) => d.code === 'duplicate-order')!;
    expect(order.relatedInformation?.[0].location.uri.path).to.match(/content\/pendulum\.mdx$/);
    expect(found.find((d) => d.code === 'unnamed-cell')!.severity).to.equal(vscode.DiagnosticSeverity.Warning);
    expect(found.find((d) => d.code === 'unknown-name')!.range.end.character).to.equal(12);
  });

  it('follow the text as it is typed', async () => {
    const uri = workspaceFile('content/broken.mdx');
    const editor = await vscode.window.showTextDocument(uri);
    const typo = new vscode.Range(25, 7, 25, 12);
    expect(editor.document.getText(typo)).to.equal('omeqa');
    await editor.edit((edit) => edit.replace(typo, 'omega'));
    await waitFor('the unknown name to go', () => !diagnosticsOf(uri, 'Phasebook').some((d) => d.code === 'unknown-name'));
    await editor.edit((edit) => edit.replace(typo, 'omeqa'));
    await waitFor('the unknown name to come back', () => diagnosticsOf(uri, 'Phasebook').some((d) => d.code === 'unknown-name'));
  });

  it("take the workspace folder's content/ as the book: the fixtures a fork keeps under vscode/test/ are no chapters", async () => {
    const { index, theoryTests } = await extensionApi();
    const nested = workspaceFile('vscode/test/fixtures/book/content/broken.mdx');
    // The driver lays the fixtures out there, as in a fork: the same files as the book's content/ here.
    expect((await vscode.workspace.fs.stat(nested)).type).to.equal(vscode.FileType.File);
    const inFixtures = (uri: vscode.Uri) => uri.path.includes('/vscode/test/fixtures/');
    expect(index.chapters().filter((c) => inFixtures(c.uri))).to.deep.equal([]);
    expect(index.chapters().map((c) => vscode.workspace.asRelativePath(c.uri))).to.include.members(['content/broken.mdx', 'content/checks.mdx', 'content/unopened.mdx']);
    expect(vscode.languages.getDiagnostics().filter(([uri, found]) => inFixtures(uri) && found.length > 0)).to.deep.equal([]);
    const items: string[] = [];
    theoryTests.controller.items.forEach((item) => items.push(item.id));
    expect(items.filter((id) => id.includes('/vscode/test/fixtures/'))).to.deep.equal([]);
  });
});
