/**
 * The work the build did ahead for one page: each model its cells define,
 * compiled (compiled-model.ts), and each formula they typeset, as HTML. The
 * page reads it from a JSON script element and uses it instead of loading
 * mathjs and KaTeX; anything not in it, such as a reader's new H, is done on
 * the page as before.
 */
import type { CompiledModel, CompiledModelStore } from '../../../core/index.ts';

/** Only imported as a type here, so the page's boot script carries none of the core. */
export const PAGE_DATA_FORMAT = 1;

/**
 * The attribute that holds page data as JSON, on a `<template>` at the end of
 * each MDX file's markup: a page has one per file it is built from.
 */
export const PAGE_DATA_ATTRIBUTE = 'data-phasebook-page-data';

export interface PageData {
  readonly format: typeof PAGE_DATA_FORMAT;
  readonly models: readonly CompiledModel[];
  /** Typeset HTML by typesetKey(source, display). */
  readonly typeset: Readonly<Record<string, string>>;
}

/** What the page's widgets use from the build's data. */
export interface PageContext {
  readonly models: CompiledModelStore;
  readonly typeset: ReadonlyMap<string, string>;
}

/**
 * Compiled models held in memory: the build's to start with, and every model
 * compiled on the page since (so editing H back to a known one is instant).
 * `onCompile` hears of each model that had to be compiled, for the "compiling…" state.
 */
export function memoryStore(models: readonly CompiledModel[], onCompile?: (key: string) => void): CompiledModelStore {
  const byKey = new Map(models.map((m) => [m.key, m]));
  return {
    get(key) {
      // Whoever asks checks what it gets (isCompiledModel); a miss here means a compile follows.
      const found = byKey.get(key);
      if (!found) onCompile?.(key);
      return found;
    },
    put(model) {
      byKey.set(model.key, model);
    },
  };
}

/**
 * The page's context from the JSON texts of its data elements. Missing,
 * damaged or other-version data counts as none: the page then compiles and
 * typesets that part itself, slower but the same.
 */
export function pageContext(jsons: Iterable<string | null | undefined>, onCompile?: (key: string) => void): PageContext {
  const models: CompiledModel[] = [];
  const typeset = new Map<string, string>();
  for (const json of jsons) {
    const data = parse(json);
    if (Array.isArray(data.models)) models.push(...data.models);
    for (const [key, html] of Object.entries(typeof data.typeset === 'object' && data.typeset ? data.typeset : {})) {
      if (typeof html === 'string') typeset.set(key, html);
    }
  }
  return { models: memoryStore(models, onCompile), typeset };
}

function parse(json: string | null | undefined): Partial<PageData> {
  try {
    const parsed: unknown = json ? JSON.parse(json) : null;
    if (typeof parsed === 'object' && parsed !== null && (parsed as PageData).format === PAGE_DATA_FORMAT) return parsed as PageData;
  } catch {
    // Damaged data is no data.
  }
  return {};
}
