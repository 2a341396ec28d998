import { fileURLToPath } from 'node:url';
import { defineConfig } from 'vitest/config';

/** The extension's unit tests (the analyzer, the catalogue, the grammar); the in-host suite is test/host/. */
export default defineConfig({
  root: fileURLToPath(new URL('.', import.meta.url)),
  test: {
    include: ['test/unit/**/*.test.ts'],
  },
});
