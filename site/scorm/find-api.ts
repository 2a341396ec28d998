/**
 * The LMS's SCORM 1.2 API, found the way SCORM 1.2 says a SCO finds it
 * (ADL SCORM 1.2 Run-Time Environment, section 3.3.6.1): an object named
 * `API` on the SCO's window or one of its parents, at most 7 levels up,
 * then on the window that opened it and that window's parents. A frame of
 * another origin cannot be read; it counts as one without the API.
 */

/** The SCORM 1.2 API as an LMS provides it: every call takes and returns strings. */
export interface Scorm12Api {
  LMSInitialize(empty: ''): string;
  LMSFinish(empty: ''): string;
  LMSGetValue(element: string): string;
  LMSSetValue(element: string, value: string): string;
  LMSCommit(empty: ''): string;
  LMSGetLastError(): string;
  LMSGetErrorString(code: string): string;
}

/** What the search reads of a window. */
export interface ApiWindow {
  readonly API?: unknown;
  readonly parent: ApiWindow | null;
  readonly opener?: ApiWindow | null;
}

/** How many parents up the search goes, as SCORM 1.2's own discovery code does. */
export const MAX_PARENTS = 7;

function isApi(value: unknown): value is Scorm12Api {
  return typeof value === 'object' && value !== null && typeof (value as Scorm12Api).LMSInitialize === 'function';
}

/** The API on `win` or one of its first 7 parents; a window that cannot be read ends the search. */
function searchUp(win: ApiWindow | null | undefined): Scorm12Api | null {
  for (let level = 0; win && level <= MAX_PARENTS; level++) {
    try {
      if (isApi(win.API)) return win.API;
      const parent = win.parent;
      if (!parent || parent === win) return null;
      win = parent;
    } catch {
      return null; // another origin's frame
    }
  }
  return null;
}

/** The LMS's API for the SCO in `win`, or null outside an LMS. */
export function findApi(win: ApiWindow): Scorm12Api | null {
  const found = searchUp(win);
  if (found) return found;
  try {
    return searchUp(win.opener);
  } catch {
    return null;
  }
}
