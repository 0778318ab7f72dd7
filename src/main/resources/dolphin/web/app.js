// The live view of a Dolphin run: the map (Leaflet), the task trees and the event log, kept up to
// date from the run's JSON stream (/events, Server-Sent Events; docs/embedding.md). Read-only.
'use strict';

const ARROW_PIXELS = 22;      // length of a vehicle's heading line on screen
const TRACK_STEP_METRES = 2;  // as the server thins tracks (Track.STEP_METRES)
const TRACK_MAX_POINTS = 5000;
const TABLE_ROWS = 100;       // rows of the vehicle table; the rest are counted
const LABELS_UP_TO = 50;      // vehicles with a permanent label on the map
const LOG_LINES = 500;
const SVG_UP_TO = 200;        // beyond, vehicles and tracks are drawn on one canvas: cheaper for a big fleet
const SILENT_COLOR = '#e76f51'; // a vehicle not heard for 3 s, before its connection timeout makes it lost (app.css too)

const map = L.map('map', { zoomControl: true, attributionControl: true }).setView([0, 0], 2);
L.control.scale({ imperial: false }).addTo(map);

let vehicles = new Map();   // id -> { data, color, marker, arrow, track, points, home }
let missions = new Map();   // id -> { layer, items: Map(seq -> layer), current }
let links = new Map();      // link name -> { name, in, out, lost, badCrcs, radio }: the vehicles name theirs
let tileLayer = null;
let userMoved = false;     // the map follows the fleet and its missions until the user pans or zooms
let fitted = false;
const canvas = L.canvas({ padding: 0.5 });
let lastLogSeq = 0;
let ended = false;

function colorOf(id) {
  let h = 0;
  for (const c of String(id)) h = (h * 31 + c.charCodeAt(0)) % 360;
  return `hsl(${(h * 137.5) % 360}, 70%, 42%)`;
}

function metresPerPixel(lat) {
  return 40075016.686 * Math.cos(lat * Math.PI / 180) / Math.pow(2, map.getZoom() + 8);
}

function ahead(lat, lon, headingDegrees, metres) {
  const h = headingDegrees * Math.PI / 180;
  return [lat + metres * Math.cos(h) / 111320, lon + metres * Math.sin(h) / (111320 * Math.cos(lat * Math.PI / 180))];
}

function distanceMetres(a, b) {
  const dLat = (b[0] - a[0]) * 111320;
  const dLon = (b[1] - a[1]) * 111320 * Math.cos(a[0] * Math.PI / 180);
  return Math.hypot(dLat, dLon);
}

function reset() {
  fitted = false;
  for (const v of vehicles.values()) [v.marker, v.arrow, v.track, v.home].forEach(l => l && l.remove());
  for (const m of missions.values()) m.layer.remove();
  vehicles = new Map();
  missions = new Map();
  links = new Map();
  lastLogSeq = 0;
  document.getElementById('log').innerHTML = '';
}

/** The renderer for a new vehicle's layers: SVG (one element each) for a small fleet, else the shared canvas. */
function renderer() {
  return vehicles.size > SVG_UP_TO ? canvas : undefined;
}

function vehicleEntry(id) {
  let v = vehicles.get(id);
  if (!v) {
    const color = colorOf(id);
    v = { data: null, color, points: [], marker: null, arrow: null, home: null,
          track: L.polyline([], { color, weight: 2, opacity: 0.6, interactive: false, renderer: renderer() }).addTo(map) };
    vehicles.set(id, v);
  }
  return v;
}

