/** Shared by the unit tests: the book's folders, its fixtures, and the builtins' names from the real catalogue. */
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { builtinNames } from '../../src/analyzer/builtin-names.ts';
import type { Catalogue } from '../../src/analyzer/catalogue.ts';
import { generateCatalogue } from '../../build/catalogue.ts';

export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');

export function readFixture(name: string): string {
  return readFileSync(path.join(ROOT, 'vscode/test/fixtures/book/content', name), 'utf8');
}

export function readBook(relative: string): string {
  return readFileSync(path.join(ROOT, relative), 'utf8');
}

let catalogue: Catalogue | undefined;

/** The catalogue generated from widgets/catalogue.ts (a TypeScript program: a couple of seconds, once per file). */
export function realCatalogue(): Catalogue {
  return (catalogue ??= generateCatalogue(ROOT));
}

export function realBuiltins(): Set<string> {
  return builtinNames(realCatalogue());
}
