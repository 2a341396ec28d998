/** Module hooks for record-loads.mjs; they run on Node's loader thread, which shares the environment. */
import { appendFileSync } from 'node:fs';

export async function load(url, context, nextLoad) {
  appendFileSync(process.env.PHASEBOOK_LOAD_LOG, `${url}\n`);
  return nextLoad(url, context);
}
