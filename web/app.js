// The page: wires the HTML controls, the URL, pointer, wheel, touch and keys to the core
// (zeroset.wasm: parsing, scene rules, validation, camera, shader assembly) and hands what
// the core computes to the WebGL2 renderer. The URL contract is docs/web.md's.
import { Renderer } from './renderer.js';
import { startKiosk } from './kiosk.js';
import { N_, tr, trf, startLanguage, setLanguage, language, languages } from './i18n.js';

const $ = (id) => document.getElementById(id);
const root = document.documentElement;
const canvas = $('view');
const errorBox = $('zeroset-error');
const notesBox = $('notes');
const statusLine = $('status');
const formulaInput = $('formula');

const MAX_DPR = 2;

let core, session, renderer;
let scale = 1;            // drawing-buffer scale: 1 at rest, reducedScale() while moving
// The cost per pixel of the latest picture (ms): the viewer's drag budget picks the reduced
// size from it (src/interact/trace_budget.hpp); first pictures are sized by the session.
let msPerPixel = 0;
let fixedSize = null;     // &size=WxH
let examples = [];
let currentExample = -1;
let pending = null;       // the draw in flight
let redrawQueued = false;
// Formula edits typed, and how many of them the prepared scene has seen: a picture is the
// current state's only when they agree (a draw begun before the last keystroke is not).
let formulaEdits = 0, formulaEditsBuilt = 0;
let firstPictureMs = null;
let kiosk = null;         // kiosk=1: the exhibit's policy (kiosk.js)
let startScene = null;    // kiosk=1: the start screen's scene, as .surf text

function setState(state) { root.dataset.zeroset = state; }

function showError(text) {
  errorBox.textContent = text.trimEnd();
  errorBox.hidden = false;
  formulaInput.setAttribute('aria-invalid', 'true');
  setState('error');
}

function clearError() {
  errorBox.hidden = true;
  errorBox.textContent = '';
  formulaInput.removeAttribute('aria-invalid');
}

function showNotes() {
  const notes = session.notes().trimEnd();
  notesBox.textContent = notes;
  notesBox.hidden = notes === '';
}

// ---- drawing ---------------------------------------------------------------------------

// The drawing buffer's size at full resolution.
function fullSize() {
  const dpr = Math.min(window.devicePixelRatio || 1, MAX_DPR);
  const cssW = fixedSize ? fixedSize[0] : canvas.clientWidth;
  const cssH = fixedSize ? fixedSize[1] : canvas.clientHeight;
  return [Math.max(1, Math.round(cssW * dpr)), Math.max(1, Math.round(cssH * dpr))];
}

// The scale of a first picture (`first`) or of a picture while dragging: the viewer's rule.
function reducedScale(first) {
  const [w, h] = fullSize();
  return 1 / (first ? session.quickScale(w, h) : core.dragScale(msPerPixel, w, h));
}

function resizeCanvas() {
  const [fullW, fullH] = fullSize();
  const w = Math.max(1, Math.round(fullW * scale));
  const h = Math.max(1, Math.round(fullH * scale));
  if (canvas.width !== w || canvas.height !== h) {
    canvas.width = w;
    canvas.height = h;
  }
}

let uploadedGeneration = -1;
let quickOnScreen = false;  // the picture shown is a first picture (the tape interpreter's)
const LINKING = 'linking';  // the formula's own program is still linking in the background

// Compiles and uploads what the prepared surface needs; '' or the message to show, or
// LINKING while a first picture stands in for it.
function loadSurfaceIntoRenderer() {
  const entry = renderer.request(session.vertexShader(), session.fragmentShader());
  if (entry === Renderer.LOST) return Renderer.LOST;
  if (quickOnScreen && !renderer.ready(entry)) return LINKING;
  const log = renderer.finish(entry);
  if (log === Renderer.LOST) return Renderer.LOST;
  if (log) {
    // The shader runs to a thousand lines: the console gets it whole, the page a few lines.
    console.groupCollapsed('zeroset: the rejected shader (driver log and fragment source)');
    console.error(log);
    console.log(session.fragmentShader());
    console.groupEnd();
    const lines = log.split('\n');
    const head = lines.slice(0, 12).join('\n') +
                 (lines.length > 12 ? `\n... (${lines.length - 12} more lines in the console)` : '');
    return 'internal error: the browser\'s WebGL2 rejected the shader zeroset generated for ' +
           'this formula. This is a bug in zeroset, not a problem with your input.\n' + head +
           '\nThe whole log and the shader source are in the browser\'s console.';
  }
  if (session.generation() !== uploadedGeneration) {
    const h = session.hierarchy();
    renderer.uploadHierarchy(h.texels, h.count);
    uploadedGeneration = session.generation();
  }
  quickOnScreen = false;
  return '';
}

