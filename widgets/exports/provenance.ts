/**
 * What the reader changed on a page, for a data export to record beside the
 * data: a file made after editing a chapter's H, or with a cell of the
 * reader's own, says so. A widget asks by sending this event (bubbling,
 * detail {provenance: null}); the page's cells fill it in synchronously
 * (boot.ts). A widget on a page without cells gets null back.
 */
export const PROVENANCE_EVENT = 'phasebook:provenance';

export interface Provenance {
  /** The page's path. */
  readonly page: string;
  /** The cells whose code is not the chapter's: edited, or added by the reader. */
  readonly cells: readonly { readonly cell: string; readonly source: string; readonly added: boolean }[];
}

export interface ProvenanceRequest {
  provenance: Provenance | null;
}

/** What the page around `widget` says the reader changed, or null. */
export function askProvenance(widget: Element): Provenance | null {
  const request: ProvenanceRequest = { provenance: null };
  widget.dispatchEvent(new CustomEvent<ProvenanceRequest>(PROVENANCE_EVENT, { bubbles: true, detail: request }));
  return request.provenance;
}
