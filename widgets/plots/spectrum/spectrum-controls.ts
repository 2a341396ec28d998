/** One option of a select: the value it stands for and what the reader sees. */
export interface Choice {
  value: string;
  label: string;
}

/** A labelled native <select> whose options can be replaced while it keeps its value. */
export interface SelectControl {
  readonly element: HTMLLabelElement;
  readonly select: HTMLSelectElement;
  setChoices(choices: readonly Choice[], value: string): void;
}

export function selectControl(label: string, name: string, choices: readonly Choice[], value: string, onChange: (value: string) => void): SelectControl {
  const element = document.createElement('label');
  element.className = `pb-plot-control pb-plot-control-${name}`;
  element.style.cssText = 'display:inline-flex;align-items:center;gap:0.35em;white-space:nowrap;';
  const text = document.createElement('span');
  text.className = 'pb-plot-control-label';
  text.style.color = 'var(--muted,#5e5b55)';
  text.textContent = label;
  const select = document.createElement('select');
  select.name = name;
  select.className = 'pb-select';
  select.addEventListener('change', () => onChange(select.value));
  element.append(text, select);
  let current = '';
  const setChoices = (next: readonly Choice[], selected: string) => {
    const key = next.map((c) => `${c.value}\u0000${c.label}`).join('\u0001');
    if (key !== current) {
      current = key;
      select.replaceChildren(
        ...next.map((c) => {
          const option = document.createElement('option');
          option.value = c.value;
          option.textContent = c.label;
          return option;
        }),
      );
    }
    select.value = selected;
  };
  setChoices(choices, value);
  return { element, select, setChoices };
}

/** The row of controls above a plot. */
export function controlRow(...controls: readonly { element: HTMLElement }[]): HTMLDivElement {
  const row = document.createElement('div');
  row.className = 'pb-plot-bar';
  row.style.cssText = 'display:flex;flex-wrap:wrap;gap:0.3rem 1rem;align-items:center;margin-bottom:0.25rem;';
  row.append(...controls.map((c) => c.element));
  return row;
}

/**
 * The series a spectrum may be taken of: every record column but t, or for a
 * large batch only the first trajectory's (and the current choice), so the
 * list stays short enough to use.
 */
export function seriesChoices(columns: readonly string[], current: string): Choice[] {
  let names = columns.slice(1);
  if (names.length > 64) names = names.filter((c) => c.endsWith('[0]') || c === current);
  return names.map((c) => ({ value: c, label: c }));
}
