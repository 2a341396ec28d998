/**
 * remark plugin: a fenced block marked ```` ```exercise ```` (one JSON
 * object, widgets/chapter/exercise/exercise-spec.ts) becomes an exercise.
 *
 * The declaration is read HERE, at build time. Its title and prompt are
 * rendered as text and typeset math; its answer-bearing parts (truth,
 * mistakes, hints, worked solution, reference code) are rendered the same
 * way and then sealed (seal.ts), so the page's text does not give them
 * away; the exercise widget (exercise.ts) unseals them in the browser. A
 * declaration that does not parse, repeats an id, or names a truth that
 * gives no number renders its error in the page and fails the build, as a
 * failing cell does (cell-failures.ts, fail-loudly.mjs).
 *
 * Emitted markup (the contract the widget, the progress page and the e2e
 * tests rely on):
 *
 *   <section class="exercise" id="exercise-<id>" data-exercise="<id>" data-exercise-kind="<kind>"
 *            data-exercise-public="<JSON>" data-exercise-sealed="<sealed>" aria-labelledby="exercise-<id>-title">
 *     <p class="exercise-head" id="exercise-<id>-title"><span class="exercise-kind">…</span> <strong>title</strong></p>
 *     <div class="exercise-prompt">…</div>
 *     <div class="exercise-body" data-exercise-body><noscript>…</noscript></div>
 *     <p class="exercise-note">…for learning, not for exams…</p>
 *   </section>
 */
import katex from 'katex';
import { fromHtmlIsomorphic } from 'hast-util-from-html-isomorphic';
import { computeTruth, KIND_NAMES, parseExercise, publicPart, seal, sealedPart } from '../../widgets/index.ts';
import { reportChapter } from './cell-failures.ts';
import { shownPath } from './remark-cells.mjs';

/** @param {string} text */
function escapeHtml(text) {
  return text.replace(/[&<>"]/g, (c) => `&#${c.charCodeAt(0)};`);
}

/**
 * An author's sentence as HTML: `$…$` typeset by KaTeX, `code`, **bold**
 * and *emphasis*, paragraphs at blank lines; everything else is text.
 * @param {string} text
 */
export function inlineHtml(text) {
  return text.split(/\n\s*\n/).map((paragraph) => {
    const html = paragraph.split(/(\$[^$]+\$|`[^`]+`)/).map((part) => {
      if (/^\$[^$]+\$$/.test(part)) return katex.renderToString(part.slice(1, -1), { throwOnError: false });
      if (/^`[^`]+`$/.test(part)) return `<code>${escapeHtml(part.slice(1, -1))}</code>`;
      return escapeHtml(part).replace(/\*\*([^*]+)\*\*/g, '<strong>$1</strong>').replace(/\*([^*]+)\*/g, '<em>$1</em>');
    }).join('');
    return `<p>${html}</p>`;
  }).join('');
}

/** The note on every exercise: honest about what grading is. */
export const HONESTY = 'Checked in your browser, for learning, not for exams: the answers are hidden in the page, not locked away.';

/**
 * @param {import('../../widgets/index.ts').Exercise} exercise
 * @returns {Promise<import('hast').Element>}
 */
export async function renderExercise(exercise) {
  const { id } = exercise;
  const rendered = {
    ...sealedPart(exercise),
    hints: exercise.hints.map(inlineHtml),
    solution: inlineHtml(exercise.solution),
  };
  const html = `<section class="exercise" id="exercise-${id}" data-exercise="${id}" data-exercise-kind="${exercise.kind}"`
    + ` data-exercise-public="${escapeHtml(JSON.stringify(publicPart(exercise)))}" data-exercise-sealed="${await seal(rendered, id)}" aria-labelledby="exercise-${id}-title">`
    + `<p class="exercise-head" id="exercise-${id}-title"><span class="exercise-kind">${KIND_NAMES[exercise.kind]}</span> <strong>${escapeHtml(exercise.title)}</strong></p>`
    + `<div class="exercise-prompt">${inlineHtml(exercise.prompt)}</div>`
    + '<div class="exercise-body" data-exercise-body><noscript><p>This exercise checks your answer in the page: turn on JavaScript to use it.</p></noscript></div>'
    + `<p class="exercise-note">${HONESTY}</p></section>`;
  return /** @type {import('hast').Element} */ (fromHtmlIsomorphic(html, { fragment: true }).children[0]);
}

/** @param {string} message @returns {import('hast').Element} */
function renderError(message) {
  return /** @type {import('hast').Element} */ (fromHtmlIsomorphic(`<p class="exercise-problem" role="note">This exercise could not be read: ${escapeHtml(message)}</p>`, { fragment: true }).children[0]);
}

/** @param {import('mdast').Parent} parent @param {(node: import('mdast').Code, parent: import('mdast').Parent, index: number) => void} visit */
function eachExerciseFence(parent, visit) {
  parent.children.forEach((child, index) => {
    if (child.type === 'code' && child.lang === 'exercise') visit(child, parent, index);
    else if ('children' in child) eachExerciseFence(child, visit);
  });
}

export function remarkExercises() {
  /**
   * @param {import('mdast').Root} tree
   * @param {import('vfile').VFile} file
   */
  return async (tree, file) => {
    /** @type {Set<string>} */
    const ids = new Set();
    /** @type {Promise<void>[]} */
    const rendering = [];
    const chapter = file.path ? shownPath(file.path) : '(chapter)';
    /** @type {string[]} */
    const problems = [];
    eachExerciseFence(tree, (node, parent, index) => {
      const parsed = parseExercise(node.value);
      const problem = 'error' in parsed ? parsed.error
        : ids.has(parsed.exercise.id) ? `the id ${parsed.exercise.id} is used twice in this chapter: progress is kept by id`
        : truthProblem(parsed.exercise);
      // Every id read counts, even one whose exercise has another problem: progress is kept by id.
      if (!('error' in parsed)) ids.add(parsed.exercise.id);
      /** @param {import('hast').Element} element */
      const place = (element) => {
        parent.children[index] = /** @type {import('mdast').RootContent} */ (/** @type {unknown} */ ({
          type: 'exercise',
          data: { hName: element.tagName, hProperties: element.properties, hChildren: element.children },
        }));
      };
      if (problem) {
        file.message(`exercise: ${problem}`, node);
        problems.push(`${chapter}:${node.position?.start.line ?? 0}: exercise${'error' in parsed ? '' : ` ${parsed.exercise.id}`}: ${problem}`);
        place(renderError(problem));
      } else {
        rendering.push(renderExercise(/** @type {{ exercise: import('../../widgets/index.ts').Exercise }} */ (parsed).exercise).then(place));
      }
    });
    await Promise.all(rendering);
    // An exercise that cannot be read or graded would fail every reader: the build fails (fail-loudly.mjs).
    reportChapter(chapter, problems, 'exercises');
  };
}

/**
 * Why a number exercise could not be graded: its truth is unknown, lacks an
 * argument, or gives no number for the arguments declared; null when it grades.
 * @param {import('../../widgets/index.ts').Exercise} exercise
 * @returns {string | null}
 */
function truthProblem(exercise) {
  if (!exercise.answer) return null;
  const { name, args } = exercise.answer.truth;
  const truth = computeTruth(name, args);
  if ('error' in truth) return truth.error;
  return Number.isFinite(truth.value) ? null : `the truth ${name} gives no number for ${JSON.stringify(args)}`;
}
