/**
 * The cell editor: CodeMirror 6 with a hand-picked minimal setup (no
 * `basicSetup`, about a quarter smaller). This module is the `editor` chunk,
 * imported when the reader first hovers, clicks or focuses a cell (lazy.ts),
 * never during the first load.
 *
 * It highlights with Lezer's `tok-*` classes, the same the build uses for the
 * static code, and its theme copies the static `<pre>` box, so swapping one
 * for the other changes nothing on screen.
 */
import { EditorState, Prec } from '@codemirror/state';
import { EditorView, highlightSpecialChars, keymap } from '@codemirror/view';
import { defaultKeymap, deleteCharBackward, deleteCharForward, history, historyKeymap, insertNewlineAndIndent, insertTab } from '@codemirror/commands';
import { bracketMatching, indentOnInput, syntaxHighlighting } from '@codemirror/language';
import { classHighlighter } from '@lezer/highlight';
import { cellJavascript } from './cell-language.ts';

/** What a cell needs from its editor. */
export interface CellEditor {
  readonly source: string;
  /** Replaces the text as one undoable change (Ctrl+Z brings the old text back). */
  replaceSource(source: string): void;
  focus(): void;
  /** Applies keys typed before the editor existed, at the cursor: characters, Enter, Tab, Backspace, Delete. */
  typeKeys(keys: readonly string[]): void;
  destroy(): void;
}

export interface EditorOptions {
  source: string;
  /** Accessible name, e.g. "Code cell period". */
  label: string;
  onRun: () => void;
  onChange: (source: string) => void;
}

/** Layout matching `pre.cell-code` in site/styles/cells.css. */
const cellTheme = EditorView.theme({
  '&': { backgroundColor: 'transparent', color: 'inherit', fontSize: 'inherit' },
  '&.cm-focused': { outline: 'none' },
  '.cm-scroller': { fontFamily: 'inherit', lineHeight: 'inherit' },
  '.cm-content': { padding: 'var(--cell-pad-y) 0', caretColor: 'var(--text)' },
  '.cm-line': { padding: '0 var(--cell-pad-x)' },
  '.cm-cursor': { borderLeftColor: 'var(--text)' },
});

/**
 * Replaces the children of `host` (the static `<pre>`) with an editor.
 * `clickAt` places the cursor where the reader clicked on the static code.
 */
export function mountEditor(host: HTMLElement, options: EditorOptions, clickAt?: { x: number; y: number }): CellEditor {
  const runKeys = Prec.highest(keymap.of([{ key: 'Shift-Enter', run: () => (options.onRun(), true) }]));
  const state = EditorState.create({
    doc: options.source,
    extensions: [
      runKeys,
      history(),
      highlightSpecialChars(),
      indentOnInput(),
      bracketMatching(),
      keymap.of([...defaultKeymap, ...historyKeymap]),
      cellJavascript(),
      syntaxHighlighting(classHighlighter),
      cellTheme,
      // tabindex makes the editable content count as focusable for the scroller around it (axe's
      // scrollable-region-focusable); it is the element Tab reaches already, so no stop is added.
      EditorView.contentAttributes.of({ 'aria-label': options.label, tabindex: '0' }),
      EditorView.updateListener.of((update) => {
        if (update.docChanged) options.onChange(update.state.doc.toString());
      }),
    ],
  });
  const view = new EditorView({ state });
  host.replaceChildren(view.dom);
  if (clickAt) {
    const position = view.posAtCoords(clickAt);
    if (position !== null) view.dispatch({ selection: { anchor: position } });
  }
  return {
    get source() {
      return view.state.doc.toString();
    },
    replaceSource(source) {
      view.dispatch({ changes: { from: 0, to: view.state.doc.length, insert: source } });
    },
    focus: () => view.focus(),
    typeKeys(keys) {
      for (const key of keys) {
        if (key === 'Enter') insertNewlineAndIndent(view);
        else if (key === 'Tab') insertTab(view);
        else if (key === 'Backspace') deleteCharBackward(view);
        else if (key === 'Delete') deleteCharForward(view);
        else view.dispatch(view.state.replaceSelection(key), { scrollIntoView: true, userEvent: 'input.type' });
      }
    },
    destroy: () => view.destroy(),
  };
}
