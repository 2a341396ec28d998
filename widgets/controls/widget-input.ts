/**
 * The one way a widget in a cell's output sets a value the cell got from
 * another cell: it sends this event (bubbling, cancelable, detail {name,
 * value}); the page (boot.ts) sets the cell of that name, if the widget's
 * cell reads it, and cancels the event, so the widget knows it will be
 * rebuilt from the new value rather than apply it on its own.
 */
export const INPUT_EVENT = 'phasebook:input';

export interface WidgetInput {
  readonly name: string;
  readonly value: number;
}

/** Sends the event from `widget`; true when no cell took the value (the widget then applies it itself). */
export function offerToCell(widget: Element, input: WidgetInput): boolean {
  return widget.dispatchEvent(new CustomEvent<WidgetInput>(INPUT_EVENT, { bubbles: true, cancelable: true, detail: input }));
}
