import { describe, expect, it } from 'vitest';
import { FigureSlots, FRAME_GAP_MS, MotionSense, MOVING_FRAMES, STILL_AFTER_MS } from '../../../../../widgets/chapter/chart/chart-reuse.ts';

/** Slots whose runs end when the test says so, instead of at a microtask. */
function slotsByHand() {
  let end: (() => void) | null = null;
  const slots = new FigureSlots<{ id: number }>((clear) => (end = clear));
  return { slots, endRun: () => (end?.(), (end = null)) };
}

describe('FigureSlots: a cell that runs again takes over the figures of its last run', () => {
  it('hands each call the figure made at the same place in the same cell’s last run', () => {
    const { slots, endRun } = slotsByHand();
    const cell = {};
    const a = { id: 1 };
    const b = { id: 2 };
    const first = slots.take(cell);
    expect(first.previous).toBeUndefined();
    first.keep(a);
    const second = slots.take(cell);
    expect(second.previous).toBeUndefined();
    second.keep(b);
    endRun();
    // The next run: first call gets a, second b, a third (new) none.
    expect(slots.take(cell).previous).toBe(a);
    expect(slots.take(cell).previous).toBe(b);
    expect(slots.take(cell).previous).toBeUndefined();
    endRun();
  });

  it('keeps cells apart, and gives nothing to a call outside a cell or to a cell defined anew', () => {
    const { slots, endRun } = slotsByHand();
    const one = {};
    const other = {};
    slots.take(one).keep({ id: 1 });
    endRun();
    expect(slots.take(other).previous).toBeUndefined();
    expect(slots.take(undefined).previous).toBeUndefined();
    // An edit defines the cell again with a new signal: a new figure.
    expect(slots.take({}).previous).toBeUndefined();
    endRun();
  });

  it('lets go of the figures a shorter run no longer makes', () => {
    const { slots, endRun } = slotsByHand();
    const cell = {};
    slots.take(cell).keep({ id: 1 });
    slots.take(cell).keep({ id: 2 });
    endRun();
    slots.take(cell);
    endRun();
    slots.take(cell);
    // The second place was dropped by the run that made only one chart.
    expect(slots.take(cell).previous).toBeUndefined();
  });

  it('ends a run at the next microtask by default, as a cell calls chart() in its synchronous code', async () => {
    const slots = new FigureSlots<{ id: number }>();
    const cell = {};
    const a = { id: 1 };
    slots.take(cell).keep(a);
    await Promise.resolve();
    expect(slots.take(cell).previous).toBe(a);
  });
});

describe('MotionSense: a figure updated frame after frame is moving', () => {
  it('moves after MOVING_FRAMES updates a frame apart, not after one update (an edit)', () => {
    const sense = new MotionSense();
    let t = 0;
    expect(sense.update(t)).toBe(false);
    // An edit, seconds later: one update.
    t += 5000;
    expect(sense.update(t)).toBe(false);
    const moving: boolean[] = [];
    for (let k = 0; k < MOVING_FRAMES; k++) moving.push(sense.update((t += 16.7)));
    expect(moving.indexOf(true)).toBe(MOVING_FRAMES - 1);
  });

  it('is still again after a gap; a gap longer than a frame starts the count anew', () => {
    const sense = new MotionSense(3);
    let t = 0;
    for (let k = 0; k < 4; k++) sense.update((t += 16));
    expect(sense.moving(t + 10)).toBe(true);
    expect(sense.moving(t + STILL_AFTER_MS)).toBe(false);
    expect(sense.update((t += FRAME_GAP_MS + 1))).toBe(false);
  });

  it('with one frame (reduced motion) the first frame-on-frame update counts', () => {
    const sense = new MotionSense(1);
    expect(sense.update(0)).toBe(false);
    expect(sense.update(16)).toBe(true);
  });
});
