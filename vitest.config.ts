import { availableParallelism } from 'node:os';
import { defineConfig } from 'vitest/config';

/**
 * Unit tests only: tests/e2e/ holds node:test files that drive a browser
 * against the built site (`npm run test:e2e`), which vitest must not pick up.
 */
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.{ts,mjs}'],
    // One temporary folder for the run, removed at its end (tests/unit/support/scratch-root.ts).
    globalSetup: ['tests/unit/support/scratch-root.ts'],
    // One limit for every test and hook, set nowhere else: a guard against a hang, not a measure of speed
    // (that is the bench's). The slowest test takes about 10 s of CPU on a quiet machine (a first model
    // compiled with mathjs, CLI runs in child processes); the limit leaves room for a machine four times
    // as loaded, and more.
    testTimeout: 120_000,
    hookTimeout: 120_000,
    // Two test files at a time at least. Vitest's default, one fewer than the cores, is one on a two-core machine,
    // where many files spend their time waiting on the CLI in a child process (and, in npm test, on the cores the
    // browsers hold): the second file fills that wait.
    maxWorkers: Math.max(2, availableParallelism() - 1),
  },
});