function updateVehicle(d) {
  const v = vehicleEntry(d.id);
  v.data = d;
  const lost = !d.connected;
  const silent = !lost && d.silence != null;
  if (d.position) {
    const at = [d.position[0], d.position[1]];
    const style = { radius: 7, color: lost ? '#777' : silent ? SILENT_COLOR : '#1d2731', weight: silent ? 3 : 1.5,
                    fillColor: lost ? '#bbb' : v.color,
                    fillOpacity: d.picked ? 0.95 : 0.35 };
    if (!v.marker) {
      v.marker = L.circleMarker(at, { ...style, className: 'dolphin-vehicle', renderer: renderer() }).addTo(map)
        .bindPopup(() => popupText(v.data));
      v.arrow = L.polyline([at, at], { color: '#1d2731', weight: 2, interactive: false, renderer: renderer() }).addTo(map);
      if (vehicles.size <= LABELS_UP_TO) {
        v.marker.bindTooltip('', { permanent: true, direction: 'right', className: 'vehicle-label', offset: [8, 0] });
      }
      v.label = null;
      v.style = '';
    } else {
      v.marker.setLatLng(at);
    }
    const styleKey = JSON.stringify(style);
    if (v.style !== styleKey) {
      v.marker.setStyle(style);
      v.style = styleKey;
    }
    const label = d.id + (lost ? ' LOST' : silent ? ' no contact' : '');
    if (v.marker.getTooltip() && v.label !== label) {
      v.marker.setTooltipContent(label);
      v.label = label;
    }
    drawArrow(v);
    const last = v.points[v.points.length - 1];
    if (!last || distanceMetres(last, at) >= TRACK_STEP_METRES) {
      v.points.push(at);
      if (v.points.length > TRACK_MAX_POINTS) v.points.splice(0, TRACK_MAX_POINTS / 2);
      v.track.setLatLngs(v.points);
    }
  }
  if (d.home) {
    const at = [d.home[0], d.home[1]];
    if (!v.home) {
      v.home = L.circleMarker(at, { radius: 4, color: v.color, weight: 2, fillColor: '#fff', fillOpacity: 1 })
        .bindTooltip('home of ' + d.id).addTo(map);
    } else {
      v.home.setLatLng(at);
    }
  }
  highlightItem(d.id, d.item);
}

function drawArrow(v) {
  const d = v.data;
  if (!d || !d.position || !v.arrow) return;
  const at = [d.position[0], d.position[1]];
  v.arrow.setLatLngs(d.heading == null ? [at, at]
    : [at, ahead(at[0], at[1], d.heading, ARROW_PIXELS * metresPerPixel(at[0]))]);
}

/** The mode as the table and popup show it: LOST after the connection timeout, before it how long the vehicle is silent. */
function modeText(d) {
  return !d.connected ? 'LOST' : d.silence != null ? `no contact ${d.silence} s` : d.mode;
}

function popupText(d) {
  const heard = d.connected && d.silence == null;
  return `<b>vehicle ${d.id}</b> (${d.type}, ${d.family})${d.vtol ? ', <span class="dolphin-vtol">' + d.vtol + '</span>' : ''}`
    + `<br>${heard ? d.mode : modeText(d) + ', last seen ' + d.mode}, `
    + `${d.armed ? 'armed' : 'disarmed'}, battery ${d.battery == null ? '?' : d.battery + ' %'}<br>`
    + `${d.relativeAlt} m above home${d.item != null ? ', item ' + d.item + ' of ' + d.total : ''}<br>`
    + `${d.picked ? 'picked by the script' : 'free'}${d.task ? '<br>task ' + escapeHtml(d.task) : ''}`
    + `${d.transfer ? '<br><span class="dolphin-transfer">' + escapeHtml(d.transfer.text) + '</span>' : ''}`
    + `${d.fenceBreached ? '<br><b>outside its fence</b>' : ''}`
    + `${d.payloads && d.payloads.length ? '<br>carries ' + d.payloads.map(escapeHtml).join(', ') : ''}`
    + `${d.readings && d.readings.length ? '<br>' + readingsText(d.readings) : ''}`
    + `${links.has(d.link) ? '<br>' + linkDetail(links.get(d.link)) : ''}`;
}

/** The link's kB/s in and out, "1.2/3.4 kB/s": a tenth below ten, whole ones above, as the status table shows them. */
function ratesText(link) {
  const kilobytes = bytes => (bytes / 1000 < 9.95 ? (bytes / 1000).toFixed(1) : (bytes / 1000).toFixed(0));
  return `${kilobytes(link.in)}/${kilobytes(link.out)} kB/s`;
}

