#!/usr/bin/env node
/** `npm run build:cli` and `prepare`: compiles the CLI into build/cli/ afresh. */
import { relative } from 'node:path';
import { buildCli, ROOT } from './cli-bundle.mjs';

const start = performance.now();
try {
  const entry = await buildCli({ clean: true });
  console.log(`phasebook: CLI compiled to ${relative(ROOT, entry)} in ${Math.round(performance.now() - start)} ms`);
} catch (error) {
  // esbuild's own report lists every error with its file and line.
  console.error(`phasebook: compiling the CLI failed\n${error?.message ?? error}`);
  // At `npm install` a failed CLI build must not stop the book's setup: bin/phasebook.mjs rebuilds or falls back to tsx.
  if (process.env.npm_lifecycle_event !== 'prepare') process.exitCode = 1;
}
