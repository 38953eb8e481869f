// The report page's behaviour: flip, heatmap, zoom, sort and filter over the cards the HTML
// already holds (the page reads without JavaScript too), the chart's hover labels, and a self
// test (?selftest) that a headless browser runs (tests/report_page_browser_test.cpp).
'use strict';

const cards = Array.from(document.querySelectorAll('.card'));
const params = new URLSearchParams(location.search);

// --- Flip: the render and what it is judged against share one grid cell, so the flip shows
// the other image at exactly the same spot and zoom.
function canFlip(card) {
  return card.querySelector('img.flip-image') !== null;
}
function flip(card) {
  if (!canFlip(card)) return;
  const shown = card.querySelector('img.shown-image');
  const other = card.querySelector('img.flip-image');
  const flipped = !shown.hidden;
  shown.hidden = flipped;
  other.hidden = !flipped;
  card.dataset.flipped = flipped ? 'yes' : 'no';
  card.querySelector('.showing-what').textContent = flipped ? other.alt : shown.alt;
}
// The image the person sees now (not merely the one the markup lists first).
function displayedImage(card) {
  return Array.from(card.querySelectorAll('.view > img:not(.heat-image)'))
    .find(img => getComputedStyle(img).display !== 'none');
}
for (const card of cards) {
  const view = card.querySelector('.view');
  if (view) view.addEventListener('click', () => flip(card));
}
let hovered = null;
for (const card of cards) {
  card.addEventListener('mouseenter', () => { hovered = card; });
  card.addEventListener('mouseleave', () => { if (hovered === card) hovered = null; });
}
function flipAll() {
  for (const card of cards) flip(card);
}
document.getElementById('flip-all').addEventListener('click', flipAll);

// --- Heatmap overlay and zoom (CSS variables, so every image follows at once).
const heatToggle = document.getElementById('heatmap-toggle');
function setHeatmap(on) {
  heatToggle.checked = on;
  document.body.classList.toggle('heatmap-on', on);
}
heatToggle.addEventListener('change', () => setHeatmap(heatToggle.checked));
document.getElementById('heatmap-opacity').addEventListener('input', e => {
  document.documentElement.style.setProperty('--heat-opacity', e.target.value / 100);
});
const zoom = document.getElementById('zoom');
function setZoom(z) {
  zoom.value = String(z);
  document.documentElement.style.setProperty('--zoom', z);
}
zoom.addEventListener('change', () => setZoom(Number(zoom.value)));
function stepZoom(direction) {
  const values = Array.from(zoom.options).map(o => Number(o.value));
  const i = values.indexOf(Number(zoom.value)) + direction;
  if (i >= 0 && i < values.length) setZoom(values[i]);
}
// The largest zoom at which the widest image fits a card of about 360 px.
const widest = Math.max(1, ...cards.map(c => Number(c.dataset.width) || 0));
setZoom([2, 1, 0.5, 0.25].find(z => widest * z <= 360) || 0.25);

document.addEventListener('keydown', e => {
  if (e.target.tagName === 'SELECT' || e.target.tagName === 'INPUT') return;
  const card = document.activeElement.closest ? document.activeElement.closest('.card') : null;
  if (e.key === 'f' && (card || hovered)) flip(card || hovered);
  else if (e.key === 'r') flipAll();
  else if (e.key === 'h') setHeatmap(!heatToggle.checked);
  else if (e.key === '+' || e.key === '=') stepZoom(1);
  else if (e.key === '-') stepZoom(-1);
});

// --- Sort and filter. Cards stay in their scene's section; sections follow their first card.
const failing = card => card.dataset.failing === 'yes';
const error = card => (card.dataset.error === '' ? -1 : Number(card.dataset.error));
const sorts = {
  'failures': (a, b) => failing(b) - failing(a) || error(b) - error(a) || listed(a, b),
  'error-desc': (a, b) => error(b) - error(a) || listed(a, b),
  'error-asc': (a, b) => error(a) - error(b) || listed(a, b),
  'path': (a, b) => a.dataset.path.localeCompare(b.dataset.path) ||
    a.dataset.variant.localeCompare(b.dataset.variant) || listed(a, b),
  'listed': (a, b) => listed(a, b),
};
function listed(a, b) {
  return Number(a.dataset.order) - Number(b.dataset.order);
}
const verdictFilter = document.getElementById('verdict-filter');
const pathFilter = document.getElementById('path-filter');
function addOptions(select, values) {
  for (const v of values) select.add(new Option(v, v));
}
const verdicts = [...new Set(cards.map(c => c.dataset.verdict).filter(v => v))];
addOptions(verdictFilter, ['failing']);  // always there: an empty result is an answer too
addOptions(verdictFilter, verdicts);
addOptions(pathFilter, [...new Set(cards.map(c => c.dataset.path))]);