// The polynomial interpreter links in the background once the formula field gets the focus,
// so that typing finds it ready (docs/interpreter.md); a visit that never edits the formula
// never pays for it.
let interpretersRequested = false;
function requestInterpreters() {
  if (interpretersRequested || !session || !session.prepared()) return;
  interpretersRequested = true;
  const entry = renderer.request(session.vertexShader(), session.interpreterShaders()[0]);
  const linked = () => {
    if (entry === Renderer.LOST) return;
    if (renderer.ready(entry)) root.dataset.interpreter = 'linked';
    else setTimeout(linked, 50);
  };
  linked();
}

// The typed formula's first picture by the tape interpreter, drawn at once when its program
// has linked; the formula's own shader replaces it (redraw).
function showFirstPicture() {
  if (!session.prepared() || session.setFormula(formulaInput.value)) return;
  // The interpreter with every operation is not used here: SwiftShader, the browsers'
  // software renderer, takes seconds to JIT it.
  if (session.prepareQuick() || !session.quickPolynomialOnly()) return;  // the build will show it
  const entry = renderer.request(session.vertexShader(), session.quickFragmentShader());
  if (entry === Renderer.LOST || !renderer.ready(entry) || renderer.finish(entry)) return;
  const h = session.quickHierarchy();
  renderer.uploadHierarchy(h.texels, h.count, 'quick');
  renderer.uploadTape(session.quickTape());
  // Reduced to the first picture's time budget and in one piece: a keystroke's picture is
  // small and done before the next key, so typing never cancels it half drawn.
  scale = reducedScale(true);
  resizeCanvas();
  quickOnScreen = true;
  const formula = formulaInput.value;
  const pixels = canvas.width * canvas.height;
  renderer.draw((w, h) => session.quickFrame(w, h), session.frame(1, 1).background,
                { quick: true, whole: true })
    .then((ms) => {
      if (ms === null) return;
      session.quickDrawn(ms, pixels);
      statusLine.textContent = `${tr('first picture')} · ${canvas.width}×${canvas.height} · ${ms.toFixed(1)} ms`;
      root.dataset.firstPicture = formula;
      root.dataset.firstPictures = String(Number(root.dataset.firstPictures || 0) + 1);
      root.dataset.firstPictureMs = ms.toFixed(0);
    });
}

// Draws the current state; sets "ready" once a full-resolution picture is complete.
function redraw() {
  if (!session.prepared()) return;
  if (pending) { redrawQueued = true; return; }
  resizeCanvas();
  const full = scale === 1;
  const error = loadSurfaceIntoRenderer();
  if (error === Renderer.LOST) return;  // the restored context draws again
  if (error === LINKING) { setTimeout(redraw, 25); return; }  // the first picture stays meanwhile
  if (error) { showError(error); return; }
  const bg = session.frame(1, 1).background;
  const pixels = canvas.width * canvas.height;
  pending = renderer.draw((w, h) => session.frame(w, h), bg).then((ms) => {
    pending = null;
    if (ms !== null && ms > 0) msPerPixel = ms / pixels;
    if (redrawQueued) { redrawQueued = false; redraw(); return; }
    if (ms === null) return;  // superseded or lost: a later draw sets the state
    statusLine.textContent = `${tr(session.method())} · ${canvas.width}×${canvas.height} · ${ms.toFixed(1)} ms`;
    if (full) {
      if (firstPictureMs === null) firstPictureMs = performance.now();
      if (!errorBox.hidden) root.dataset.zeroset = 'error';
      else if (formulaEditsBuilt === formulaEdits) setState('ready');
    }
    return ms;
  }).catch((e) => {
    pending = null;
    showError(trf('zeroset could not draw: %s', e && e.message ? e.message : e));
  });
}

// prepare() (octree, hierarchy, shaders) and draw; '' or the error shown.
function prepareAndDraw() {
  const error = session.prepare();
  if (error) { showError(error); return error; }
  clearError();
  showNotes();
  buildParams();
  buildSettings();
  redraw();
  return '';
}

// ---- scene edits -------------------------------------------------------------------------

function afterSceneLoaded() {
  formulaInput.value = session.formula();
  return prepareAndDraw();
}

function applySetting(key, tomlValue) {
  setState('busy');
  const error = session.applyOverrides([`${key}=${tomlValue}`]);
  if (error) { showError(error); return; }
  clearError();
  // The session builds what the key invalidates (nothing for a frame parameter).
  prepareAndDraw();
}

