/**
 * A chunk of the book that could not be fetched when it was wanted: the
 * connection is gone (offline, a train in a tunnel), or the site was
 * updated under an open page. The browser says only "Failed to fetch
 * dynamically imported module"; the reader is told what that means and
 * what will help.
 */

/** The errors browsers give for a failed `import()`: Chromium, Firefox, Safari. */
const LOAD_FAILURE = /dynamically imported module|Importing a module script failed/i;

/** An error saying that `what` ("The simulator") could not be loaded, and that a reload will help. */
export function loadFailure(what: string): Error {
  const error = new Error(
    `${what} could not be loaded: the connection to the book's site seems to be lost${globalThis.navigator?.onLine === false ? ' (the browser is offline)' : ''}. Reload the page when you are back online; your edits are kept.`,
  );
  error.name = 'LoadError';
  return error;
}

/** `error` said for the reader when it is a failed load of `what`, else as it is. */
export function explainLoadFailure(error: unknown, what: string): unknown {
  return error instanceof Error && LOAD_FAILURE.test(error.message) ? loadFailure(what) : error;
}
