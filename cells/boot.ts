/**
 * Starts the live cells of a chapter page. Imported by
 * site/components/Cells.astro on pages that have cells.
 *
 * Finds the chapter root (`[data-chapter="<slug>"]`) and its cells
 * (`[data-cell]`, see site/lib/remark-cells.mjs), and defines them in one
 * notebook as they are wanted (schedule.ts): the cells near the view and
 * what they read at once, the rest as the reader scrolls. `data-cells-ready`
 * on <body> says that every cell wanted at first has shown its first value
 * or error, `data-cells-complete` that every cell of the page has. Editors load when the reader first touches a
 * cell (lazy.ts). The build's compiled models and typeset equations come
 * from the page's data element (chapter/models/page-data.ts).
 *
 * A page opened from a shared link (`#share=…`, share-format.ts) runs over an
 * in-memory store holding the link's edits as unrun drafts, apart from the
 * reader's own saved edits (share-session.ts, share-ui.ts, loaded then).
 * An embed page (`[data-embed-cell]`) keeps its edits in memory and talks to
 * the page around it (embed.ts, loaded then).
 */
import { PAGE_DATA_ATTRIBUTE, pageContext, createLibrary, prefetchWidgets, PROVENANCE_EVENT, type ProvenanceRequest, INPUT_EVENT, type WidgetInput } from '../widgets/index.ts';
import { createBuiltins } from './builtins.ts';
import { pageLoopGuard } from './cell-definition.ts';
import { blockedMessage, cellOfSource, recentCell, stackOf } from './cell-errors.ts';
import type { LiveCell } from './cell.ts';
import { ChapterCells } from './chapter.ts';
import { watchScrollables } from './scrollables.ts';
import { colourCodeWhenNear } from './code-tokens.ts';
import { MathSnapshot, pageIntact } from './integrity.ts';
import { formatError } from './spec.ts';
import { currentCellSignal, Notebook } from './runtime.ts';
import { CellScheduler } from './schedule.ts';
import { EditStore } from './storage.ts';
import { isShareFragment } from './share-fragment.ts';
import type { SharedView } from './share-ui.ts';
import { CellView } from './cell-view.ts';
import { loadFailure } from './load-failure.ts';
import type { Sandbox } from './sandbox/index.ts';
import { captionFigures } from './print-captions.ts';
import { wireHandout } from './handout.ts';
import type { ExercisePage } from './exercises.ts';

function markReady(): void {
  document.body.dataset.cellsReady = '';
  document.dispatchEvent(new CustomEvent('phasebook:cells-ready'));
}

/** Settles once every cell of the page has shown its first value or error (markComplete). */
let allShown: () => void = () => {};
const complete = new Promise<void>((resolve) => (allShown = resolve));

function markComplete(): void {
  document.body.dataset.cellsComplete = '';
  allShown();
}

/**
 * Every edit on the page as one JSON file, for a reader whose browser will
 * not keep them. Rarely wanted, so its module loads then (a page's first
 * scripts stay small).
 */
async function downloadEdits(cells: readonly LiveCell[]): Promise<void> {
  const { downloadText } = await import('../widgets/exports/download.ts');
  const edits = cells.flatMap((cell) => (cell.edit ? [{ cell: cell.id, ...cell.edit }] : []));
  const file = { page: location.href, saved: new Date().toISOString(), edits };
  const name = `phasebook-edits-${location.pathname.split('/').filter(Boolean).pop() ?? 'page'}.json`;
  downloadText([JSON.stringify(file, null, 2)], 'application/json', name);
}

/**
 * Errors no cell's promise carries — a cell's timer or handler throwing, a
 * promise it let fail, a request the Content-Security-Policy blocked — show
 * under the cell whose code it was, not only in the console.
 */
function reportLaterErrors(cells: readonly LiveCell[]): void {
  const show = (source: string | null | undefined, message: string, guess = false): boolean => {
    const id = cellOfSource(source) ?? (guess ? recentCell() : null);
    const cell = cells.find((c) => c.id === id);
    cell?.showLaterError(message);
    return cell !== undefined;
  };
  addEventListener('error', (event) => {
    if (show(stackOf(event.error), `${formatError(event.error ?? event.message)} (after the cell ran)`)) event.preventDefault();
  });
  addEventListener('unhandledrejection', (event) => {
    if (show(stackOf(event.reason), `${formatError(event.reason)} (a promise of this cell failed)`)) event.preventDefault();
  });
  document.addEventListener('securitypolicyviolation', (event) => {
    show(event.sourceFile, blockedMessage(event.blockedURI, event.effectiveDirective), true);
  });
}

