import { expect } from 'chai';
import * as vscode from 'vscode';
import { diagnosticsOf, extensionApi, waitFor, workspaceFile } from './support.ts';

describe('Phasebook: New chapter', () => {
  before(extensionApi);

  it('copies the template into content/ with the title given and the next free order', async () => {
    const uri = await vscode.commands.executeCommand<vscode.Uri>('phasebook.newChapter', { title: 'Waves on a string' });
    expect(uri.toString()).to.equal(workspaceFile('content/waves-on-a-string.mdx').toString());
    const text = new TextDecoder().decode(await vscode.workspace.fs.readFile(uri));
    const template = new TextDecoder().decode(await vscode.workspace.fs.readFile(workspaceFile('templates/chapter.mdx')));
    // Orders 7, 8 and 50 are taken in the test workspace: 1 is the first free one.
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
