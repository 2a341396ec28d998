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

declare function acquireVsCodeApi(): { postMessage(message: PreviewMessage): void };

async function start(): Promise<void> {
  const vscode = acquireVsCodeApi();
  const post = (message: PreviewMessage) => vscode.postMessage(message);
  const article = document.querySelector<HTMLElement>('article[data-chapter]');
  if (!article) return;
  followVsCodeTheme();
  await prepareWorkers(scriptBase);
  const page = new ChapterPage(article, post);
  const scroll = new ScrollSync(page.blocks, (line) => post({ type: 'scrolled', line }));

  // A double-click on a cell's code opens that line in the editor.
  article.addEventListener('dblclick', (event) => {
    const block = (event.target as Element).closest<HTMLElement>('.pb-block');
    const code = (event.target as Element).closest('.cell-editor');
    if (block && code) post({ type: 'open', line: Number(block.dataset.line) });
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