/**
 * A widget's control for a value the widget got from another cell (a
 * simulator's dt field, its dt from the chapter's `dt` cell) sets that cell:
 * one value, which the chapter's checks use too.
 */
function passWidgetInputs(root: HTMLElement, cells: readonly LiveCell[]): void {
  root.addEventListener(INPUT_EVENT, (event) => {
    const { name, value } = (event as CustomEvent<Partial<WidgetInput>>).detail ?? {};
    if (typeof name !== 'string' || typeof value !== 'number') return;
    const holder = cells.find((cell) => cell.root.contains(event.target as Node));
    const source = cells.find((cell) => cell.name === name);
    if (!holder || !source || source === holder || !holder.inputs.includes(name)) return;
    event.preventDefault();
    source.setFromWidget(value);
  });
}

/**
 * Shared links are rare and the Share button is pressed once in a while, so
 * their code (share-ui.ts and the format and session behind it) loads only
 * then, not with every page.
 */
const loadShare = () => import('./share-ui.ts');

/** Says in the share panel under the title that sharing could not start, and why. */
function showShareUnavailable(what: string): void {
  const panel = document.querySelector<HTMLElement>('[data-share-edits] [data-share-panel]');
  if (!panel) return;
  const line = document.createElement('p');
  line.setAttribute('role', 'alert');
  line.textContent = loadFailure(what).message;
  panel.replaceChildren(line);
  panel.hidden = false;
}

/** The shared link's edits for this chapter (share-ui.ts), or null: the chapter then starts as without the link. */
async function openSharedLink(root: HTMLElement): Promise<SharedView | null> {
  let share: Awaited<ReturnType<typeof loadShare>>;
  try {
    share = await loadShare();
  } catch {
    // The share code could not load (offline, say): the chapter opens without the link, and says so.
    showShareUnavailable('The shared link’s edits could not be shown, since the code that opens them');
    return null;
  }
  try {
    return await share.openShared(root);
  } catch (error) {
    // Nothing in decoding should throw; if it does, the reader hears why the edits are not shown.
    console.error(error);
    share.showShareProblem('The link’s shared edits could not be opened.');
    return null;
  }
}

/** Wires the Share and Embed buttons under the chapter's title (site/components/ShareEdits.astro). */
function wireShareButton(chapter: ChapterCells): void {
  const trigger = document.querySelector<HTMLButtonElement>('[data-share-edits] [data-share-button]');
  trigger?.addEventListener('click', () => void loadShare().then((m) => m.shareEdits(chapter), () => showShareUnavailable('Sharing')));
  const embed = document.querySelector<HTMLButtonElement>('[data-share-edits] [data-embed-button]');
  embed?.addEventListener('click', () => void loadShare().then((m) => m.embedWidget(chapter), () => showShareUnavailable('Embedding')));
}

/**
 * The sandbox (sandbox/index.ts): loaded, in a chunk of its own, and
 * installed when the first code that is not the chapter's is about to run.
 * `ready` is null until then: nothing to undo before.
 */
function pageSandbox(store: EditStore, cells: () => readonly LiveCell[]) {
  let loading: Promise<Sandbox> | null = null;
  const sandbox = {
    ready: null as Sandbox | null,
    load: (): Promise<Sandbox> =>
      (loading ??= import('./sandbox/index.ts').then(
        (m) => (sandbox.ready = m.installSandbox(store, cells)),
        () => {
          loading = null;
          throw loadFailure('The guard that edited code runs in');
        },
      )),
  };
  return sandbox;
}

function boot(): void {
  const root = document.querySelector<HTMLElement>('[data-chapter]');
  if (!root) return;
  colourCodeWhenNear(root);
  // An embed page (site/pages/embed/): its own store and its messages with the page around it (embed.ts).
  if (root.hasAttribute('data-embed-cell')) {
    void import('./embed.ts').then(
      (embed) => embed.startEmbed(root, (store) => start(root, null, store)),
      () => start(root, null),
    );
    return;
  }
  // Pasting another shared link into the address bar changes only the fragment: load the page for it.
  addEventListener('hashchange', () => {
    if (isShareFragment(location.hash)) location.reload();
  });
  if (!isShareFragment(location.hash)) {
    void start(root, null);
    return;
  }
  void openSharedLink(root).then((shared) => start(root, shared));
}