let typingTimer = 0;
function buildTypedFormula() {
  clearTimeout(typingTimer);
  if (!session) return;
  setState('busy');
  formulaEditsBuilt = formulaEdits;
  const error = (kiosk && kiosk.refusal(formulaInput.value)) || session.setFormula(formulaInput.value);
  if (error) { showError(error); return; }
  scale = 1;  // after a first picture at the reduced size
  prepareAndDraw();
}
function formulaEdited() {
  clearTimeout(typingTimer);
  ++formulaEdits;
  const refusal = kiosk && session ? kiosk.refusal(formulaInput.value) : '';
  if (refusal) {
    formulaEditsBuilt = formulaEdits;  // the state is the refusal
    showError(refusal);
    if (scale !== 1 && session.prepared()) { scale = 1; redraw(); }  // not left at a first picture's size
    return;
  }
  if (session) {
    setState('busy');  // the picture on screen is not the typed formula's yet
    showFirstPicture();
  }
  typingTimer = setTimeout(buildTypedFormula, core.typingPauseMs());  // the session's rule
}
formulaInput.addEventListener('focus', requestInterpreters);
formulaInput.addEventListener('input', formulaEdited);
$('formula-form').addEventListener('submit', (e) => e.preventDefault());

// ---- parameters and settings panels --------------------------------------------------

const paramRanges = new Map();  // name -> [lo, hi], fixed while the formula keeps the name

function buildParams() {
  const box = $('params');
  const params = session.params();
  const names = params.map((p) => p.name).join(',');
  if (box.dataset.names === names) {
    for (const p of params) {
      const row = box.querySelector(`[data-param="${p.name}"]`);
      if (row && document.activeElement?.closest('.param') !== row) {
        row.querySelector('input[type=range]').value = p.value;
        row.querySelector('input[type=number]').value = p.value;
      }
    }
    return;
  }
  box.dataset.names = names;
  box.replaceChildren();
  for (const p of params) {
    if (!paramRanges.has(p.name)) paramRanges.set(p.name, [p.lo, p.hi]);  // src/interact
    const [lo, hi] = paramRanges.get(p.name);
    const row = document.createElement('div');
    row.className = 'param';
    row.dataset.param = p.name;
    const id = `param-${p.name}`;
    row.innerHTML = `<label for="${id}"></label><input id="${id}" type="range"><input type="number" step="any" aria-label="">`;
    row.querySelector('label').textContent = p.name;
    const slider = row.querySelector('input[type=range]');
    const number = row.querySelector('input[type=number]');
    number.setAttribute('aria-label', trf('%s value', p.name));
    Object.assign(slider, { min: lo, max: hi, step: (hi - lo) / 1000, value: p.value });
    number.value = p.value;
    const set = (v) => {
      const error = session.setParam(p.name, Number(v));
      if (error) { showError(error); return; }
      clearError();
      slider.value = v;
      number.value = v;
      setState('busy');
      const err = session.prepare();
      if (err) { showError(err); return; }
      redraw();
    };
    slider.addEventListener('input', () => set(slider.value));
    number.addEventListener('change', () => set(number.value));
    box.append(row);
  }
}

const MAX_CLIP_PLANES = 4;  // render/settings.hpp kMaxClipPlanes
const MAX_SURFACES = 4;  // scene/scene.hpp kMaxSurfaces

function tomlOf(setting, value) {
  switch (setting.type) {
    case 'bool': return value ? 'true' : 'false';
    case 'enum': case 'function': return JSON.stringify(value);
    case 'vec3': return `[${value.map(Number).join(', ')}]`;
    default: return String(Number(value));
  }
}

const hex = (v) => Math.round(Math.min(1, Math.max(0, v)) * 255).toString(16).padStart(2, '0');

