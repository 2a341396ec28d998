/**
 * templates/chapter.mdx, the chapter teachers copy into content/: its front
 * matter has the fields site/content.config.ts requires, and every code cell
 * parses, so a copy builds and runs as it stands. (The page /for-teachers/
 * renders the template live, so the e2e suite runs its cells too.)
 */
import { readFileSync } from 'node:fs';
import { parseCell } from '@observablehq/parser';
import { describe, expect, it } from 'vitest';

const source = readFileSync(new URL('../../../templates/chapter.mdx', import.meta.url), 'utf8');

/** The `key: value` lines of the front matter, with YAML comments and blank lines left out. */
function frontMatter(text: string): Record<string, string> {
  const match = /^---\n([\s\S]*?)\n---\n/.exec(text);
  if (!match) throw new Error('no front matter');
  const fields: Record<string, string> = {};
  for (const line of match[1].split('\n')) {
    if (/^\s*(#|$)/.test(line)) continue;
    const field = /^([A-Za-z_]\w*):\s*(.*?)\s*(?:\s#.*)?$/.exec(line);
    if (!field) throw new Error(`not a "key: value" line: ${line}`);
    fields[field[1]] = field[2].replace(/^(["'])(.*)\1$/, '$2');
  }
  return fields;
}

/** The sources of the ```js cell blocks, as site/lib/remark-cells.mjs finds them. */
function cells(text: string): string[] {
  const found: string[] = [];
  const fence = /^```js[ \t]+([^\n]*)\n([\s\S]*?)^```[ \t]*$/gm;
  for (const [, meta, body] of text.matchAll(fence)) {
    if (meta.split(/\s+/).includes('cell')) found.push(body.replace(/^\n+/, '').trimEnd());
  }
  return found;
}

describe('templates/chapter.mdx', () => {
  it('has the required front matter: title, a one-sentence description and an integer order', () => {
    const fields = frontMatter(source);
    expect(fields.title).toBeTruthy();
    expect(fields.description).toMatch(/^[A-Z].*\.$/);
    expect(fields.description.split(/[.!?](\s|$)/).filter((s) => s.trim()).length).toBe(1);
    expect(fields.order).toMatch(/^\d+$/);
  });

  it('has a model, a simulator, a theory check and exercises', () => {
    expect(source).toContain('canonicalEquations(');
    expect(source).toContain('equations(');
    expect(source).toContain('simulator(');
    expect(source).toContain('theoryCheck(');
    expect(source).toMatch(/^## Try it$/m);
    expect(source).toMatch(/\$\$[\s\S]+?\$\$/);
  });

  it('has code cells that all parse, each with its own name', () => {
    const sources = cells(source);
    expect(sources.length).toBeGreaterThanOrEqual(6);
    const names = sources.map((cell) => {
      const parsed = parseCell(cell);
      // Named cells keep a reader's saved edit when cells are added or moved (see the template).
      expect(parsed.id?.name, cell).toBeTruthy();
      return parsed.id.name as string;
    });
    expect(new Set(names).size).toBe(names.length);
  });

  it('links to other chapters relatively (../name/), which resolves under any base path and in any preview', () => {
    const links = [...source.matchAll(/\]\(([^)\s]+)\)/g)].map((m) => m[1]);
    expect(links).toContain('../introduction/');
    expect(links.filter((url) => url.startsWith('/') && !url.startsWith('//'))).toEqual([]);
  });
});
