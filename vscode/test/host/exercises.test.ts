import { expect } from 'chai';
import * as vscode from 'vscode';
import { children, extensionApi, recordRun, waitFor, workspaceFile } from './support.ts';

/** A chapter's "Exercises" group in the Test Explorer, once the index has it. */
async function exercisesOf(relative: string): Promise<vscode.TestItem> {
  const { theoryTests } = await extensionApi();
  const id = workspaceFile(relative).toString();
  return waitFor(`the exercises of ${relative}`, () => {
    const chapter = theoryTests.controller.items.get(id);
    return chapter && children(chapter).find((c) => c.label === 'Exercises');
  });
}

/** The (0-based) line of the first line of `path` that holds `text`. */
async function lineWith(path: string, text: string): Promise<number> {
  const document = await vscode.workspace.openTextDocument(workspaceFile(path));
  return document.getText().split('\n').findIndex((line) => line.includes(text));
}

describe('exercises in the Test Explorer', () => {
  before(extensionApi);

  it("lists a chapter's exercises beside its theory checks: title, kind, the fence's lines", async () => {
    // content/pendulum.mdx is the book's template (the driver copies it there).
    const group = await exercisesOf('content/pendulum.mdx');
    const fence = await lineWith('content/pendulum.mdx', '```exercise');
    expect(children(group).map((c) => [c.label, c.description])).to.deep.equal([
      ['The period at a large swing', 'Predict, then check'],
      ['Just over the top', 'Find it'],
      ['A faster pendulum', 'Write code'],
    ]);
    expect(children(group)[0].range?.start.line).to.equal(fence);
    expect(children(group)[0].range?.end.line).to.be.greaterThan(fence + 10);
  });

  it("runs the template's exercises in the extension host: each answer key holds", async () => {
    const { theoryTests } = await extensionApi();
    const group = await exercisesOf('content/pendulum.mdx');
    const outcomes = await recordRun(theoryTests.controller, () =>
      theoryTests.profile.runHandler(new vscode.TestRunRequest([group]), new vscode.CancellationTokenSource().token),
    );
    expect(outcomes).to.deep.equal([
      'started The period at a large swing',
      'passed The period at a large swing',
      'started Just over the top',
      'passed Just over the top',
      'started A faster pendulum',
      'passed A faster pendulum',
      'end',
    ]);
  });

  it('fails an answer key that lets a wrong answer through, at that answer, and a declaration that does not parse, at its fence', async () => {
    const { theoryTests } = await extensionApi();
    const group = await exercisesOf('content/exercises.mdx');
    const path = 'content/exercises.mdx';
    const [six, constant, unfinished] = await Promise.all([lineWith(path, '"value": 6,'), lineWith(path, '"mistakes": ["p^2/2 + 2*q^2"'), lineWith(path, '"id": "no-solution"')]);
    const outcomes = await recordRun(theoryTests.controller, () =>
      theoryTests.profile.runHandler(new vscode.TestRunRequest([group]), new vscode.CancellationTokenSource().token),
    );
    expect(outcomes.filter((o) => !o.startsWith('started'))).to.deep.equal([
      'passed The period of a spring',
      `failed A tolerance too loose: The wrong answer 6 is within the tolerance of the truth 6.28319 (± 0.628319): the page would call it right. Tighten the tolerance, or drop this mistake., at line ${six}`,
      `failed Checks that miss a mistake: The wrong H “p^2/2 + q^2/2 + 1” passes every check: the checks cannot tell it from the reference “p^2/2 + q^2/2”. Add a check that does., at line ${constant}`,
      // At the opening fence, two lines above the id.
      `failed Exercise 4: The declaration does not parse: "solution", the worked solution, is needed., at line ${unfinished - 2}`,
      'end',
    ]);
  });

  it('follows edits: an exercise renamed, removed, added', async () => {
    const uri = workspaceFile('content/exercises.mdx');
    const group = await exercisesOf('content/exercises.mdx');
    const labels = () => children(group).map((c) => c.label).join(' | ');
    const editor = await vscode.window.showTextDocument(uri);
    const original = editor.document.getText();
    const whole = () => new vscode.Range(editor.document.positionAt(0), editor.document.positionAt(editor.document.getText().length));
    const set = (text: string) => editor.edit((edit) => edit.replace(whole(), text));
    try {
      await set(original.replace('"title": "A tolerance too loose"', '"title": "Too loose"'));
      await waitFor('the new title', () => labels() === 'The period of a spring | Too loose | Checks that miss a mistake | Exercise 4');
      const unfinished = original.slice(original.lastIndexOf('```exercise'));
      await set(original.replace(unfinished, ''));
      await waitFor('the removed exercise to go', () => labels() === 'The period of a spring | A tolerance too loose | Checks that miss a mistake');
      await set(`${original}\n${original.slice(original.indexOf('```exercise'), original.indexOf('```\n', original.indexOf('```exercise') + 3) + 4).replace('harmonic-period', 'harmonic-period-again').replace('The period of a spring', 'Again')}`);
      await waitFor('the added exercise', () => labels() === 'The period of a spring | A tolerance too loose | Checks that miss a mistake | Exercise 4 | Again');
    } finally {
      await set(original);
      await vscode.commands.executeCommand('workbench.action.files.save');
    }
    await waitFor('the exercises as they were', () => labels() === 'The period of a spring | A tolerance too loose | Checks that miss a mistake | Exercise 4');
  });
});