// One row of a panel: the key and an input that applies it through --set's validation.
function settingRow(s) {
  const row = document.createElement('div');
  row.className = 'setting';
  const id = 'set-' + s.key.replace(/\./g, '-');
  const label = document.createElement('label');
  label.htmlFor = id;
  label.textContent = keyLabel(s.key.replace(/^(lights\.source|clip\.plane|surface)\.\d+\./, ''));
  label.title = s.key;
  row.append(label);
  let input;
  if (s.type === 'bool') {
    input = document.createElement('input');
    input.type = 'checkbox';
    input.checked = s.value[0] !== 0;
    input.addEventListener('change', () => applySetting(s.key, tomlOf(s, input.checked)));
  } else if (s.type === 'function') {
    input = document.createElement('input');
    input.type = 'text';
    input.spellcheck = false;
    input.value = s.choice;
    input.addEventListener('change', () => applySetting(s.key, tomlOf(s, input.value)));
  } else if (s.type === 'enum') {
    input = document.createElement('select');
    for (const c of s.choices) input.add(new Option(tr(c), c, false, c === s.choice));
    input.addEventListener('change', () => applySetting(s.key, tomlOf(s, input.value)));
  } else if (s.type === 'vec3' && /color/.test(s.key)) {
    input = document.createElement('input');
    input.type = 'color';
    input.value = '#' + s.value.map(hex).join('');
    input.addEventListener('change', () => {
      const v = [1, 3, 5].map((i) => parseInt(input.value.slice(i, i + 2), 16) / 255);
      applySetting(s.key, tomlOf(s, v));
    });
  } else if (s.type === 'vec3') {
    input = document.createElement('span');
    input.className = 'vec';
    const parts = s.value.map((v, i) => {
      const n = document.createElement('input');
      n.type = 'number';
      n.step = 'any';
      n.value = v;
      n.setAttribute('aria-label', `${label.textContent} ${'xyz'[i]}`);
      return n;
    });
    parts.forEach((n, i) => {
      n.addEventListener('change', () => applySetting(s.key, tomlOf(s, parts.map((p) => p.value))));
      n.dataset.key = `${s.key}.${'xyz'[i]}`;
    });
    input.append(...parts);
    parts[0].id = id;
  } else {
    input = document.createElement('input');
    input.type = 'number';
    input.step = s.type === 'int' ? '1' : 'any';
    if (Number.isFinite(s.lo)) input.min = s.lo;
    if (Number.isFinite(s.hi)) input.max = s.hi;
    input.value = s.value[0];
    input.addEventListener('change', () => applySetting(s.key, tomlOf(s, input.value)));
  }
  if (s.type !== 'vec3' || /color/.test(s.key)) {
    input.id = id;
    input.dataset.key = s.key;
  }
  row.append(input);
  return row;
}

// The panels, built from the .surf schema (every key, its range and value) and the scene's
// light sources; rebuilt after each edit, keeping which are open and the focused key.
function buildSettings() {
  const box = $('settings');
  const open = new Set([...box.querySelectorAll('details[open]')].map((d) => d.dataset.group));
  const focused = document.activeElement?.dataset?.key;
  box.replaceChildren();
  const groups = new Map();
  const group = (name) => {
    if (!groups.has(name)) {
      const d = document.createElement('details');
      d.dataset.group = name;
      d.open = open.has(name);
      const summary = document.createElement('summary');
      summary.textContent = tr(name);
      d.append(summary);
      groups.set(name, d);
    }
    return groups.get(name);
  };
  // The sections in the session's order (session::panelGroups), each key where it says.
  for (const name of core.panelGroups()) group(name);
  for (const s of session.settings()) group(s.group).append(settingRow(s));
  session.listEntries('lights.source').forEach((light, i) => {
    const set = document.createElement('fieldset');
    const legend = document.createElement('legend');
    legend.textContent = trf('light %d', i + 1);
    set.append(legend, ...light.map(settingRow));
    group(core.panelGroup('lights.source')).append(set);
  });
  surfaceRows(group(core.panelGroup('surface')));
  clipPlaneRows(group(core.panelGroup('clip.plane')));
  box.append(...[...groups.values()].filter((d) => d.children.length > 1));
  if (focused) box.querySelector(`[data-key="${focused}"]`)?.focus();
}

// A list of the scene ([[clip.plane]], [[surface]]): one fieldset per entry from `first` on,
// with its keys and a remove button, and a button that adds `fresh` while fewer than `max`.
// Adding and removing replace the whole list through --set.
function listRows(box, { list, first = 0, max, legend, addLabel, fresh }) {
  const entries = session.listEntries(list);
  const id = list.replace('.', '-');
  const valueOf = (s) => s.type === 'function' || s.type === 'enum' ? s.choice
    : s.type === 'bool' ? s.value[0] !== 0 : s.type === 'vec3' ? s.value : s.value[0];
  const inline = (entry) => '{' + entry.map((s) =>
    `${s.key.slice(`${list}.`.length).replace(/^\d+\./, '')} = ${tomlOf(s, valueOf(s))}`).join(', ') + '}';
  const setList = (all) => applySetting(list, `[${all.join(', ')}]`);
  entries.forEach((entry, i) => {
    if (i < first) return;
    const set = document.createElement('fieldset');
    const title = document.createElement('legend');
    title.textContent = trf(legend, i + 1);
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.textContent = tr('remove');
    remove.id = `${id}-${i + 1}-remove`;
    remove.addEventListener('click', () => setList(entries.filter((_, j) => j !== i).map(inline)));
    set.append(title, ...entry.map(settingRow), remove);
    box.append(set);
  });
  if (entries.length < max) {
    const add = document.createElement('button');
    add.type = 'button';
    add.textContent = tr(addLabel);
    add.id = `${id}-add`;
    add.addEventListener('click', () => setList([...entries.map(inline), fresh]));
    box.append(add);
  }
}

