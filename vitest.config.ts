import { defineConfig } from 'vitest/config';

/**
 * Unit tests only: tests/e2e/ holds node:test files that drive a browser
 * against the built site (`npm run test:e2e`), which vitest must not pick up.
 */
export default defineConfig({
  test: {
    include: ['tests/unit/**/*.test.{ts,mjs}'],
  },
});