/** A radio's report: its signals and the free part of the ground radio's transmit buffer, or how long it has been silent. */
function radioText(r) {
  if (r.silence != null) return `<span class="dolphin-radio" data-radio="silent">radio silent ${r.silence} s</span>`;
  const dbm = v => (v == null ? '?' : v);
  return `<span class="dolphin-radio" data-radio="current" data-txbuf="${r.txbuf}" data-low="${r.txbuf < 50}">`
    + `radio ${dbm(r.rssiDbm)}/${dbm(r.remrssiDbm)} dBm txbuf ${r.txbuf}%</span>`;
}

/** The vehicle's link in the table's cell: its rates, and the radio's report when one came. */
function linkText(d) {
  const link = links.get(d.link);
  return link ? ratesText(link) + (link.radio ? ' ' + radioText(link.radio) : '') : '';
}

/** The link in the popup: its name, rates and losses, the radio's report with its noise and errors. */
function linkDetail(link) {
  const r = link.radio;
  return `link ${escapeHtml(link.name)}: ${ratesText(link)} in/out`
    + `${link.lost ? ', ' + link.lost + ' frames lost' : ''}${link.badCrcs ? ', ' + link.badCrcs + ' bad CRCs' : ''}`
    + `${r ? '<br>' + radioText(r) + `, noise ${r.noiseDbm ?? '?'}/${r.remnoiseDbm ?? '?'} dBm, ${r.rxerrors} receive errors, ${r.fixed} corrected` : ''}`;
}

/** Readings as "SMOKE 12.5, TEMP 21 degC"; a stale one is greyed, as its sensor has stopped sending. */
function readingsText(readings) {
  return readings.map(r => {
    const value = typeof r.value === 'number' ? Number(r.value.toPrecision(4)) : r.value;
    const text = `${escapeHtml(r.name)} ${value}${r.unit ? ' ' + escapeHtml(r.unit) : ''}`;
    return `<span class="reading" data-reading="${escapeHtml(r.name)}" data-fresh="${r.fresh}"${r.fresh ? '' : ' style="color:#999"'}>${text}</span>`;
  }).join(', ');
}

const FENCE_STYLE = { inclusion: { color: '#2a9d8f', weight: 2, fillOpacity: 0.05 },
                      exclusion: { color: '#e63946', weight: 2, fillOpacity: 0.15 } };

function updateMission(id, geojson) {
  const old = missions.get(id);
  if (old) old.layer.remove();
  const color = colorOf(id);
  const items = new Map();
  const layer = L.geoJSON(geojson, {
    renderer: renderer(),
    style: f => f.properties.fence ? FENCE_STYLE[f.properties.fence]
      : f.properties.kind ? { color, weight: 2, fillOpacity: 0.08 }
      : f.properties.footprints ? { color, weight: 0.5, opacity: 0.35, fillOpacity: 0.03 }
      : { color, weight: 2, dashArray: '6 4', opacity: 0.8 },
    onEachFeature: (f, layer) => {
      const p = f.properties;
      if (!p.kind && !p.footprints) return;
      // marks the drawn shape for people's style sheets and the browser test
      layer.on('add', () => layer.getElement()?.classList.add(p.kind ? 'dolphin-survey' : 'dolphin-footprints'));
      if (p.kind) layer.bindTooltip(`${geojson.name}: ${p.word} from item ${p.seq}, `
        + `${p.gsd != null ? p.gsd.toFixed(2) + ' cm/px, ' : ''}${p.photos} photos`);
    },
    pointToLayer: (f, at) => {
      const p = f.properties;
      if (p.rally != null) return L.circleMarker(at, { radius: 5, color: '#f4a261', weight: 2, fillOpacity: 0.6 }).bindTooltip('rally point ' + p.rally);
      if (p.fence) return L.circleMarker(at, { radius: 5, color: '#2a9d8f', weight: 2, fillOpacity: 0.6 }).bindTooltip('fence return point');
      const m = L.circleMarker(at, { radius: p.home ? 0 : 3, color, weight: 1, fillColor: '#fff', fillOpacity: 1 })
        .bindTooltip(`${geojson.name}: item ${p.seq} ${p.command}`);
      items.set(p.seq, m);
      return m;
    }
  }).addTo(map);
  missions.set(id, { layer, items, current: null, bounds: layer.getBounds() });
  const v = vehicles.get(id);
  if (v && v.data) highlightItem(id, v.data.item);
}