// The clip planes, z <= 0 the first one added.
function clipPlaneRows(box) {
  listRows(box, { list: 'clip.plane', max: MAX_CLIP_PLANES, legend: N_('plane %d'),
                  addLabel: N_('add plane'), fresh: '{normal = [0, 0, 1], offset = 0}' });
}

// The surfaces after the first (whose formula is the formula field), the plane z = 0 the
// first one added.
function surfaceRows(box) {
  listRows(box, { list: 'surface', first: 1, max: MAX_SURFACES, legend: N_('surface %d'),
                  addLabel: N_('add surface'), fresh: '{formula = "z"}' });
}

// ---- pointer, wheel, touch, keys -----------------------------------------------------

const pointers = new Map();
let dragFrom = null;
let pinchFrom = 0;

function cssSize() {
  const r = canvas.getBoundingClientRect();
  return [r.width, r.height];
}

canvas.addEventListener('pointerdown', (e) => {
  if (!session) return;
  canvas.setPointerCapture(e.pointerId);
  pointers.set(e.pointerId, [e.offsetX, e.offsetY]);
  if (pointers.size === 1) {
    session.beginDrag();
    dragFrom = [e.offsetX, e.offsetY];
  } else if (pointers.size === 2) {
    const [a, b] = [...pointers.values()];
    pinchFrom = Math.hypot(a[0] - b[0], a[1] - b[1]);
    dragFrom = null;
  }
});

// Hovering with a mouse shows what lies under the cursor (src/probe): the point, F's
// normal and the curvatures, in the status line.
let lastProbe = 0, probeTimer = 0;
function showProbe(e) {
  // At most one probe per 80 ms, and always one for where the cursor stopped.
  const x = Math.floor(e.offsetX), y = Math.floor(e.offsetY);
  clearTimeout(probeTimer);
  const wait = lastProbe + 80 - performance.now();
  if (wait > 0) {
    probeTimer = setTimeout(() => showProbe({ offsetX: x, offsetY: y }), wait);
    return;
  }
  if (!session.prepared()) return;
  lastProbe = performance.now();
  const [w, h] = cssSize();
  const r = session.probe(x, y, Math.round(w), Math.round(h));
  const f = (v) => (Number.isFinite(v) ? v.toPrecision(4) : 'n/a');
  statusLine.textContent = r.error ? r.error : !r.hit ? tr('no surface under the cursor')
    : (r.surfaces > 1 ? trf('surface %d of %d', r.surface, r.surfaces) + ' · ' : '') +
      `(${r.point.map(f).join(', ')}) · n (${r.normal.map(f).join(', ')}) · ` +
      `K ${f(r.K)} · H ${f(r.H)} · k1 ${f(r.k1)} · k2 ${f(r.k2)}`;
}

canvas.addEventListener('pointermove', (e) => {
  if (!session) return;
  if (!pointers.has(e.pointerId)) {
    if (e.pointerType === 'mouse') showProbe(e);
    return;
  }
  pointers.set(e.pointerId, [e.offsetX, e.offsetY]);
  if (pointers.size === 1 && dragFrom) {
    const [w, h] = cssSize();
    session.drag(dragFrom[0], dragFrom[1], e.offsetX, e.offsetY, Math.round(w), Math.round(h));
  } else if (pointers.size === 2 && pinchFrom > 0) {
    const [a, b] = [...pointers.values()];
    const d = Math.hypot(a[0] - b[0], a[1] - b[1]);
    // zoomCamera: each step moves the eye 15% closer.
    session.zoom(Math.log(d / pinchFrom) / -Math.log(0.85));
    pinchFrom = d;
  } else {
    return;
  }
  scale = reducedScale(false);
  setState('busy');
  redraw();
});

function endPointer(e) {
  if (!pointers.delete(e.pointerId)) return;
  if (pointers.size === 1) {  // back to turning with the finger that stays
    const [p] = [...pointers.values()];
    session.beginDrag();
    dragFrom = p;
    return;
  }
  if (pointers.size === 0) {
    dragFrom = null;
    scale = 1;
    buildSettings();
    redraw();
  }
}
canvas.addEventListener('pointerup', endPointer);
canvas.addEventListener('pointercancel', endPointer);

