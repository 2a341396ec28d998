import { expect } from 'chai';
import * as vscode from 'vscode';
import { askDriver } from '../driver-protocol.ts';
import { extensionApi, nextMessage, pause, waitFor, workspaceFile } from './support.ts';

describe('the live preview', () => {
  const uri = workspaceFile('content/pendulum.mdx');
  before(extensionApi);

  it('renders the chapter with its cells running: the simulator settles', async () => {
    const { previews } = await extensionApi();
    await vscode.window.showTextDocument(uri, { viewColumn: vscode.ViewColumn.One });
    await vscode.commands.executeCommand('phasebook.openPreview', uri);
    const preview = previews.get(uri)!;
    expect(preview, 'the preview of pendulum.mdx').not.to.equal(undefined);
    const report = await nextMessage(preview, 'cells', (m) => m.cells.find((c) => c.id === 'pendulumSimulator')?.state === 'fulfilled' && m.cells.every((c) => c.state !== 'pending'));
    expect(report.cells.map((c) => [c.id, c.state])).to.deep.equal([
      ['pendulum', 'fulfilled'], ['pendulumH', 'fulfilled'], ['pendulumStart', 'fulfilled'], ['pendulumModel', 'fulfilled'],
      ['pendulumEquations', 'fulfilled'], ['pendulumSimulator', 'fulfilled'], ['periodCheck', 'fulfilled'], ['myPendulum', 'fulfilled'],
    ]);
    const lines = preview.document.getText().split('\n');
    const fence = lines.indexOf('pendulumSimulator = simulator({') - 1;
    expect(report.cells.find((c) => c.id === 'pendulumSimulator')).to.deep.include({ line: fence, endLine: lines.indexOf('```', fence + 1) });
  });

  it('keeps every cell (and its widget) when only prose changes', async () => {
    const { previews } = await extensionApi();
    const preview = previews.get(uri)!;
    const editor = await vscode.window.showTextDocument(uri, { viewColumn: vscode.ViewColumn.One });
    const line = editor.document.getText().split('\n').findIndex((l) => l.startsWith('A pendulum swings'));
    const version = editor.document.version;
    const rendered = nextMessage(preview, 'rendered', (m) => m.version > version);
    await editor.edit((edit) => edit.insert(new vscode.Position(line, 0), 'Indeed, '));
    const report = await rendered;
    expect(report).to.deep.include({ created: [], changed: [], removed: [] });
    expect(report.kept).to.include.members(['pendulumSimulator', 'periodCheck']);
  });

  it('redefines only the cell whose code changed; the others keep their elements', async () => {
    const { previews } = await extensionApi();
    const preview = previews.get(uri)!;
    const editor = await vscode.window.showTextDocument(uri, { viewColumn: vscode.ViewColumn.One });
    const offset = editor.document.getText().indexOf('({omega0: 2})');
    const range = new vscode.Range(editor.document.positionAt(offset), editor.document.positionAt(offset + '({omega0: 2})'.length));
    const rendered = nextMessage(preview, 'rendered', (m) => m.changed.length > 0);
    await editor.edit((edit) => edit.replace(range, '({omega0: 3})'));
    const report = await rendered;
    expect(report).to.deep.include({ created: [], changed: ['pendulum'], removed: [] });
    expect(report.kept).to.include('pendulumSimulator');
  });

  it('runs a cell from its CodeLens command and reports its result', async () => {
    const { previews } = await extensionApi();
    const preview = previews.get(uri)!;
    // Cells report only when their state changes: a report after the command is the cell running again.
    const ran = nextMessage(preview, 'cells', (m) => m.cells.find((c) => c.id === 'pendulumEquations')?.state === 'fulfilled', 20_000);
    await vscode.commands.executeCommand('phasebook.runCell', uri, 'pendulumEquations');
    await ran;
  });

  it('scrolls the editor as the preview is scrolled, and the preview as the editor is', async () => {
    const { previews } = await extensionApi();
    const preview = previews.get(uri)!;
    const editor = await vscode.window.showTextDocument(uri, { viewColumn: vscode.ViewColumn.One });
    const lines = editor.document.getText().split('\n');
    const checkFence = lines.indexOf('periodCheck = {') - 1;
    const modelFence = lines.indexOf('pendulumModel = canonicalEquations({') - 1;
    // An editor revealing a line at its top keeps a few lines above it (under its sticky headings).
    const near = (line: number, target: number) => target - 6 <= line && line <= target + 2;

    // The reader scrolls the preview to the check, again if need be: on a busy machine the preview may still be
    // settling from the edits before (a re-render puts back its scroll position). A broken sync never follows.
    const follows = () => near(editor.visibleRanges[0].start.line, checkFence);
    for (let attempt = 1; !follows(); attempt++) {
      askDriver('scroll-to-cell periodCheck');
      try {
        await waitFor(`the editor to show line ${checkFence} at its top`, follows, 10_000);
      } catch (error) {
        if (attempt === 4) throw error;
      }
    }

    await pause(400);
    const reported = nextMessage(preview, 'scrolled');
    editor.revealRange(new vscode.Range(modelFence, 0, modelFence, 0), vscode.TextEditorRevealType.AtTop);
    // The preview follows (and ignores its own scrolling); nudged, it reports the line at its top.
    await pause(600);
    askDriver('nudge');
    const { line } = await reported;
    expect(near(line, modelFence), `the preview's top line ${line}, the editor's ${modelFence}`).to.equal(true);
  });

  it('is left in front, its simulator running, for the driver to read its canvases', async () => {
    const { previews } = await extensionApi();
    const preview = await previews.open(uri);
    expect(preview.panel.visible).to.equal(true);
  });
});
