/**
 * What reaches other hosts beyond the Content-Security-Policy's reach is
 * taken away before reader code runs. The policy (site/lib/csp.ts) governs
 * fetches, images, scripts and the rest, but Chromium has no directive for
 * WebRTC: an RTCPeerConnection given a STUN or TURN server on another host
 * sends it UDP and TCP traffic, with whatever the code puts in the
 * username. The book uses none of these, so they are removed from the
 * page's globals (cells see the page's globals, `window.RTCPeerConnection`
 * included). Frames, which would bring fresh copies, cannot be made
 * (dom-guard.ts); link hints are dom-guard.ts's too.
 */

/** Globals that open connections the policy does not see: WebRTC (`RTC…`, `webkitRTC…`) and the Payment Request API, which fetches a payment method's manifest from its site. */
export const UNGOVERNED = /^(webkit)?RTC|^PaymentRequest$/;

/** Removes them; returns the names removed. */
export function removeUngoverned(global: typeof globalThis = globalThis): string[] {
  const removed: string[] = [];
  for (const name of Object.getOwnPropertyNames(global)) {
    if (UNGOVERNED.test(name) && Reflect.deleteProperty(global, name)) removed.push(name);
  }
  return removed;
}
