import { expect } from 'chai';
import * as vscode from 'vscode';
import { extensionApi } from './support.ts';

/** A chapter with the text `before` in a cell, and the position at its end. */
async function cellWith(before: string, after = '\n```\n'): Promise<{ document: vscode.TextDocument; position: vscode.Position }> {
  const head = '---\ntitle: T\ndescription: D\norder: 1\n---\n\n```js cell\npendulumModel = canonicalEquations({dof: 1, hamiltonian: "p^2/2"})\n```\n\n```js cell\n';
  const document = await vscode.workspace.openTextDocument({ language: 'mdx', content: head + before + after });
  return { document, position: document.positionAt(head.length + before.length) };
}

async function complete(before: string, after?: string): Promise<vscode.CompletionItem[]> {
  const { document, position } = await cellWith(before, after);
  const list = await vscode.commands.executeCommand<vscode.CompletionList>('vscode.executeCompletionItemProvider', document.uri, position);
  return list.items;
}

const labelOf = (item: vscode.CompletionItem) => (typeof item.label === 'string' ? item.label : item.label.label);
const docOf = (item: vscode.CompletionItem) => (typeof item.documentation === 'string' ? item.documentation : item.documentation?.value ?? '');

describe('completion and hover', () => {
  before(extensionApi);

  it("offers simulator's options from its TypeScript type, with their docs, leaving out those written", async () => {
    const items = await complete('sim = simulator({ model: pendulumModel, ');
    const options = items.filter((i) => i.kind === vscode.CompletionItemKind.Property);
    const labels = options.map(labelOf);
    expect(labels).to.include.members(['initial', 'views', 'timePlot', 'dt', 'invalidation']);
    expect(labels).not.to.include('model');
    const initial = options.find((i) => labelOf(i) === 'initial')!;
    expect(initial.detail).to.equal('required option of simulator');
    expect(docOf(initial)).to.include('[q…, p…], or a list of them for a batch of trajectories');
  });

  it('offers nested options (timePlot) and a constructor\'s options (new Simulation)', async () => {
    expect((await complete('sim = simulator({ timePlot: { ')).map(labelOf)).to.include('height');
    expect((await complete('run = new Simulation(pendulumModel, { ')).map(labelOf)).to.include.members(['initial', 'dt', 'capacity']);
  });

  it("offers the chapter's other cells and the book's builtins where a name goes", async () => {
    const items = await complete('x = pend');
    const cell = items.find((i) => labelOf(i) === 'pendulumModel')!;
    expect(cell.kind).to.equal(vscode.CompletionItemKind.Variable);
    const simulator = items.find((i) => labelOf(i) === 'simulator')!;
    expect(simulator.detail).to.equal('simulator(options: SimulatorOptions): Promise<SimulatorElement>');
    expect(items.find((i) => labelOf(i) === 'Simulation')?.kind).to.equal(vscode.CompletionItemKind.Class);
    expect(items.map(labelOf)).to.include.members(['theoryCheck', 'invalidation', 'width', 'sin', 'PI']);
  });

  it('offers nothing of its own in a string', async () => {
    const items = await complete("x = simulator({ label: 'a ");
    // VS Code's own word completion and the snippets may still come; our items have details.
    expect(items.filter((i) => i.detail && i.kind !== vscode.CompletionItemKind.Snippet).map((i) => `${labelOf(i)}: ${i.detail}`)).to.deep.equal([]);
  });

  it("offers the extension's snippets: a cell, a simulator, a theory check, front matter", async () => {
    const document = await vscode.workspace.openTextDocument({ language: 'mdx', content: 'Some prose.\n\n' });
    const list = await vscode.commands.executeCommand<vscode.CompletionList>('vscode.executeCompletionItemProvider', document.uri, new vscode.Position(2, 0));
    const snippets = list.items.filter((i) => i.kind === vscode.CompletionItemKind.Snippet);
    expect(snippets.map(labelOf)).to.include.members(['cell', 'simulator', 'theoryCheck', 'frontmatter', 'model']);
    const cell = snippets.find((i) => labelOf(i) === 'cell')!;
    const body = cell.insertText instanceof vscode.SnippetString ? cell.insertText.value : String(cell.insertText);
    expect(body).to.equal('```js cell\n${1:name} = ${2:value}\n```\n$0');
  });

  it('hovers show an option, a builtin, a cell', async () => {
    const { document } = await cellWith('sim = simulator({ model: pendulumModel, views: [] })');
    const hover = async (word: string) => {
      const at = document.positionAt(document.getText().lastIndexOf(word) + 1);
      const hovers = await vscode.commands.executeCommand<vscode.Hover[]>('vscode.executeHoverProvider', document.uri, at);
      return hovers.flatMap((h) => h.contents.map((c) => (typeof c === 'string' ? c : c.value))).join('\n');
    };
    expect(await hover('views')).to.include('(option of simulator) views?: readonly ("time" | "trajectory" | "phase" | "spectrum")[]');
    expect(await hover('simulator')).to.include("simulator({hamiltonian, initial, …}) → Promise of the widget's element");
    expect(await hover('pendulumModel')).to.include('cell `pendulumModel`');
  });
});
