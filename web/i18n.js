// The page's texts in the visitor's language (docs/languages.md). The catalogs are the
// core's (po/*.po, built into zeroset.wasm), so the page, the viewer and the core's own
// messages (a kiosk's refusal, a key's effect) speak the same language.
//
// Marks, which scripts/update-po.sh collects: tr('text') and trf('pattern %s', value) in
// scripts, N_('text') where a text sits in a table and is translated where it is shown,
// data-i18n on an element whose text is translated, and data-i18n-attrs="title ..." naming
// the attributes that are.

let core = null;

export const N_ = (text) => text;

export function tr(text) { return core ? core.translate(text) : text; }

// tr(pattern) with each %s or %d replaced by the next value.
export function trf(pattern, ...values) {
  let i = 0;
  return tr(pattern).replace(/%[sd]/g, () => String(values[i++]));
}

export function language() { return core ? core.currentLanguage() : 'en'; }

// The language the URL asks for (lang=), else the first of the browser's that has a
// catalog, else English; then the page's static texts in it.
export function startLanguage(zeroset, params) {
  core = zeroset;
  const asked = [params.get('lang'), ...(navigator.languages || [navigator.language])];
  const code = asked.map((tag) => (tag ? core.knownLanguage(tag) : '')).find((c) => c) || 'en';
  setLanguage(code);
}

export function setLanguage(code) {
  if (!core.setLanguage(code)) return false;
  document.documentElement.lang = core.currentLanguage();
  translatePage();
  return true;
}

// The English of each marked text is kept on its element, so switching again starts from it.
const squeeze = (s) => s.replace(/\s+/g, ' ').trim();
function translatePage() {
  for (const el of document.querySelectorAll('[data-i18n]')) {
    el.dataset.i18nText ??= squeeze(el.textContent);
    el.textContent = tr(el.dataset.i18nText);
  }
  for (const el of document.querySelectorAll('[data-i18n-attrs]')) {
    for (const attr of el.dataset.i18nAttrs.split(/\s+/)) {
      const key = 'i18n' + attr.replace(/(^|-)(\w)/g, (_, __, c) => c.toUpperCase());
      el.dataset[key] ??= squeeze(el.getAttribute(attr) || '');
      el.setAttribute(attr, tr(el.dataset[key]));
    }
  }
}

// The languages with a catalog, for the page's selector: [{code, name}].
export function languages() { return core.languages(); }