function highlightItem(id, seq) {
  const m = missions.get(id);
  if (!m || m.current === seq) return;
  const before = m.items.get(m.current);
  if (before) before.setStyle({ radius: 3, fillColor: '#fff' });
  const now = m.items.get(seq);
  if (now) now.setStyle({ radius: 6, fillColor: '#ffd60a' });
  m.current = seq;
}

function escapeHtml(s) {
  return String(s).replace(/[&<>"']/g, c => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' }[c]));
}

function renderTree(executes) {
  const box = document.getElementById('tree');
  if (!executes.length) {
    box.innerHTML = '<p class="empty">no execute yet</p>';
    return;
  }
  const ul = document.createElement('ul');
  ul.className = 'tree';
  executes.forEach(e => ul.appendChild(treeNode(e)));
  box.replaceChildren(ul);
}

function treeNode(n) {
  const li = document.createElement('li');
  li.className = 'node';
  li.dataset.occurrence = n.occurrence;
  li.dataset.kind = n.kind;
  li.dataset.label = n.label;
  li.dataset.state = n.state;
  const leaf = n.children.length === 0;
  li.innerHTML = `<div class="row"><span class="state">${n.state}</span>`
    + (leaf && n.label !== n.kind ? `<span class="kind">${escapeHtml(n.kind)}</span> ` : '')
    + `<span class="label">${escapeHtml(n.label)}</span>`
    + (n.vehicles.length ? ` <span class="on">on ${escapeHtml(n.vehicles.join(', '))}</span>` : '')
    + (n.since != null ? ` <span class="since">${n.state === 'running' ? 'since' : 'at'} ${n.since.toFixed(1)} s</span>` : '')
    + (n.detail ? ` <span class="detail">${escapeHtml(n.detail)}</span>` : '') + '</div>';
  if (!leaf) {
    const ul = document.createElement('ul');
    n.children.forEach(c => ul.appendChild(treeNode(c)));
    li.appendChild(ul);
  }
  return li;
}

function naturalOrder(a, b) {
  return a.localeCompare(b, undefined, { numeric: true });
}

function renderTable() {
  const all = [...vehicles.values()].map(v => v.data).filter(Boolean)
    .sort((a, b) => (b.picked - a.picked) || naturalOrder(a.id, b.id));
  const rows = all.slice(0, TABLE_ROWS).map(d => {
    const pos = d.position || [null, null];
    return `<tr data-vehicle="${escapeHtml(d.id)}" data-connected="${d.connected}" data-silent="${d.silence != null}" data-picked="${d.picked}" `
      + `data-lat="${pos[0]}" data-lon="${pos[1]}" data-mode="${escapeHtml(d.mode)}">`
      + `<td>${escapeHtml(d.id)}</td><td>${escapeHtml(d.type)}</td><td>${escapeHtml(modeText(d))}${d.armed ? ' armed' : ''}${d.vtol ? ', ' + d.vtol : ''}</td>`
      + `<td>${d.battery == null ? '?' : d.battery + ' %'}</td><td>${d.relativeAlt.toFixed(1)} m</td>`
      + `<td>${d.item != null ? d.item + '/' + d.total : '-'}</td><td class="dolphin-link">${linkText(d)}</td>`
      + `<td>${d.readings && d.readings.length ? readingsText(d.readings) : ''}</td><td>${escapeHtml(d.task)}${d.transfer ? ' <span class="dolphin-transfer">' + escapeHtml(d.transfer.text) + '</span>' : ''}</td></tr>`;
  });
  document.querySelector('#vehicles tbody').innerHTML = rows.join('');
  document.getElementById('vehicle-count').textContent = `(${all.length})`;
  document.getElementById('more-vehicles').textContent = all.length > TABLE_ROWS ? `and ${all.length - TABLE_ROWS} more` : '';
}

function appendLog(entries, lost) {
  const ol = document.getElementById('log');
  const atBottom = ol.scrollTop + ol.clientHeight >= ol.scrollHeight - 4;
  if (lost) addLogLine(ol, { kind: 'error', time: null, vehicle: null, text: `${lost} earlier events not shown (this viewer fell behind)` });
  for (const e of entries) {
    if (e.seq <= lastLogSeq) continue;
    lastLogSeq = e.seq;
    addLogLine(ol, e);
  }
  while (ol.children.length > LOG_LINES) ol.removeChild(ol.firstChild);
  if (atBottom) ol.scrollTop = ol.scrollHeight;
}

function addLogLine(ol, e) {
  const li = document.createElement('li');
  li.dataset.kind = e.kind;
  li.innerHTML = (e.time != null ? `<span class="time">${e.time.toFixed(1)} s</span>` : '')
    + (e.vehicle ? `<b>${escapeHtml(e.vehicle)}</b> ` : '') + escapeHtml(e.text);
  ol.appendChild(li);
}

/** Frames the fleet and its missions once they appear, and again only when they leave the view. */
function follow() {
  if (userMoved) return;
  const bounds = L.latLngBounds([]);
  vehicles.forEach(v => { if (v.data && v.data.position) bounds.extend([v.data.position[0], v.data.position[1]]); });
  missions.forEach(m => { if (m.bounds.isValid()) bounds.extend(m.bounds); });
  if (bounds.isValid() && (!fitted || !map.getBounds().contains(bounds))) {
    map.fitBounds(bounds.pad(0.1), { maxZoom: 17, animate: false });
    fitted = true;
  }
}
['mousedown', 'wheel', 'touchstart', 'keydown'].forEach(e => map.getContainer().addEventListener(e, () => { userMoved = true; }));

function apply(data) {
  Object.entries(data.links).forEach(([name, l]) => links.set(name, l));
  data.vehicles.forEach(updateVehicle);
  Object.entries(data.missions).forEach(([id, g]) => updateMission(id, g));
  if (data.executes) renderTree(data.executes);
  appendLog(data.log, data.logLost);
  document.getElementById('run-time').textContent = `t = ${data.time.toFixed(1)} s`;
  renderTable();
  document.getElementById('script').textContent = data.run.script + (data.run.outcome ? ' (' + data.run.outcome + ')' : '');
  follow();
}

function setConnection(state, text) {
  const c = document.getElementById('connection');
  c.dataset.state = state;
  c.textContent = text;
}

function snapshot(data) {
  reset();
  if (data.config.tiles && !tileLayer) {
    tileLayer = L.tileLayer(data.config.tiles, { maxZoom: 19, attribution: 'map tiles: ' + new URL(data.config.tiles.replace(/[{}]/g, ''), location).host }).addTo(map);
  }
  for (const [id, points] of Object.entries(data.tracks)) {
    const v = vehicleEntry(id);
    v.points = points.slice();
    v.track.setLatLngs(v.points);
  }
  apply(data);
}

map.on('zoomend', () => vehicles.forEach(drawArrow));

const events = new EventSource('events' + location.search);
events.addEventListener('snapshot', m => { setConnection('live', 'live'); snapshot(JSON.parse(m.data)); });
events.addEventListener('update', m => apply(JSON.parse(m.data)));
events.addEventListener('end', () => {
  ended = true;
  events.close();
  setConnection('ended', 'the run has ended');
});
events.onerror = () => {
  if (!ended) setConnection('lost', 'connection lost: retrying');
};
window.dolphinView = { vehicles, missions, map };
