#!/usr/bin/env node
/**
 * `phasebook`: runs the compiled CLI (build/cli/, see cli-bundle.mjs), which
 * starts in about the time Node itself does. When the bundle is missing or
 * older than its TypeScript sources — a developer edited them — it is rebuilt
 * first (a fraction of a second), so an edit never runs stale code. Only if
 * that build cannot be made (no esbuild, a read-only install) does tsx compile
 * the TypeScript in-process, as slowly as before but still correct.
 */
import { pathToFileURL } from 'node:url';
import { buildCli, freshEntry } from './cli-bundle.mjs';

async function loadMain() {
  let entry = freshEntry();
  if (!entry) {
    try {
      // The bundle esbuild has just made from the sources as they are now; a file saved while it ran makes the next run rebuild.
      entry = await buildCli();
    } catch {
      // A syntax error in the sources lands here too; tsx then reports it with its position.
    }
  }
  if (entry) return import(pathToFileURL(entry).href);
  const { register } = await import('tsx/esm/api');
  register();
  return import('../cli/main.ts');
}

const { main } = await loadMain();
process.exitCode = await main(process.argv.slice(2));
