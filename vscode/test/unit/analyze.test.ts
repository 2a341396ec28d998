import { readdirSync } from 'node:fs';
import path from 'node:path';
import { beforeAll, describe, expect, test } from 'vitest';
import { analyzeChapter } from '../../src/analyzer/analyze.ts';
import type { Problem } from '../../src/analyzer/problems.ts';
import { readBook, readFixture, realBuiltins, ROOT } from './support.ts';

let builtins: Set<string>;
beforeAll(() => {
  builtins = realBuiltins();
});

/** A problem as `code line:character-line:character`, lines and characters from 0. */
function where(text: string, problem: Problem): string {
  const at = (offset: number) => {
    const before = text.slice(0, offset).split('\n');
    return `${before.length - 1}:${before.at(-1)!.length}`;
  };
  return `${problem.code} ${at(problem.start)}-${at(problem.end)}`;
}

describe('analyzeChapter(text, builtins)', () => {
  test('reports each problem of the broken fixture at its place', () => {
    const text = readFixture('broken.mdx');
    const { problems, cells } = analyzeChapter(text, builtins);
    expect(problems.map((p) => where(text, p))).toEqual([
      'front-matter 0:0-0:3',
      'duplicate-name 9:0-9:9',
      'duplicate-name 13:0-13:9',
      'cell-syntax 17:12-17:13',
      'unnamed-cell 21:0-21:5',
      'unknown-name 25:7-25:12',
    ]);
    expect(cells.map((c) => c.id)).toEqual(['omega', 'omega-dup2', 'cell-3', 'cell-4', 'typo', 'fine']);
  });

  test('says what is wrong in words, with the parser\'s own message for a syntax error', () => {
    const { problems } = analyzeChapter(readFixture('broken.mdx'), builtins);
    const byCode = Object.fromEntries(problems.map((p) => [p.code, p]));
    expect(byCode['front-matter'].message).toMatch(/no `description`/);
    expect(byCode['cell-syntax'].message).toBe('SyntaxError: Unexpected end of input (1:13)');
    expect(byCode['unknown-name'].message).toMatch(/`omeqa` is not defined/);
    expect(byCode['unnamed-cell'].severity).toBe('warning');
    expect(byCode['duplicate-name'].related?.[0]).toMatchObject({ message: '`omega` is also defined here' });
  });

  test('builtins, Math by name, width and invalidation are not unknown names', () => {
    const text = '---\ntitle: t\ndescription: d\norder: 1\n---\n\n```js cell\nx = simulator({ invalidation, width }) && sin(PI) + now + visibility\n```\n';
    expect(analyzeChapter(text, builtins).problems).toEqual([]);
  });

  test('a cell in a list item is placed at its indented position', () => {
    const text = '---\ntitle: t\ndescription: d\norder: 1\n---\n\n- Try this:\n\n  ```js cell\n\n  y = nope + 1\n  ```\n';
    const problem = analyzeChapter(text, builtins).problems[0];
    expect(where(text, problem)).toBe('unknown-name 10:6-10:10');
  });

  test('an MDX syntax error fails the build: reported at its place, the cells still found', () => {
    const text = '---\ntitle: t\ndescription: d\norder: 1\n---\n\nA stray {brace + } here.\n\n```js cell\nz = 1\n```\n';
    const analysis = analyzeChapter(text, builtins);
    expect(analysis.problems.map((p) => where(text, p))).toEqual(['mdx-syntax 6:17-6:18']);
    expect(analysis.problems[0].message).toMatch(/^MDX: /);
    expect(analysis.cells.map((c) => c.name)).toEqual(['z']);
  });

  test('front matter: none, invalid YAML, and an order that is not a whole number', () => {
    expect(analyzeChapter('Just text.\n', builtins).problems[0]).toMatchObject({ code: 'front-matter', start: 0, end: 10 });
    const yaml = analyzeChapter('---\ntitle: [unclosed\n---\n', builtins).problems[0];
    expect(yaml).toMatchObject({ code: 'front-matter' });
    expect(yaml.message).toMatch(/^Front matter is not valid YAML/);
    const text = '---\ntitle: t\ndescription: d\norder: 2.5\n---\n';
    const order = analyzeChapter(text, builtins);
    expect(order.problems.map((p) => where(text, p))).toEqual(['front-matter 3:0-3:10']);
    expect(order.problems[0].message).toMatch(/integer/);
    expect(order.frontMatter.order).toBeNull();
  });

  test('keeps a valid order for the workspace check even when another field is wrong', () => {
    const { frontMatter } = analyzeChapter('---\ntitle: 3\norder: 12\n---\n', builtins);
    expect(frontMatter.order).toMatchObject({ value: 12 });
    expect(frontMatter.title).toBeNull();
  });

  test('bad input never throws', () => {
    for (const text of ['', '---', '---\n---\n', '```js cell\n', '```js cell\n)))\n```\n', '\u0000{<', '---\n: :\n---\n{']) {
      expect(() => analyzeChapter(text, builtins)).not.toThrow();
    }
  });

  test('the book\'s chapters and template have no errors (only unnamed cells, which some chapters leave)', () => {
    const files = [...readdirSync(path.join(ROOT, 'content')).map((f) => `content/${f}`), 'templates/chapter.mdx'];
    for (const file of files) {
      const problems = analyzeChapter(readBook(file), builtins).problems.filter((p) => p.code !== 'unnamed-cell');
      expect(problems, file).toEqual([]);
    }
  });
});
