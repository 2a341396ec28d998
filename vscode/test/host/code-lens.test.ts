import { expect } from 'chai';
import * as vscode from 'vscode';
import { extensionApi, workspaceFile } from './support.ts';

describe('CodeLens', () => {
  before(extensionApi);

  it('puts Run cell and Run all above each cell, naming the cell', async () => {
    const uri = workspaceFile('content/pendulum.mdx');
    const document = await vscode.workspace.openTextDocument(uri);
    const lenses = await vscode.commands.executeCommand<vscode.CodeLens[]>('vscode.executeCodeLensProvider', uri);
    const fences = document.getText().split('\n').flatMap((line, i) => (line.startsWith('```js cell') ? [i] : []));
    expect(fences).to.have.length(8);
    expect(lenses.map((l) => `${l.range.start.line} ${l.command?.title}`)).to.deep.equal(fences.flatMap((line) => [`${line} $(play) Run cell`, `${line} Run all`]));
    expect(lenses[0].command).to.deep.include({ command: 'phasebook.runCell' });
    expect(lenses[0].command?.arguments?.map(String)).to.deep.equal([uri.toString(), 'pendulum']);
    expect(lenses[1].command?.command).to.equal('phasebook.runAll');
  });

  it('follow the cells as they are added', async () => {
    const document = await vscode.workspace.openTextDocument({ language: 'mdx', content: 'Text.\n' });
    const before = await vscode.commands.executeCommand<vscode.CodeLens[]>('vscode.executeCodeLensProvider', document.uri);
    expect(before).to.have.length(0);
    const edit = new vscode.WorkspaceEdit();
    edit.insert(document.uri, new vscode.Position(1, 0), '\n```js cell\nx = 1\n```\n');
    await vscode.workspace.applyEdit(edit);
    const after = await vscode.commands.executeCommand<vscode.CodeLens[]>('vscode.executeCodeLensProvider', document.uri);
    expect(after.map((l) => l.range.start.line)).to.deep.equal([2, 2]);
  });
});
