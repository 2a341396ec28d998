import { describe, expect, it } from 'vitest';
import { type ApiWindow, findApi, type Scorm12Api } from '../../../../site/scorm/find-api.ts';
import { LmsSession } from '../../../../site/scorm/lms-session.ts';

/** An LMS's API that keeps the data model and logs each call; `refuse` names elements it will not take. */
function fakeLms(values: Record<string, string> = {}, refuse: readonly string[] = []) {
  const data: Record<string, string> = { 'cmi.core.lesson_status': 'not attempted', 'cmi.suspend_data': '', ...values };
  const calls: string[] = [];
  let last = '0';
  const api: Scorm12Api = {
    LMSInitialize: () => (calls.push('LMSInitialize'), 'true'),
    LMSFinish: () => (calls.push('LMSFinish'), 'true'),
    LMSCommit: () => (calls.push('LMSCommit'), 'true'),
    LMSGetValue: (element) => data[element] ?? '',
    LMSSetValue: (element, value) => {
      calls.push(`${element}=${value}`);
      if (refuse.includes(element)) {
        last = '405';
        return 'false';
      }
      data[element] = value;
      return 'true';
    },
    LMSGetLastError: () => last,
    LMSGetErrorString: (code) => (code === '405' ? 'Incorrect Data Type' : ''),
  };
  return { api, data, calls };
}

describe('site/scorm/lms-session.ts: the chapter’s attempt in SCORM 1.2’s data model', () => {
  it('marks a first launch incomplete, with the score’s range, and commits', () => {
    const { api, data, calls } = fakeLms();
    expect(new LmsSession(api, ['a', 'b', 'c'], () => {}).start()).toBe(true);
    expect(data['cmi.core.lesson_status']).toBe('incomplete');
    expect([data['cmi.core.score.min'], data['cmi.core.score.max']]).toEqual(['0', '100']);
    expect(calls[0]).toBe('LMSInitialize');
    expect(calls.at(-1)).toBe('LMSCommit');
  });

  it('reports the share solved, each exercise once, committed after each change, and completed when all are', () => {
    const { api, data, calls } = fakeLms();
    const session = new LmsSession(api, ['a', 'b', 'c'], () => {});
    session.start();
    session.result('a', true);
    expect(data['cmi.core.score.raw']).toBe('33.33');
    expect(calls.at(-1)).toBe('LMSCommit');
    const before = calls.length;
    session.result('a', true); // solved again: no change
    session.result('b', false); // a failed check: no change
    session.result('elsewhere', true); // not this chapter's
    expect(calls.length).toBe(before);
    session.result('b', true);
    expect([data['cmi.core.score.raw'], data['cmi.core.lesson_status']]).toEqual(['66.67', 'incomplete']);
    session.result('c', true);
    expect([data['cmi.core.score.raw'], data['cmi.core.lesson_status']]).toEqual(['100', 'completed']);
    session.finish();
    session.finish();
    expect(calls.filter((c) => c === 'LMSFinish')).toHaveLength(1);
    expect(data['cmi.core.exit']).toBe('');
  });

  it('keeps a returning student’s solved exercises, from the LMS’s suspend data, and leaves a suspended attempt resumable', () => {
    const { api, data } = fakeLms({ 'cmi.core.lesson_status': 'incomplete', 'cmi.suspend_data': '["a","gone"]' });
    const session = new LmsSession(api, ['a', 'b'], () => {});
    session.start();
    expect(data['cmi.core.score.raw']).toBe('50');
    session.finish();
    expect(data['cmi.core.exit']).toBe('suspend');
    expect(JSON.parse(data['cmi.suspend_data'])).toEqual(['a']);
  });

  it('says a refusal once, with the LMS’s error, and throws nothing', () => {
    const { api } = fakeLms({}, ['cmi.core.score.min', 'cmi.core.score.raw']);
    const said: string[] = [];
    const session = new LmsSession(api, ['a', 'b'], (m) => said.push(m));
    session.start();
    session.result('a', true);
    expect(said).toHaveLength(1);
    expect(said[0]).toMatch(/error 405: Incorrect Data Type.*not lost/);
    const throwing = { ...api, LMSInitialize: () => { throw new Error('LMS down'); } };
    const told: string[] = [];
    expect(new LmsSession(throwing, ['a'], (m) => told.push(m)).start()).toBe(false);
    expect(told[0]).toMatch(/LMS down/);
  });
});

describe('site/scorm/find-api.ts: the LMS’s API, found as SCORM 1.2 finds it', () => {
  const api = fakeLms().api;
  /** A chain of windows, the top one first; the last is the SCO's. */
  function chain(depth: number, top: Partial<ApiWindow> = {}): ApiWindow {
    let win: ApiWindow = { parent: null, ...top };
    (win as { parent: ApiWindow }).parent = win; // a top window is its own parent
    for (let i = 0; i < depth; i++) win = { parent: win };
    return win;
  }

  it('finds it on a parent up to 7 levels up, and not 8', () => {
    expect(findApi(chain(0, { API: api }))).toBe(api);
    expect(findApi(chain(7, { API: api }))).toBe(api);
    expect(findApi(chain(8, { API: api }))).toBeNull();
  });

  it('then on the window that opened the SCO, and its parents', () => {
    expect(findApi({ ...chain(0), opener: chain(2, { API: api }) })).toBe(api);
  });

  it('takes a frame of another origin, which throws when read, for one without it', () => {
    const foreign = { get API(): unknown { throw new DOMException('Blocked', 'SecurityError'); }, get parent(): ApiWindow { throw new DOMException('Blocked', 'SecurityError'); } };
    expect(findApi({ parent: foreign as ApiWindow })).toBeNull();
    expect(findApi(chain(0))).toBeNull();
  });
});
