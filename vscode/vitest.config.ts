import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

/** The extension's unit tests (the analyzer, the catalogue, the grammar); the in-host suite is test/host/. */
export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  test: {
    include: ['test/unit/**/*.test.ts'],
    // One limit for every test and hook, set nowhere else: a guard against a hang, not a measure of speed.
    // vitest's 5 s default failed tests that parse the book's chapters on a loaded machine.
    testTimeout: 120_000,
    hookTimeout: 120_000,
  },
});
