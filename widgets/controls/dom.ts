/** Small DOM builders shared by the controls and the data panel. */

let counter = 0;

/** A page-unique id for label/aria wiring. */
export function uid(prefix: string): string {
  counter += 1;
  return `${prefix}-${counter}-${Math.random().toString(36).slice(2, 6)}`;
}

/** An element with a class, attributes and children. */
export function h<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  className: string,
  attributes: Record<string, string> = {},
  ...children: (Node | string)[]
): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  if (className) e.className = className;
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
  e.append(...children);
  return e;
}

/** A button with visible text, an optional icon hidden from assistive technology, and a tooltip. */
export function button(text: string, title: string, icon?: string): HTMLButtonElement {
  const b = h('button', 'pb-button', { type: 'button', title });
  if (icon) b.append(h('span', 'pb-icon', { 'aria-hidden': 'true' }, icon));
  b.append(h('span', 'pb-label', {}, text));
  return b;
}

/** Sets a button's visible text (and icon) in place. */
export function relabel(b: HTMLButtonElement, text: string, icon?: string): void {
  const label = b.querySelector('.pb-label');
  if (label) label.textContent = text;
  const i = b.querySelector('.pb-icon');
  if (i && icon !== undefined) i.textContent = icon;
}

/** A text input with its label and an inline message slot wired by aria-describedby. */
export function field(labelText: string, value: string, attributes: Record<string, string> = {}): {
  wrapper: HTMLElement;
  input: HTMLInputElement;
  message: HTMLElement;
} {
  const id = uid('pb-field');
  const input = h('input', 'pb-input', { id, type: 'text', inputmode: 'decimal', spellcheck: 'false', autocomplete: 'off', value, ...attributes });
  const message = h('span', 'pb-field-message', { id: `${id}-message`, 'aria-live': 'polite' });
  input.setAttribute('aria-describedby', message.id);
  const wrapper = h('span', 'pb-field', {}, h('label', 'pb-field-label', { for: id }, labelText), input, message);
  return { wrapper, input, message };
}

/** Shows or clears a field's inline error message. */
export function setFieldError(input: HTMLInputElement, message: HTMLElement, error: string | null): void {
  message.textContent = error ?? '';
  if (error) input.setAttribute('aria-invalid', 'true');
  else input.removeAttribute('aria-invalid');
}

/** Whether the reader's system asks for reduced motion: animated widgets then wait for Play. */
export function prefersReducedMotion(): boolean {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}
