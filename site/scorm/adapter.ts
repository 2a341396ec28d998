/**
 * The SCORM 1.2 adapter of a packaged chapter (`npm run package:scorm`,
 * bin/package-scorm.mjs): only a package's page loads it, never the book's.
 * It finds the LMS's API (find-api.ts) and reports the chapter's exercise
 * score and completion (lms-session.ts) as the reader's checks come in,
 * through the event the exercises send for that purpose
 * (EXERCISE_RESULT_EVENT, cells/progress.ts). Which exercises the chapter
 * has, it reads from their declarations in the page.
 *
 * Outside an LMS (the page opened on its own) it does nothing at all. An
 * LMS that refuses a call is said once, in a line at the top of the
 * chapter, where the reader looks; nothing is thrown.
 */
import { EXERCISE_RESULT_EVENT, type ExerciseResult } from '../../cells/index.ts';
import { findApi } from './find-api.ts';
import { LmsSession } from './lms-session.ts';

function say(message: string): void {
  const note = document.createElement('p');
  note.className = 'scorm-note';
  note.setAttribute('role', 'status');
  note.dataset.scormNote = '';
  note.textContent = message;
  const place = document.querySelector('main') ?? document.body;
  place.prepend(note);
}

function start(): void {
  const api = findApi(window);
  if (!api) return;
  const exercises = [...document.querySelectorAll<HTMLElement>('[data-exercise]')].map((element) => element.dataset.exercise ?? '').filter(Boolean);
  const session = new LmsSession(api, [...new Set(exercises)], say);
  if (!session.start()) return;
  document.addEventListener(EXERCISE_RESULT_EVENT, (event) => {
    const { id, solved } = (event as CustomEvent<ExerciseResult>).detail;
    session.result(id, solved);
  });
  // pagehide covers the page being closed or left, and the back-forward cache; unload is for LMS frames that never fire it.
  window.addEventListener('pagehide', () => session.finish());
  window.addEventListener('unload', () => session.finish());
}

start();