let wheelTimer = 0;
canvas.addEventListener('wheel', (e) => {
  e.preventDefault();
  if (!session) return;
  const steps = -e.deltaY / (e.deltaMode === 1 ? 3 : 100);
  session.zoom(steps);
  scale = reducedScale(false);
  setState('busy');
  redraw();
  clearTimeout(wheelTimer);
  wheelTimer = setTimeout(() => { scale = 1; buildSettings(); redraw(); }, 200);
}, { passive: false });

document.addEventListener('keydown', (e) => {
  // An exhibit keeps the browser's own print, open and save dialogs shut.
  if (kiosk && (e.ctrlKey || e.metaKey) && ['p', 'o', 's'].includes(e.key.toLowerCase())) {
    e.preventDefault();
    return;
  }
  const t = e.target;
  if (t instanceof HTMLInputElement || t instanceof HTMLSelectElement || t instanceof HTMLTextAreaElement) return;
  if (!session || e.altKey || e.metaKey) return;
  // GLFW's key codes: the upper-case letters, and 262 / 263 for the right and left arrows.
  const arrows = { ArrowRight: 262, ArrowLeft: 263 };
  if (e.key.length !== 1 && !(e.key in arrows)) return;
  const code = arrows[e.key] || e.key.toUpperCase().charCodeAt(0);
  const mods = (e.shiftKey ? 1 : 0) | (e.ctrlKey ? 2 : 0);
  const result = session.key(code, mods);
  if (!result.action && result.effect === 0) return;
  e.preventDefault();
  if (result.message) statusLine.textContent = result.message;
  switch (result.action) {
    case 'next': loadExampleAt(currentExample + 1); return;
    case 'previous': loadExampleAt(currentExample - 1); return;
    case 'png': if (!kiosk) downloadPng(); return;
    case 'save': if (!kiosk) saveSurf(); return;
    case 'formula': formulaInput.focus(); return;
    case 'panel': togglePanel(); return;
    case 'gallery': $('gallery-panel').open = !$('gallery-panel').open; return;
    case 'reset': buildSettings(); redraw(); return;
  }
  if (result.effect === 2) prepareAndDraw();
  else { buildSettings(); redraw(); }
});

function togglePanel() {
  const panel = $('panel');
  panel.hidden = !panel.hidden;
  document.body.classList.toggle('panel-closed', panel.hidden);
  $('panel-toggle').setAttribute('aria-expanded', String(!panel.hidden));
}
$('panel-toggle').addEventListener('click', togglePanel);

// ---- files, gallery, sharing ---------------------------------------------------------

function loadText(text, name) {
  setState('busy');
  // SURFER's .jsurf files and surf's scripts (.pic, docs/surf-scripts.md) are imported.
  const error = /\.jsurf$/i.test(name) ? session.loadJsurf(text, name)
    : /\.pic$/i.test(name) ? session.loadSurfScript(text, name) : session.loadSurf(text, name);
  if (error) { showError(error); return error; }
  return afterSceneLoaded();
}

async function loadFile(file) {
  if (!session) return;
  if (!/\.(surf|jsurf|pic)$/i.test(file.name)) {
    showError(trf('%s: zeroset opens .surf and .jsurf files', file.name));
    return;
  }
  loadText(await file.text(), file.name);
}

$('open').addEventListener('click', () => $('file').click());
$('file').addEventListener('change', () => {
  const f = $('file').files[0];
  if (f) loadFile(f);
  $('file').value = '';
});
window.addEventListener('dragover', (e) => { e.preventDefault(); document.body.classList.add('dropping'); });
window.addEventListener('dragleave', () => document.body.classList.remove('dropping'));
window.addEventListener('drop', (e) => {
  e.preventDefault();
  document.body.classList.remove('dropping');
  const f = e.dataTransfer?.files?.[0];
  if (f && !kiosk) loadFile(f);
});

function saveBlob(blob, name) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
function downloadPng() {
  if (!session) return; canvas.toBlob((b) => b && saveBlob(b, 'zeroset.png'), 'image/png'); }
function saveSurf() {
  if (session) saveBlob(new Blob([session.sceneText()], { type: 'text/plain' }), 'scene.surf');
}
$('download').addEventListener('click', downloadPng);
$('save').addEventListener('click', saveSurf);
$('reset').addEventListener('click', () => {
  if (!session) return;
  session.resetView();
  buildSettings();
  redraw();
});

