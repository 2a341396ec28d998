/**
 * The in-host suite: loaded by VS Code's extension host (a web worker, as
 * on github.dev) through @vscode/test-web, run with Mocha's browser build.
 * Its output reaches the driver (test/driver/run.ts) through the page's
 * codeAutomationLog, its result through codeAutomationExit.
 */
import 'mocha/mocha.js';

export async function run(): Promise<void> {
  mocha.setup({ ui: 'bdd', reporter: 'spec', timeout: 120_000, color: false });
  // Imported after setup: the files call describe() as they load.
  await import('./diagnostics.test.ts');
  await import('./code-lens.test.ts');
  await import('./completion.test.ts');
  await import('./new-chapter.test.ts');
  await import('./theory-tests.test.ts');
  await import('./exercises.test.ts');
  await import('./preview.test.ts');
  return new Promise((resolve, reject) => {
    mocha.run((failures) => (failures ? reject(new Error(`${failures} test(s) failed`)) : resolve()));
  });
}
