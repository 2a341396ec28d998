/**
 * The progress page's script (site/pages/progress.astro): fills in each
 * exercise's state from this browser's storage, and exports, imports and
 * resets it. Every failure is said in the page's status line.
 */
import { type ChapterExercises, type ExerciseRecord, ProgressStore } from '../../cells/index.ts';

function describe(record: ExerciseRecord | null): string {
  if (!record) return 'Not tried';
  const checks = `${record.attempts} check${record.attempts === 1 ? '' : 's'}`;
  const shown = record.solutionShown ? ', solution shown' : '';
  return record.status === 'solved' ? `Solved (${checks}${shown})` : record.attempts ? `Not solved yet (${checks}${shown})` : `Solution shown, not yet checked`;
}

function start(): void {
  const list = document.querySelector<HTMLElement>('[data-progress-list]');
  const message = document.querySelector<HTMLElement>('[data-progress-message]');
  const summary = document.querySelector<HTMLElement>('[data-progress-summary]');
  if (!list || !message || !summary) return;
  const chapters = JSON.parse(list.dataset.progressChapters ?? '[]') as ChapterExercises[];
  const store = new ProgressStore();
  const say = (text: string) => (message.textContent = text);

  const show = () => {
    let solved = 0;
    let total = 0;
    for (const item of list.querySelectorAll<HTMLElement>('[data-progress-id]')) {
      const record = store.load(item.dataset.progressPage ?? '', item.dataset.progressId ?? '');
      const state = item.querySelector<HTMLElement>('[data-progress-state]');
      if (state) state.textContent = describe(record);
      item.dataset.progressStatus = record?.status ?? 'new';
      total++;
      if (record?.status === 'solved') solved++;
    }
    summary.textContent = `${solved} of ${total} exercises solved.`;
  };
  if (!store.available) say('This browser keeps nothing for this site (private mode, or storage switched off): no progress can be shown or kept here.');
  show();

  document.querySelector('[data-progress-export]')?.addEventListener('click', async () => {
    const file = store.exportFile(chapters);
    let downloadText: typeof import('../../widgets/exports/download.ts').downloadText;
    try {
      // Rarely wanted, so its module loads then, as the cells' own download of edits does (cells/boot.ts).
      ({ downloadText } = await import('../../widgets/exports/download.ts'));
    } catch {
      say('The export could not be made: the connection to the book’s site seems to be lost. Reload the page when you are back online.');
      return;
    }
    downloadText([JSON.stringify(file, null, 2)], 'application/json', 'phasebook-progress.json');
    const count = Object.values(file.chapters).reduce((n, records) => n + Object.keys(records).length, 0);
    say(`Exported ${count} exercise result${count === 1 ? '' : 's'} to phasebook-progress.json.`);
  });

  const input = document.querySelector<HTMLInputElement>('[data-progress-import]');
  input?.addEventListener('change', async () => {
    const file = input.files?.[0];
    if (!file) return;
    let text: string;
    try {
      text = await file.text();
    } catch {
      say('That file could not be read.');
      return;
    }
    const result = store.importFile(text, chapters);
    input.value = '';
    if ('error' in result) say(result.error);
    else {
      say(`Imported ${result.imported} exercise result${result.imported === 1 ? '' : 's'}${result.skipped ? `; ${result.skipped} for exercises this book does not have were left out` : ''}.`);
      show();
    }
  });

  const confirm = document.querySelector<HTMLElement>('[data-progress-confirm]');
  const reset = document.querySelector<HTMLButtonElement>('[data-progress-reset]');
  reset?.addEventListener('click', () => {
    if (!confirm) return;
    confirm.hidden = false;
    confirm.querySelector<HTMLButtonElement>('[data-progress-reset-no]')?.focus();
  });
  confirm?.querySelector('[data-progress-reset-no]')?.addEventListener('click', () => {
    confirm.hidden = true;
    reset?.focus();
  });
  confirm?.querySelector('[data-progress-reset-yes]')?.addEventListener('click', () => {
    confirm.hidden = true;
    say(store.reset(chapters) ? 'Every result was forgotten.' : 'This browser would not let the results be forgotten.');
    show();
    reset?.focus();
  });
  // Another tab checked an exercise: show it.
  addEventListener('storage', show);
}

start();
