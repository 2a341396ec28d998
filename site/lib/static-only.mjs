/**
 * Astro integration: what the build leaves in its output folder is only what
 * a static host serves. Astro's static build renders the pages with server
 * code that it writes beside them (`chunks/*.mjs`, `content-*.mjs`, and the
 * content schemas in `collections/` when the output folder is not dist/);
 * the Pages workflow would publish all of it. The pages never load a `.mjs`
 * file — the browser's modules are `.js` under `_astro/` — so those go, with
 * the schemas and the folders they leave empty.
 */
import { readdir, rm, rmdir } from 'node:fs/promises';
import { join, relative, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

/** A file of the output that is the build's server side, by its path from the output folder. */
export function isServerOutput(path) {
  const parts = path.split(/[\\/]/);
  if (parts[0] === '_astro') return false;
  return path.endsWith('.mjs') || (parts[0] === 'collections' && path.endsWith('.schema.json'));
}

/** Removes the server's files under `root`, then the folders left empty; returns the paths removed. */
async function removeServerOutput(root, dir = root) {
  const removed = [];
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) {
      removed.push(...(await removeServerOutput(root, path)));
      if ((await readdir(path)).length === 0) await rmdir(path);
    } else if (isServerOutput(relative(root, path).split(sep).join('/'))) {
      await rm(path);
      removed.push(relative(root, path));
    }
  }
  return removed;
}

/** @returns {import('astro').AstroIntegration} */
export function staticOnly() {
  return {
    name: 'phasebook:static-only',
    hooks: {
      'astro:build:done': async ({ dir, logger }) => {
        const removed = await removeServerOutput(fileURLToPath(dir));
        logger.info(`${removed.length} file(s) of Astro's server code removed from the output`);
      },
    },
  };
}