// Share links hold the whole scene: its .surf text, deflated and base64url-encoded.
async function encodeScene(text) {
  const stream = new Blob([text]).stream().pipeThrough(new CompressionStream('deflate-raw'));
  const bytes = new Uint8Array(await new Response(stream).arrayBuffer());
  let s = '';
  for (const b of bytes) s += String.fromCharCode(b);
  return btoa(s).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}
async function decodeScene(code) {
  const b64 = code.replace(/-/g, '+').replace(/_/g, '/');
  const bin = atob(b64 + '='.repeat((4 - b64.length % 4) % 4));
  const bytes = Uint8Array.from(bin, (c) => c.charCodeAt(0));
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate-raw'));
  return await new Response(stream).text();
}
$('share').addEventListener('click', async () => {
  if (!session) return;
  const url = new URL(location.href);
  url.search = '';
  url.searchParams.set('scene', await encodeScene(session.sceneText()));
  const field = $('share-link');
  field.value = url.href;
  field.hidden = false;
  field.select();
  navigator.clipboard?.writeText(url.href).catch(() => {});
});

let exampleRequest = 0;
async function loadExampleAt(i) {
  if (examples.length === 0 || !session) return;
  currentExample = ((i % examples.length) + examples.length) % examples.length;
  const ex = examples[currentExample];
  const request = ++exampleRequest;
  const text = await fetchText(`examples/${ex.name}.surf`);
  if (request !== exampleRequest) return;  // a later pick won
  if (text === null) { showError(trf('example %s: not found', ex.name)); return; }
  loadText(text, ex.name + '.surf');
}

async function fetchText(url) {
  try {
    const r = await fetch(url);
    return r.ok ? await r.text() : null;
  } catch {
    return null;
  }
}

// The texts the page builds itself, in the current language: the keys' list, the gallery,
// the language selector.
function buildTexts() {
  $('keys').replaceChildren();
  for (const k of core.keys()) {
    if (kiosk && !k.kiosk) continue;
    const li = document.createElement('li');
    li.textContent = `${k.key}: ${tr(k.description)}`;
    $('keys').append(li);
  }
  buildGallery();
  filterGallery();
  const select = $('language');
  select.replaceChildren(...languages().map((l) => new Option(l.name, l.code, false, l.code === language())));
  kiosk?.translate();
}

// A setting's label: its key ("tracing.epsilon", the name .surf files and --set use), or in
// another language its words translated ("trazado · épsilon").
function keyLabel(key) {
  const words = key.split('.').map((w) => w.replace(/_/g, ' '));
  const shown = words.map(tr);
  return shown.every((w, i) => w === words[i]) ? key : shown.join(' · ');
}

function buildGallery() {
  const list = $('gallery');
  list.replaceChildren();
  examples.forEach((ex, i) => {
    const li = document.createElement('li');
    li.dataset.search = [ex.name, ex.title, ex.summary, tr(ex.title), tr(ex.summary || ''), ex.formula]
      .join(' ').toLowerCase();
    const b = document.createElement('button');
    b.type = 'button';
    b.title = ex.summary ? tr(ex.summary) : ex.name;
    const img = document.createElement('img');
    img.loading = 'lazy';
    img.alt = '';
    img.src = `examples/images/${ex.image}`;
    const caption = document.createElement('span');
    caption.textContent = ex.title ? tr(ex.title) : ex.name;
    b.append(img, caption);
    b.addEventListener('click', () => loadExampleAt(i));
    li.append(b);
    list.append(li);
  });
}
// The gallery's search, in English and in the page's language.
function filterGallery() {
  const q = $('gallery-search').value.toLowerCase().trim();
  for (const li of $('gallery').children) li.hidden = q !== '' && !li.dataset.search.includes(q);
}
$('gallery-search').addEventListener('input', filterGallery);

// ---- start ---------------------------------------------------------------------------

