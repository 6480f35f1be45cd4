// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tiny DOM helpers shared by the playground's modules.

/** The element with `id`; a missing one is a bug in index.html, so say which. */
export function byId(id) {
  const node = document.getElementById(id);
  if (!node) throw new Error(`index.html lacks #${id}`);
  return node;
}

export function element(tag, text, className) {
  const node = document.createElement(tag);
  if (text !== undefined) node.textContent = text;
  if (className) node.className = className;
  return node;
}

let measureContext = null;

/**
 * Sizes a <select> to the option it shows (a native select is as wide as its widest option, so a
 * cap would cut the one shown); CSS max-width still applies on narrow screens.
 */
export function fitSelectToValue(select) {
  const option = select.selectedOptions[0];
  if (!option) return;
  measureContext ??= document.createElement('canvas').getContext('2d');
  if (!measureContext) return;
  const style = getComputedStyle(select);
  measureContext.font = style.font || `${style.fontSize} ${style.fontFamily}`;
  const text = measureContext.measureText(option.textContent).width;
  const chrome = parseFloat(style.paddingLeft) + parseFloat(style.paddingRight)
    + parseFloat(style.borderLeftWidth) + parseFloat(style.borderRightWidth);
  // The drop-down arrow takes about 1.6em on every platform.
  select.style.width = `${Math.ceil(text + chrome + 1.6 * parseFloat(style.fontSize) + 4)}px`;
}
