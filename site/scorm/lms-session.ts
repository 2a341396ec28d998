/**
 * A chapter's attempt as the LMS sees it, through SCORM 1.2's data model:
 * the share of the chapter's exercises solved as `cmi.core.score.raw`
 * (0–100, with `score.min` 0 and `score.max` 100), `cmi.core.lesson_status`
 * 'incomplete' from the first launch and 'completed' once every exercise is
 * solved, and the ids solved so far in `cmi.suspend_data`, so that a
 * student who comes back, on any computer, keeps their score. Every change
 * is committed at once.
 *
 * An LMS that refuses a call is not an error of the chapter: its last
 * error is passed to `say`, once per session, and nothing is thrown.
 */
import type { Scorm12Api } from './find-api.ts';

/** The LMS's error, in words, for the page. */
export type Say = (message: string) => void;

export class LmsSession {
  readonly #api: Scorm12Api;
  readonly #exercises: readonly string[];
  readonly #say: Say;
  readonly #solved = new Set<string>();
  #open = false;
  #said = false;

  constructor(api: Scorm12Api, exercises: readonly string[], say: Say) {
    this.#api = api;
    this.#exercises = exercises;
    this.#say = say;
  }

  /** The score, 0–100: the share of the exercises solved, to two decimals. */
  get score(): number {
    return this.#exercises.length === 0 ? 100 : Math.round((10_000 * this.#solved.size) / this.#exercises.length) / 100;
  }

  get complete(): boolean {
    return this.#solved.size === this.#exercises.length;
  }

  /** LMSInitialize, then what a first launch or a return sets; false when the LMS would not start. */
  start(): boolean {
    if (!this.#call(() => this.#api.LMSInitialize(''))) return false;
    this.#open = true;
    for (const id of this.#suspended()) if (this.#exercises.includes(id)) this.#solved.add(id);
    const status = this.#api.LMSGetValue('cmi.core.lesson_status');
    this.#set('cmi.core.score.min', '0');
    this.#set('cmi.core.score.max', '100');
    if (this.#solved.size > 0 || this.complete) this.#reportScore();
    else if (status === 'not attempted' || status === '') this.#set('cmi.core.lesson_status', 'incomplete');
    this.#commit();
    return true;
  }

  /** A check of exercise `id` ended; a newly solved exercise changes the score, and is committed. */
  result(id: string, solved: boolean): void {
    if (!this.#open || !solved || this.#solved.has(id) || !this.#exercises.includes(id)) return;
    this.#solved.add(id);
    this.#reportScore();
    this.#commit();
  }

  /** LMSFinish, once; the exit is 'suspend' while exercises remain, so the LMS keeps the suspend data for the return. */
  finish(): void {
    if (!this.#open) return;
    this.#open = false;
    this.#set('cmi.core.exit', this.complete ? '' : 'suspend');
    this.#commit();
    this.#call(() => this.#api.LMSFinish(''));
  }

  #reportScore(): void {
    this.#set('cmi.core.score.raw', String(this.score));
    this.#set('cmi.suspend_data', JSON.stringify([...this.#solved]));
    this.#set('cmi.core.lesson_status', this.complete ? 'completed' : 'incomplete');
  }

  #suspended(): string[] {
    try {
      const data: unknown = JSON.parse(this.#api.LMSGetValue('cmi.suspend_data') || '[]');
      return Array.isArray(data) ? data.filter((id): id is string => typeof id === 'string') : [];
    } catch {
      return [];
    }
  }

  #set(element: string, value: string): void {
    this.#call(() => this.#api.LMSSetValue(element, value));
  }

  #commit(): void {
    this.#call(() => this.#api.LMSCommit(''));
  }

  /** Makes one call; a refusal ('false', or a throw from a faulty LMS) is said once, with the LMS's own words. */
  #call(call: () => string): boolean {
    let result: string;
    try {
      result = String(call());
    } catch (error) {
      this.#tell(`the course system failed (${error instanceof Error ? error.message : String(error)})`);
      return false;
    }
    if (result === 'true') return true;
    let code = '';
    let words = '';
    try {
      code = String(this.#api.LMSGetLastError());
      words = String(this.#api.LMSGetErrorString(code));
    } catch {
      // its own error could not be read: the refusal is said without it
    }
    this.#tell(`the course system refused to record it${code && code !== '0' ? ` (error ${code}${words ? `: ${words}` : ''})` : ''}`);
    return false;
  }

  #tell(why: string): void {
    if (this.#said) return;
    this.#said = true;
    this.#say(`Your course may not see your progress in this chapter: ${why}. Your work here is not lost: this browser keeps it, and the chapter works as before.`);
  }
}