/** Starts the page's cells over `store`: by default the reader's saved edits, keyed by the page's path. */
async function start(root: HTMLElement, shared: SharedView | null, store = shared?.store ?? new EditStore(location.pathname)): Promise<ChapterCells> {
  // Keyed by the page's path, base path included: two books on one origin keep their edits apart.
  const data = [...document.querySelectorAll(`template[${PAGE_DATA_ATTRIBUTE}]`)].map((t) => t.getAttribute(PAGE_DATA_ATTRIBUTE));
  const page = pageContext(data, () => {
    document.dispatchEvent(new CustomEvent('phasebook:compiling'));
  });
  const library = createLibrary(page, currentCellSignal);
  const notebook = new Notebook(createBuiltins(root, library));
  const math = new MathSnapshot();
  const scheduler = new CellScheduler(markReady, markComplete, (cell) => prefetchWidgets(cell.root));
  const sandbox = pageSandbox(store, () => chapter.cells);
  const chapter: ChapterCells = new ChapterCells(root, store, notebook, scheduler, {
    downloadEdits: () => void downloadEdits(chapter.cells),
    checkPage: () => ({ restored: math.restore(), intact: pageIntact(root) }),
    // The notice loads then; whatever the cell left of the page, a module still loads.
    pageBroken: (label) => void import('./recovery.ts').then((m) => m.showPageBroken(label)),
    readerScope: () => sandbox.load().then((s) => s.scope),
    // Without the sandbox the edit cannot run anyway: applying it says why.
    holdSaved: (cell) => sandbox.load().then((s) => s.holdSaved(cell), () => false),
    redefining: (id) => sandbox.ready?.redefining(id),
  });
  // A loop the guard stopped is said under its cell; one whose loops keep being stopped loses its timers.
  pageLoopGuard.onStop((stop) => chapter.cells.find((c) => c.id === stop.cell)?.loopStopped(stop, sandbox.ready?.loopStopped(stop.cell) ?? null));
  await chapter.build();
  const { cells } = chapter;
  wireShareButton(chapter);
  if (shared) void loadShare().then((m) => m.showSharedBanner(shared, chapter));
  // A page being printed starts every cell (those that have run print their output), and captions its figures.
  const startAll = (): void => cells.forEach((cell) => scheduler.want(cell));
  addEventListener('beforeprint', () => {
    startAll();
    captionFigures(root, location.href);
  });
  const handout = document.querySelector<HTMLElement>('[data-print-handout]');
  const button = handout?.querySelector<HTMLButtonElement>('[data-print-button]');
  const status = handout?.querySelector<HTMLElement>('[data-print-status]');
  if (button && status) wireHandout(button, status, { startAll, complete });
  // Keystrokes typed just before the reader leaves are saved, not lost with the pending timer.
  addEventListener('pagehide', () => cells.forEach((cell) => cell.leaving()));
  document.addEventListener('visibilitychange', () => {
    if (document.visibilityState === 'hidden') cells.forEach((cell) => cell.flush());
  });
  reportLaterErrors(cells);
  passWidgetInputs(root, cells);
  watchScrollables(root);
  // A data export asks what the reader changed on this page, to record it with the data.
  root.addEventListener(PROVENANCE_EVENT, (event) => {
    (event as CustomEvent<ProvenanceRequest>).detail.provenance = { page: location.pathname, cells: chapter.provenance() };
  });
  // Another tab of this book saved an edit: the cell showing it hears of it.
  addEventListener('storage', (event) => {
    const cell = event.key ? cells.find((c) => store.editKey(c.id) === event.key) : undefined;
    if (cell && event.storageArea === localStorage) cell.externalChange(store.parseEvent(event.newValue));
  });
  scheduler.watch([...cells]);
  watchExercises(root, {
    notebook,
    cells: () => chapter.cells,
    want: (cell) => scheduler.want(cell),
    model: (spec) => library.canonicalEquations().then((build) => build(spec)),
  });
  return chapter;
}

/**
 * The chapter's exercises (site/lib/remark-exercises.mjs) start when one
 * first comes near the view: their code (exercises.ts and the widget) is
 * then loaded, never with the chapter's first paint.
 */
function watchExercises(root: HTMLElement, page: ExercisePage): void {
  const exercises = [...root.querySelectorAll<HTMLElement>('[data-exercise]')];
  if (!exercises.length) return;
  const observer = new IntersectionObserver((entries) => {
    if (!entries.some((entry) => entry.isIntersecting)) return;
    observer.disconnect();
    void import('./exercises.ts').then(
      (m) => m.startExercises(exercises, page),
      () => exercises.forEach((exercise) => exercise.querySelector('[data-exercise-body]')?.replaceChildren(loadFailure('This exercise').message)),
    );
  }, { rootMargin: '200px 0px' });
  exercises.forEach((exercise) => observer.observe(exercise));
}

boot();
