/**
 * Three kinds of element never enter the page once reader code has run:
 *
 * - frames (`iframe`, `frame`, `object`, `embed`, …): a frame of this
 *   origin is a second window, with its own untouched globals
 *   (RTCPeerConnection, Function, setTimeout), reachable as `window[0]` the
 *   moment it is inserted, so every guard of the sandbox would be one
 *   `document.body.append(frame)` away;
 * - a `<link>` to another site: `rel=preconnect` and `dns-prefetch` open
 *   connections that the Content-Security-Policy does not govern;
 * - `<meta http-equiv=refresh>`, a navigation by markup.
 *
 * The check has to come before the element is in the page (a preconnect
 * starts on insertion; a frame's window exists at once), so a
 * MutationObserver, which reports afterwards, cannot do it: every way to
 * make or insert an element is wrapped — creating one by name, inserting
 * nodes, setting markup (checked by parsing it inert first), setting a
 * link's address. The book itself makes none of these, so the check needs
 * no caller: whoever asks is refused, with a DOMException that names what
 * and why, which shows under the cell that asked.
 */

const FRAMES = new Set(['iframe', 'frame', 'frameset', 'object', 'embed', 'portal', 'fencedframe']);
/** Everything the check looks at inside a subtree; templates are looked into too. */
const SUSPECTS = [...FRAMES, 'link[href]', 'meta[http-equiv]', 'template'].join(',');

export class RefusedElement extends DOMException {
  constructor(message: string) {
    super(message, 'NotAllowedError');
  }
}

const STAY = "cells stay on this book's site";

/** The host a link's address reaches when it is another site's (only web addresses open connections). */
function offSite(href: string): string | null {
  try {
    const url = new URL(href, document.baseURI);
    return (url.protocol === 'http:' || url.protocol === 'https:') && url.origin !== location.origin ? url.host : null;
  } catch {
    return null;
  }
}

/** Why `element` may not be in the page, or null. */
export function refusalOf(element: Element): string | null {
  const name = element.localName;
  if (FRAMES.has(name)) return `a cell cannot put an <${name}> in the page: a frame is a second page, outside the book's guards`;
  if (name === 'link') {
    const where = offSite(element.getAttribute('href') ?? '');
    return where ? `a <link> to ${where}: ${STAY} (a link hint opens connections the Content-Security-Policy does not see)` : null;
  }
  if (name === 'meta' && (element.getAttribute('http-equiv') ?? '').trim().toLowerCase() === 'refresh') {
    return '<meta http-equiv="refresh">: a cell cannot make the page go elsewhere or reload itself';
  }
  return null;
}

/** Why something in `root` (an element, its descendants and the contents of its templates) may not be in the page, or null. */
export function refusalIn(root: Node): string | null {
  if (root instanceof Element) {
    const own = refusalOf(root);
    if (own) return own;
    if (root.localName === 'template') return refusalIn((root as HTMLTemplateElement).content);
  }
  if (!(root instanceof Element || root instanceof DocumentFragment || root instanceof Document) || !root.firstChild) return null;
  for (const element of root.querySelectorAll(SUSPECTS)) {
    const refusal = element.localName === 'template' ? refusalIn((element as HTMLTemplateElement).content) : refusalOf(element);
    if (refusal) return refusal;
  }
  return null;
}

function refuse(refusal: string | null): void {
  if (refusal) throw new RefusedElement(`Blocked: ${refusal}.`);
}

/** Nodes among `args` (strings are text, and harmless). */
function checkNodes(args: readonly unknown[]): void {
  for (const arg of args) if (arg instanceof Node) refuse(refusalIn(arg));
}

type Method = (this: unknown, ...args: unknown[]) => unknown;

/** Wraps `owner[name]` so that `check(args)` runs first. */
function wrapMethod(owner: object | undefined, name: string, check: (args: unknown[], self: unknown) => void): void {
  const real = owner && (Reflect.get(owner, name) as Method | undefined);
  if (typeof real !== 'function') return;
  Object.defineProperty(owner, name, {
    configurable: true,
    writable: true,
    value: function (this: unknown, ...args: unknown[]) {
      check(args, this);
      return real.apply(this, args);
    },
  });
}

/** Wraps the setter of `owner[name]`. */
function wrapSetter(owner: object | undefined, name: string, check: (value: unknown, self: unknown) => void): void {
  const descriptor = owner && Object.getOwnPropertyDescriptor(owner, name);
  const set = descriptor?.set;
  if (!owner || !descriptor || !set) return;
  Object.defineProperty(owner, name, {
    ...descriptor,
    set(this: unknown, value: unknown) {
      check(value, this);
      set.call(this, value);
    },
  });
}

let inert: Document | null = null;

/** Markup, parsed where nothing it holds can load or run: a template of a document without a window. */
function markupRefusal(markup: unknown, innerHTML: (this: Element, value: string) => void): string | null {
  if (typeof markup !== 'string' && !(typeof markup === 'object' && markup !== null)) return null;
  inert ??= document.implementation.createHTMLDocument('');
  const template = inert.createElement('template');
  innerHTML.call(template, String(markup));
  return refusalIn(template.content);
}

