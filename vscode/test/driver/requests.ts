/**
 * What the in-host suite asks of the driver: things only a user (or playwright) can do in
 * the webview, such as scrolling the preview. The suite writes a line
 * `[phasebook-driver] <request> <argument>` to its console; the driver does it in the frame
 * of the preview of "The pendulum", and the suite watches the effect from its side.
 *
 * - `scroll-to-cell <id>`: scrolls the preview so that the cell's block is at its top;
 * - `nudge`: scrolls the preview by a pixel, so that it reports the line at its top.
 */
import type { Page } from 'playwright-core';
import { DRIVER_REQUEST } from '../driver-protocol.ts';
import { previewFrame } from './preview-checks.ts';

/** Does the request in a log line, if it is one; a failure is logged, and the suite's wait for its effect times out. */
export async function handleRequest(page: Page, line: string): Promise<void> {
  if (!line.startsWith(DRIVER_REQUEST)) return;
  const [name = '', argument = ''] = line.slice(DRIVER_REQUEST.length).trim().split(/\s+/);
  const frame = await previewFrame(page, 'The pendulum');
  const done = await frame?.evaluate(([request, id]) => {
    if (request === 'scroll-to-cell') {
      const block = document.querySelector(`figure[data-cell="${CSS.escape(id)}"]`)?.closest('.pb-block');
      block?.scrollIntoView({ block: 'start' });
      return !!block;
    }
    if (request === 'nudge') {
      scrollBy(0, 1);
      return true;
    }
    return false;
  }, [name, argument] as const);
  if (!done) console.error(`driver: could not do "${line}"`);
}
