import { expect } from 'chai';
import * as vscode from 'vscode';
import { diagnosticsOf, extensionApi, waitFor, workspaceFile } from './support.ts';

describe('Phasebook: New chapter', () => {
  before(extensionApi);

  it('copies the template into content/ with the title given and the next free order', async () => {
    // VS Code for the web may offer no file search (it found no template there): the command must not need it.
    const workspace = vscode.workspace as unknown as { findFiles: typeof vscode.workspace.findFiles };
    const findFiles = workspace.findFiles;
    const searched: string[] = [];
    workspace.findFiles = async (include) => (searched.push(String(include)), []);
    let uri: vscode.Uri;
    try {
      uri = await vscode.commands.executeCommand<vscode.Uri>('phasebook.newChapter', { title: 'Waves on a string' });
    } finally {
      workspace.findFiles = findFiles;
    }
    expect(searched, 'file searches').to.deep.equal([]);
    expect(uri, 'the new chapter').not.to.equal(undefined);
    expect(uri.toString()).to.equal(workspaceFile('content/waves-on-a-string.mdx').toString());
    const text = new TextDecoder().decode(await vscode.workspace.fs.readFile(uri));
    const template = new TextDecoder().decode(await vscode.workspace.fs.readFile(workspaceFile('templates/chapter.mdx')));
    // Orders 7, 8, 50 and 60 are taken in the test workspace: 1 is the first free one.
    expect(text).to.equal(template.replace(/^title: .*$/m, 'title: "Waves on a string"').replace(/^order: .*$/m, 'order: 1'));
    expect(vscode.window.activeTextEditor?.document.uri.toString()).to.equal(uri.toString());
  });

  it('gives the new chapter no problems, and does not overwrite a chapter', async () => {
    const api = await extensionApi();
    const uri = workspaceFile('content/waves-on-a-string.mdx');
    await waitFor('the new chapter to be analysed', () => api.index.known(uri));
    expect(diagnosticsOf(uri, 'Phasebook')).to.deep.equal([]);
    expect(await vscode.commands.executeCommand('phasebook.newChapter', { title: 'Waves on a string' })).to.equal(undefined);
  });
});
