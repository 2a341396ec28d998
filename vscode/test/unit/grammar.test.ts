import { readFileSync } from 'node:fs';
import path from 'node:path';
import { createHighlighter, type Highlighter } from 'shiki';
import { beforeAll, describe, expect, test } from 'vitest';
import { ROOT } from './support.ts';

/** The extension's TextMate grammar, run by Shiki (Astro's highlighter) with VS Code's Markdown, JavaScript and YAML grammars. */
const grammar = JSON.parse(readFileSync(path.join(ROOT, 'vscode/syntaxes/phasebook-mdx.tmLanguage.json'), 'utf8'));
let highlighter: Highlighter;

beforeAll(async () => {
  highlighter = await createHighlighter({
    themes: ['github-dark'],
    langs: ['markdown', 'javascript', 'yaml', { ...grammar, name: 'phasebook-mdx', embeddedLangs: ['markdown', 'javascript', 'yaml'] }],
  });
});

/** The scopes of the token that holds `text` on line `line` (from 0). */
function scopesOf(source: string, line: number, text: string): string[] {
  // A language of our own, unknown to Shiki's list of bundled ones.
  // No time limit per line: Shiki's default, 500 ms, cut a line's tokens short on a loaded machine, where the
  // first line also pays for compiling the grammars' expressions, and the token looked for was then missing.
  const tokens = highlighter.codeToTokensBase(source, { lang: 'phasebook-mdx' as never, theme: 'github-dark', includeExplanation: true, tokenizeTimeLimit: 0 });
  const token = tokens[line].find((t) => t.content.includes(text));
  if (!token) throw new Error(`no token with ${text} on line ${line}: ${tokens[line].map((t) => t.content).join('|')}`);
  return token.explanation!.flatMap((e) => e.scopes.map((s) => s.scopeName));
}

describe('phasebook-mdx.tmLanguage.json', () => {
  const chapter = ['---', 'title: Waves', '---', '', 'Some *prose*.', '', '```js cell', 'osc = simulator({ model, initial: [1, 0] })', '```', '', '{/* a note */}'].join('\n');

  test('a js cell fence is JavaScript inside', () => {
    expect(scopesOf(chapter, 7, 'simulator')).toEqual(expect.arrayContaining(['markup.fenced_code.block.cell.phasebook', 'meta.embedded.block.javascript', 'entity.name.function.js']));
    expect(scopesOf(chapter, 6, 'cell')).toContain('fenced_code.block.language.attributes.markdown');
  });

  test('front matter is YAML, prose is Markdown, MDX comments are comments', () => {
    expect(scopesOf(chapter, 1, 'title')).toEqual(expect.arrayContaining(['meta.embedded.block.frontmatter', 'entity.name.tag.yaml']));
    expect(scopesOf(chapter, 4, 'prose')).toContain('markup.italic.markdown');
    expect(scopesOf(chapter, 10, 'a note')).toContain('comment.block.mdx');
  });

  test('a fence that is not a cell is left to Markdown', () => {
    const source = '```js\nx = 1\n```\n';
    expect(scopesOf(source, 1, 'x')).not.toContain('markup.fenced_code.block.cell.phasebook');
  });
});
