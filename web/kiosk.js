// Kiosk mode (kiosk=1, docs/web.md): the page as an unattended exhibit, under the policy of
// `zeroset view --kiosk` (src/interact/kiosk.hpp): nothing that opens or writes a file, the
// start screen (the gallery over the first scene) again after `idle` seconds without input,
// typed polynomials up to `max-degree`, and the formula keyboard of
// src/interact/formula_keyboard.hpp for touch screens. A page may enter fullscreen only on a
// user's gesture, so it asks on the first touch; a browser in its own kiosk mode
// (chromium --kiosk URL) is fullscreen from the start.

// Reads the policy from the URL (the core's defaults where a value is missing or out of
// range), builds the keyboard and starts the idle clock. `keys` are the page's handlers:
// edited() after a key changed the formula field, submit() for the draw key, idle() when
// the start screen is due.
import { tr } from './i18n.js';

export function startKiosk(core, params, formulaInput, keys) {
  const defaults = core.kioskDefaults();
  const number = (name, fallback, lo, hi) => {
    const v = Number(params.get(name));
    return params.has(name) && Number.isFinite(v) && v >= lo && v <= hi ? v : fallback;
  };
  const policy = {
    idleSeconds: number('idle', defaults.idleSeconds, 1, 86400),
    maxDegree: Math.round(number('max-degree', defaults.maxDegree, 1, 64)),
  };
  document.body.classList.add('kiosk');

  const board = document.getElementById('formula-keyboard');
  for (const row of core.formulaKeyRows()) {
    for (const key of row) {
      if (!key) { board.append(document.createElement('span')); continue; }
      const b = document.createElement('button');
      b.type = 'button';
      b.dataset.key = key;
      b.addEventListener('click', () => {
        if (key === 'draw') { keys.submit(); return; }
        formulaInput.value = core.pressFormulaKey(formulaInput.value, key);
        keys.edited();
      });
      board.append(b);
    }
  }
  board.hidden = false;
  // The word keys (draw, clear) and the delete key's name are translated; the rest are what
  // they type.
  const translate = () => {
    for (const b of board.querySelectorAll('button')) {
      const key = b.dataset.key;
      const word = key === 'draw' || key === 'clear';
      b.textContent = key === '<-' ? '⌫' : word ? tr(key) : key;
      b.setAttribute('aria-label', key === '<-' ? tr('delete') : word ? tr(key) : key);
    }
  };
  translate();

  let lastInput = performance.now();
  let leftStart = false;  // input since the start screen
  const noteInput = () => { lastInput = performance.now(); leftStart = true; };
  for (const type of ['pointerdown', 'pointermove', 'keydown', 'wheel', 'input'])
    window.addEventListener(type, noteInput, { capture: true, passive: true });
  setInterval(() => {
    if (leftStart && performance.now() - lastInput >= policy.idleSeconds * 1000) {
      leftStart = false;
      keys.idle();
    }
  }, 250);
  // A click (a tap's too) is a gesture the browser lets ask for fullscreen; asked again
  // after a refusal or after the visitor left it.
  window.addEventListener('click', () => {
    if (!document.fullscreenElement) document.documentElement.requestFullscreen?.().catch(() => {});
  });

  return {
    policy,
    translate,
    // '' or why the exhibit does not draw `formula`.
    refusal: (formula) => core.kioskRefusal(formula, policy.maxDegree),
  };
}
