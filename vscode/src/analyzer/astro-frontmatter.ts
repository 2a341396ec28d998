/**
 * Astro's own front-matter parser, the one that reads every chapter at
 * build time (YAML between `---` lines, via js-yaml). Imported by file
 * because the package's index also loads Shiki and reads `process`, which
 * the web extension host has not; this module needs only js-yaml.
 */
export { extractFrontmatter, parseFrontmatter } from '../../../node_modules/@astrojs/markdown-remark/dist/frontmatter.js';
