/**
 * A derivation asked of the reader (a "Try it" item that says "show",
 * "deduce", "which… and why") carries a hint and an answer, closed until
 * asked for: `<details class="derivation-hint">` then
 * `<details class="derivation-answer">`, each with a summary and a body
 * (site/styles/global.css; the teachers' page says how to write them).
 * This reads every chapter's MDX as the build does and checks the pairs.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { expect, test } from 'vitest';

const ROOT = resolve(__dirname, '../../..');
const files = [...readdirSync(join(ROOT, 'content')).filter((f) => f.endsWith('.mdx')).map((f) => join('content', f)), 'templates/chapter.mdx'];

interface Block { readonly kind: 'hint' | 'answer'; readonly summary: string; readonly body: string; readonly at: number }

/** The derivation blocks of an MDX text, in order, with the line each opens on. */
export function derivationBlocks(text: string): Block[] {
  const blocks: Block[] = [];
  const open = /<details class="derivation-(hint|answer)">([\s\S]*?)<\/details>/g;
  for (const match of text.matchAll(open)) {
    const inner = match[2];
    const summary = /<summary>([\s\S]*?)<\/summary>/.exec(inner)?.[1].trim() ?? '';
    const body = inner.replace(/<summary>[\s\S]*?<\/summary>/, '').trim();
    blocks.push({ kind: match[1] as Block['kind'], summary, body, at: text.slice(0, match.index).split('\n').length });
  }
  return blocks;
}

test.each(files)('%s: every derivation hint is followed by its answer, each with a summary and a body', (file) => {
  const blocks = derivationBlocks(readFileSync(join(ROOT, file), 'utf8'));
  const problems: string[] = [];
  blocks.forEach((block, i) => {
    if (!block.summary) problems.push(`line ${block.at}: a ${block.kind} without <summary>`);
    if (block.body.length < 20) problems.push(`line ${block.at}: a ${block.kind} with no text to speak of`);
    if (block.kind === 'hint' && blocks[i + 1]?.kind !== 'answer') problems.push(`line ${block.at}: a hint with no answer after it`);
    if (block.kind === 'answer' && blocks[i - 1]?.kind !== 'hint') problems.push(`line ${block.at}: an answer with no hint before it`);
  });
  expect(problems).toEqual([]);
});

test('the pairing check finds an answer missing, a hint missing and an empty body', () => {
  const hint = '<details class="derivation-hint"><summary>Hint</summary>\n\nLook at the tree with four leaves.\n\n</details>';
  const answer = '<details class="derivation-answer"><summary>Answer</summary>\n\nIt is the bushy tree, of order five.\n\n</details>';
  expect(derivationBlocks(hint + answer).map((b) => b.kind)).toEqual(['hint', 'answer']);
  expect(derivationBlocks(answer).map((b) => b.kind)).toEqual(['answer']);
  expect(derivationBlocks('<details class="derivation-hint"><summary>Hint</summary></details>')[0].body).toBe('');
});
