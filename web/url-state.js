// SPDX-License-Identifier: GPL-3.0-or-later
//
// The page's shareable state lives in the URL's query string (example, parts, seed, candidates,
// rank, mode, timeLimit, joints and clearance for plates, and resolution for a bundled mesh), so a design can be sent as a link.
// Reading it only pre-fills the page: a link never starts a design by itself.

export const URL_KEYS = ['example', 'parts', 'seed', 'candidates', 'rank', 'mode', 'timeLimit', 'joints', 'clearance', 'resolution'];

/** The known parameters present in the URL, as strings. */
export function readUrlState() {
  const params = new URLSearchParams(location.search);
  const state = {};
  for (const key of URL_KEYS) {
    if (params.has(key)) state[key] = params.get(key);
  }
  return state;
}

/**
 * Merges `changes` into the URL (an empty string or null removes a key) without adding a
 * history entry: editing a field should not make the back button replay every keystroke.
 */
export function writeUrlState(changes) {
  const params = new URLSearchParams(location.search);
  for (const [key, value] of Object.entries(changes)) {
    if (value === null || value === undefined || value === '') params.delete(key);
    else params.set(key, String(value));
  }
  const query = params.toString();
  const url = `${location.pathname}${query ? `?${query}` : ''}${location.hash}`;
  if (url !== `${location.pathname}${location.search}${location.hash}`) history.replaceState(history.state, '', url);
}