/** Installs the checks on this realm's DOM. */
export function guardElements(): void {
  const innerHTML = Object.getOwnPropertyDescriptor(Element.prototype, 'innerHTML')?.set as (this: Element, value: string) => void;
  const markup = (value: unknown) => refuse(markupRefusal(value, innerHTML));
  const nodes = (args: unknown[]) => checkNodes(args);

  for (const name of ['createElement', 'createElementNS']) {
    wrapMethod(Document.prototype, name, (args) => {
      const tag = String(args[name === 'createElement' ? 0 : 1] ?? '').toLowerCase().replace(/^.*:/, '');
      if (FRAMES.has(tag)) refuse(`a cell cannot put an <${tag}> in the page: a frame is a second page, outside the book's guards`);
    });
  }
  wrapMethod(Node.prototype, 'appendChild', nodes);
  wrapMethod(Node.prototype, 'insertBefore', (args) => checkNodes(args.slice(0, 1)));
  wrapMethod(Node.prototype, 'replaceChild', (args) => checkNodes(args.slice(0, 1)));
  for (const owner of [Element.prototype, Document.prototype, DocumentFragment.prototype, CharacterData.prototype, DocumentType.prototype]) {
    for (const name of ['append', 'prepend', 'before', 'after', 'replaceWith', 'replaceChildren']) wrapMethod(owner, name, nodes);
  }
  wrapMethod(Element.prototype, 'insertAdjacentElement', (args) => checkNodes(args.slice(1)));
  wrapMethod(Element.prototype, 'insertAdjacentHTML', (args) => markup(args[1]));
  wrapMethod(Element.prototype, 'setHTMLUnsafe', (args) => markup(args[0]));
  wrapMethod(Element.prototype, 'setHTML', (args) => markup(args[0]));
  wrapMethod(ShadowRoot.prototype, 'setHTMLUnsafe', (args) => markup(args[0]));
  wrapMethod(Document, 'parseHTMLUnsafe', (args) => markup(args[0]));
  wrapSetter(Element.prototype, 'innerHTML', markup);
  wrapSetter(Element.prototype, 'outerHTML', markup);
  wrapSetter(ShadowRoot.prototype, 'innerHTML', markup);
  wrapMethod(Range.prototype, 'insertNode', nodes);
  wrapMethod(Range.prototype, 'surroundContents', nodes);
  wrapMethod(Range.prototype, 'createContextualFragment', (args) => markup(args[0]));
  wrapMethod(globalThis.DOMParser?.prototype, 'parseFromString', (args) => markup(args[0]));
  wrapMethod(Document.prototype, 'execCommand', (args) => {
    if (String(args[0]).toLowerCase() === 'inserthtml') markup(args[2]);
  });
  wrapMethod(globalThis.customElements, 'define', (args) => {
    const base = String((args[2] as ElementDefinitionOptions | undefined)?.extends ?? '').toLowerCase();
    if (FRAMES.has(base)) refuse(`a cell cannot put an <${base}> in the page: a frame is a second page, outside the book's guards`);
  });

  // A link's or a meta's attributes, set on one already in the page (or soon to be).
  const attribute = (name: unknown, value: unknown, self: unknown) => {
    if (!(self instanceof Element)) return;
    const key = String(name).toLowerCase();
    if (self.localName === 'link' && key === 'href') {
      const where = offSite(String(value));
      if (where) refuse(`a <link> to ${where}: ${STAY} (a link hint opens connections the Content-Security-Policy does not see)`);
    }
    if (self.localName === 'meta' && key === 'http-equiv' && String(value).trim().toLowerCase() === 'refresh') {
      refuse('<meta http-equiv="refresh">: a cell cannot make the page go elsewhere or reload itself');
    }
  };
  wrapMethod(Element.prototype, 'setAttribute', (args, self) => attribute(args[0], args[1], self));
  wrapMethod(Element.prototype, 'setAttributeNS', (args, self) => attribute(args[1], args[2], self));
  const attrNode = (args: unknown[], self: unknown) => {
    const attr = args[0];
    if (attr instanceof Attr) attribute(attr.localName, attr.value, self);
  };
  wrapMethod(Element.prototype, 'setAttributeNode', attrNode);
  wrapMethod(Element.prototype, 'setAttributeNodeNS', attrNode);
  // A map does not say whose attributes it holds when it holds none: an address to another site is refused whatever its element.
  const namedItem = (args: unknown[], self: unknown) => {
    const attr = args[0];
    if (!(attr instanceof Attr)) return;
    const owner = (self as NamedNodeMap)[0]?.ownerElement;
    if (owner) attribute(attr.localName, attr.value, owner);
    else if (attr.localName.toLowerCase() === 'href' && offSite(attr.value)) refuse(`an address to ${offSite(attr.value)} set this way: ${STAY}`);
    else if (attr.localName.toLowerCase() === 'http-equiv') attribute('http-equiv', attr.value, document.createElement('meta'));
  };
  wrapMethod(NamedNodeMap.prototype, 'setNamedItem', namedItem);
  wrapMethod(NamedNodeMap.prototype, 'setNamedItemNS', namedItem);
  wrapSetter(Attr.prototype, 'value', (value, self) => attribute((self as Attr).localName, value, (self as Attr).ownerElement));
  wrapSetter(Node.prototype, 'nodeValue', (value, self) => {
    if (self instanceof Attr) attribute(self.localName, value, self.ownerElement);
  });
  wrapSetter(Node.prototype, 'textContent', (value, self) => {
    if (self instanceof Attr) attribute(self.localName, value, self.ownerElement);
  });
  wrapSetter(HTMLLinkElement.prototype, 'href', (value, self) => attribute('href', value, self));
  wrapSetter(HTMLMetaElement.prototype, 'httpEquiv', (value, self) => attribute('http-equiv', value, self));
}
