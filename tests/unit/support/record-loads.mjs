/**
 * `node --import ./record-loads.mjs …`: appends the URL of every module the
 * process loads to the file named by $PHASEBOOK_LOAD_LOG, so a test can tell
 * which parts of the bundle a run read (module hooks, Node ≥ 20.6).
 */
import { register } from 'node:module';

register('./load-hooks.mjs', import.meta.url);