function shows(card) {
  const v = verdictFilter.value, p = pathFilter.value;
  const verdictOk = v === '' || (v === 'failing' ? failing(card) : card.dataset.verdict === v);
  return verdictOk && (p === '' || card.dataset.path === p);
}
function arrange() {
  const order = sorts[document.getElementById('sort').value];
  const main = document.querySelector('main');
  const sections = Array.from(document.querySelectorAll('section.scene'));
  const firstOf = new Map();
  for (const section of sections) {
    const list = Array.from(section.querySelectorAll('.card')).sort(order);
    const holder = section.querySelector('.cards');
    for (const card of list) {
      card.hidden = !shows(card);
      holder.appendChild(card);
    }
    const visible = list.filter(c => !c.hidden);
    section.hidden = visible.length === 0;
    firstOf.set(section, visible[0] || list[0]);
  }
  sections.sort((a, b) => order(firstOf.get(a), firstOf.get(b)));
  for (const section of sections) main.appendChild(section);
  const shown = cards.filter(c => !c.hidden).length;
  document.getElementById('shown-count').textContent = shown + ' of ' + cards.length + ' cards';
}
for (const id of ['sort', 'verdict-filter', 'path-filter']) {
  document.getElementById(id).addEventListener('change', arrange);
}

// --- The chart's hover labels: every point names itself ([data-label]) next to the pointer.
const tooltip = document.getElementById('tooltip');
for (const point of document.querySelectorAll('figure.chart [data-label]')) {
  point.addEventListener('mousemove', e => {
    tooltip.textContent = point.dataset.label;
    tooltip.style.left = (e.clientX + 12) + 'px';
    tooltip.style.top = (e.clientY + 12) + 'px';
    tooltip.hidden = false;
  });
  point.addEventListener('mouseleave', () => { tooltip.hidden = true; });
}

// --- Initial state from the address (for links and screenshots): ?verdict=failing&path=gx
// &sort=error-desc&zoom=2&heatmap=on&flip=all.
if (params.get('verdict')) verdictFilter.value = params.get('verdict');
if (params.get('path')) pathFilter.value = params.get('path');
if (params.get('sort')) document.getElementById('sort').value = params.get('sort');
if (params.get('zoom')) setZoom(Number(params.get('zoom')));
if (params.get('heatmap') === 'on') setHeatmap(true);
if (params.get('flip') === 'all') flipAll();
arrange();

// --- Self test (?selftest), once every image has loaded or failed: whether each card's images
// loaded (their natural size), whether a flip changes the displayed image, which cards the
// "failing" filter shows, and each chart as laid out (title, points, size). The result is JSON in #selftest-result, for `chromium --dump-dom`.
function selftest() {
  const result = { cards: cards.length, images: 0, not_loaded: [], flip: null, failing_shown: [] };
  for (const card of cards) {
    let ok = true;
    for (const img of card.querySelectorAll('.view > img')) {
      result.images += 1;
      const loaded = img.complete && img.naturalWidth > 0;
      if (!loaded) result.not_loaded.push(img.getAttribute('src'));
      ok = ok && loaded && img.naturalWidth === Number(card.dataset.width);
    }
    card.dataset.loaded = ok ? 'yes' : 'no';
  }
  const target = cards.find(canFlip);
  if (target) {
    const before = displayedImage(target);
    flip(target);
    const after = displayedImage(target);
    result.flip = {
      case: target.dataset.case,
      before: before ? before.getAttribute('src') : null,
      after: after ? after.getAttribute('src') : null,
      after_loaded: !!after && after.naturalWidth > 0,
    };
    flip(target);
  }
  const saved = verdictFilter.value;
  verdictFilter.value = 'failing';
  verdictFilter.dispatchEvent(new Event('change'));
  result.failing_shown = cards.filter(c => c.offsetParent !== null).map(c => c.dataset.case);
  verdictFilter.value = saved;
  verdictFilter.dispatchEvent(new Event('change'));
  // Each chart as drawn: its title, its points (hover labels) and its laid-out size.
  result.charts = Array.from(document.querySelectorAll('figure.chart svg')).map(svg => {
    const box = svg.getBoundingClientRect();
    const title = svg.querySelector('text');
    // Text the chart cuts off at its right edge (a legend entry longer than its column).
    const chartWidth = svg.width.baseVal.value;
    const cut = Array.from(svg.querySelectorAll('text')).filter(t => {
      const b = t.getBBox();
      return b.x + b.width > chartWidth;
    }).map(t => t.textContent);
    return {
      title: title ? title.textContent : '',
      points: svg.querySelectorAll('[data-label]').length,
      cut_text: cut,
      width: Math.round(box.width),
      height: Math.round(box.height),
    };
  });
  const out = document.createElement('pre');
  out.id = 'selftest-result';
  out.textContent = JSON.stringify(result);
  document.body.appendChild(out);
}
if (params.has('selftest')) {
  if (document.readyState === 'complete') selftest();
  else window.addEventListener('load', selftest);
}
