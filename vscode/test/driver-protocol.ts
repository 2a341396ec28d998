/**
 * How the in-host suite asks the driver (test/driver/requests.ts) to act in the webview:
 * a console line starting with this marker, which reaches the driver through the page's
 * codeAutomationLog.
 */
export const DRIVER_REQUEST = '[phasebook-driver]';

/** Asks the driver to do `request` in the pendulum chapter's preview (see test/driver/requests.ts for the requests). */
export function askDriver(request: string): void {
  console.info(`${DRIVER_REQUEST} ${request}`);
}
