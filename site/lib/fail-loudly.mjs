/**
 * Astro integration: a build whose chapters have problems with their cells
 * (cell-failures.ts) fails, listing every one, a line each, on stderr.
 *
 * The check runs when Vite has compiled every chapter, before a page is
 * written, so a broken book is never published. The dev server prints the
 * same lines as a chapter is compiled, and keeps serving: the page shows the
 * failure under the cell.
 */
import { recordedProblems, onChapterReport } from './cell-failures.ts';

/** @returns {import('astro').AstroIntegration} */
export function failLoudly() {
  return {
    name: 'phasebook:fail-loudly',
    hooks: {
      'astro:config:setup': ({ command, updateConfig }) => {
        if (command !== 'build') return;
        updateConfig({
          vite: {
            plugins: [
              {
                name: 'phasebook:fail-loudly',
                apply: 'build',
                buildEnd(error) {
                  const problems = recordedProblems();
                  if (error || !problems.length) return;
                  for (const line of problems) console.error(line);
                  this.error(`${problems.length} problem(s) with the chapters' cells, listed above, one per line`);
                },
              },
            ],
          },
        });
      },
      'astro:server:setup': ({ logger }) => {
        onChapterReport((_file, problems) => {
          for (const line of problems) logger.warn(line);
        });
      },
    },
  };
}
