/**
 * The preview webview's script: takes the host's messages (render, run,
 * reveal, checks) and sends back what happened (rendered, cells' states,
 * scrolling, a double-click on a cell's code).
 */
import type { HostMessage, PreviewMessage } from '../shared/messages.ts';
import { ChapterPage } from './chapter-page.ts';
import { ScrollSync } from './scroll-sync.ts';
import { followVsCodeTheme } from './theme.ts';
import { prepareWorkers } from './workers.ts';

declare function acquireVsCodeApi(): { postMessage(message: PreviewMessage): void; setState(state: unknown): void };

async function start(): Promise<void> {
  const vscode = acquireVsCodeApi();
  const post = (message: PreviewMessage) => vscode.postMessage(message);
  const article = document.querySelector<HTMLElement>('article[data-chapter]');
  if (!article) return;
  // What VS Code gives back to restore this preview after a reload (PreviewManager.revive).
  vscode.setState({ uri: article.dataset.document });
  followVsCodeTheme();
  await prepareWorkers(scriptBase);
  const page = new ChapterPage(article, post);
  const scroll = new ScrollSync(page.blocks, (line) => post({ type: 'scrolled', line }));

  // A double-click on a cell's code opens the cell in the editor.
  article.addEventListener('dblclick', (event) => {
    const target = event.target as Element;
    const cell = target.closest<HTMLElement>('.cell-editor')?.closest<HTMLElement>('figure[data-cell]');
    const line = cell ? page.lineOf(cell.dataset.cell ?? '') : undefined;
    if (line !== undefined) post({ type: 'open', line: line + 1 });
  });

  addEventListener('message', (event: MessageEvent<HostMessage>) => {
    const message = event.data;
    try {
      if (message.type === 'render') page.render(message.version, message.text);
      else if (message.type === 'run') page.run(message.cell);
      else if (message.type === 'reveal') scroll.reveal(message.line);
      else if (message.type === 'checks') void page.checks(message.cells, message.timeoutMs).then((results) => post({ type: 'checks', request: message.request, results }));
    } catch (error) {
      // A chapter the renderer cannot take must not end the preview: the next text may be fine.
      console.error(error);
    }
  });
  post({ type: 'ready' });
}

/** Read before any await: document.currentScript is only set while the script first runs. */
const scriptBase = document.currentScript?.dataset.workers ?? '';

void start();