async function start() {
  setState('loading');
  const params = new URLSearchParams(location.search);
  if (params.get('embed') === '1') document.body.classList.add('embed');
  const size = /^(\d+)x(\d+)$/.exec(params.get('size') || '');
  if (size) {
    // Within what every browser's drawing buffer holds.
    fixedSize = [Math.min(Math.max(Number(size[1]), 1), 4096), Math.min(Math.max(Number(size[2]), 1), 4096)];
    canvas.style.width = `${fixedSize[0]}px`;
    canvas.style.height = `${fixedSize[1]}px`;
  }
  // The wasm, the gallery's index and the WebGL context (the browser starts its GPU side)
  // come at once: none waits for another.
  const coreReady = createZeroset();
  const indexReady = fetchText('examples/index.json');
  // The URL's example too, once the index says it exists (no request for unknown names).
  const exampleName = params.get('example');
  const exampleReady = indexReady.then((index) => {
    const known = index && JSON.parse(index).some((e) => e.name === exampleName);
    return known ? fetchText(`examples/${exampleName}.surf`) : null;
  });
  renderer = new Renderer(canvas, { onRestored: () => { uploadedGeneration = -1; redraw(); } });
  core = await coreReady;
  session = new core.Session();
  startLanguage(core, params);
  if (params.get('kiosk') === '1') {
    kiosk = startKiosk(core, params, formulaInput,
                       { edited: formulaEdited, submit: buildTypedFormula, idle: showStartScreen });
  }
  const index = await indexReady;
  examples = index ? JSON.parse(index) : [];
  buildTexts();
  $('language').addEventListener('change', () => {
    setLanguage($('language').value);
    buildTexts();
    if (session.prepared()) { buildParams(); buildSettings(); }
  });

  // The URL's scene; where it does not load, its error above the default surface.
  let error = '';
  if (params.has('scene')) {
    try {
      error = session.loadSurf(await decodeScene(params.get('scene')), 'shared scene');
    } catch {
      error = tr('scene: this share link is damaged (it does not decode); showing the default surface');
    }
  } else if (params.has('example')) {
    const name = params.get('example');
    const at = examples.findIndex((e) => e.name === name);
    const text = at >= 0 ? await exampleReady : null;
    if (text === null) error = trf('example=%s: no such example (the gallery lists them)', name);
    else { currentExample = at; error = session.loadSurf(text, name + '.surf'); }
  } else if (params.has('formula')) {
    error = session.loadFormula(params.get('formula'));
  } else if (kiosk && examples.length) {
    // An exhibit starts on the gallery's first surface, as `zeroset view` does.
    const text = await fetchText(`examples/${examples[0].name}.surf`);
    if (text !== null) { currentExample = 0; error = session.loadSurf(text, examples[0].name + '.surf'); }
  }
  for (const formula of params.getAll('surface')) {
    if (!error) error = session.addSurface(formula);
  }
  if (!error) {
    const sets = params.getAll('set');
    if (sets.length) error = session.applyOverrides(sets);
  }
  formulaInput.value = session.formula();
  if (error) {
    const prepareError = session.prepare();
    if (prepareError) { session.loadFormula('x^2 + y^2 + z^2 - 1'); session.prepare(); }
    showNotes(); buildParams(); buildSettings(); redraw();
    showError(error);
    return;
  }
  const prepareError = session.prepare();
  if (prepareError) {
    const shown = prepareError;
    session.loadFormula('x^2 + y^2 + z^2 - 1');
    session.prepare();
    formulaInput.value = session.formula();
    showNotes(); buildParams(); buildSettings(); redraw();
    showError(shown);
    return;
  }
  showNotes(); buildParams(); buildSettings(); redraw();
  if (kiosk) {
    startScene = { text: session.sceneText(), example: currentExample, language: language() };
    // The formula keyboard never focuses the field: the interpreter links now.
    requestInterpreters();
  }
}

// Kiosk mode: the scene the page opened with, the gallery open and the panel shown.
function showStartScreen() {
  if (!session || !startScene) return;
  // The exhibit's language for the next visitor.
  if (language() !== startScene.language && setLanguage(startScene.language)) {
    buildTexts();
    buildSettings();
  }
  currentExample = startScene.example;
  $('gallery-search').value = '';
  for (const li of $('gallery').children) li.hidden = false;
  $('gallery-panel').open = true;
  if ($('panel').hidden) togglePanel();
  scale = 1;
  loadText(startScene.text, 'start.surf');
  root.dataset.kioskStarts = String(Number(root.dataset.kioskStarts || 0) + 1);
}

new ResizeObserver(() => { if (session) redraw(); }).observe(canvas);

// For tests and benchmarks (tests/web): the session, and full-frame timings.
window.zeroset = {
  get session() { return session; },
  get firstPictureMs() { return firstPictureMs; },
  async frameTimes(count) {
    const times = [];
    for (let i = 0; i < count; i++) {
      const ms = await renderer.draw((w, h) => session.frame(w, h), session.frame(1, 1).background,
                                     { whole: true });
      if (ms !== null) times.push(ms);
    }
    return times;
  },
};

start().catch((e) => { showError(trf('zeroset could not start: %s', e && e.message ? e.message : e)); });
