/**
 * A small built book in memory, shaped as the build for packages writes it
 * (site/scorm/chapter-files.ts): two chapters sharing chunks, a worker,
 * fonts, the search box and its index; for the tests of site/scorm/.
 */
import { type BuiltSite, PACKAGE_BASE as B } from '../../../site/scorm/chapter-files.ts';

/** A built book in memory: path → text. */
export function builtSite(files: Record<string, string>): BuiltSite {
  const encoder = new TextEncoder();
  return {
    paths: Object.keys(files),
    read: (path) => {
      if (!(path in files)) throw new Error(`no ${path}`);
      return encoder.encode(files[path]);
    },
  };
}

/** A small book shaped as the build writes it: two chapters sharing chunks, a worker, fonts, search. */
export const BOOK: Record<string, string> = {
  'index.html': `<a href="${B}introduction/">Introduction</a>`,
  'introduction/index.html': [
    '<html><head><meta http-equiv="Content-Security-Policy" content="default-src \'self\'; script-src \'self\' \'unsafe-eval\'">',
    `<title>Introduction — Phasebook</title><link rel="preload" href="${B}_astro/serif.A1.woff2"></head><body><main>`,
    `<form class="site-search" role="search" data-search data-search-module="${B}_astro/search.S1.js" data-search-index="${B}pagefind/"><input type="search"></form>`,
    `<a href="${B}">Contents</a> <a href="${B}kepler/#orbit">Kepler</a> <a href="${B}introduction/#cell-sim">here</a>`,
    `<script type="module" src="${B}_astro/boot.C1.js"></script></main></body></html>`,
  ].join('\n'),
  'kepler/index.html': `<script type="module" src="${B}_astro/kepler-only.K1.js"></script>`,
  '_astro/boot.C1.js': `import{a}from"./core.D1.js";const d=()=>import("./exercise.E1.js");const m=["_astro/plots.P1.js"];const base="${B}";`,
  '_astro/core.D1.js': `new Worker(new URL("${B}_astro/sim-worker.W1.js",import.meta.url),{type:"module"})`,
  '_astro/exercise.E1.js': 'export const x=1',
  '_astro/plots.P1.js': 'export const y=2',
  '_astro/sim-worker.W1.js': 'self.onmessage=()=>{}',
  '_astro/serif.A1.woff2': 'font bytes',
  '_astro/unused.U1.js': 'export const nobody=0',
  '_astro/kepler-only.K1.js': 'export const k=0',
  '_astro/search.S1.js': `new Worker(new URL("${B}_astro/search-worker.SW1.js",import.meta.url))`,
  '_astro/search-worker.SW1.js': 'importScripts()',
  'pagefind/pagefind.js': 'pagefind',
  'pagefind/index/en.pf_index': 'index',
};
