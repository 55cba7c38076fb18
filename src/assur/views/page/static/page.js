// assur page: plain JavaScript, no build step. Talks to the JSON API of
// assur.views.page.server; draws the mechanism in SVG itself and the plots with
// plot.js (window.AssurPlot).
"use strict";

const SVGNS = "http://www.w3.org/2000/svg";
const POSITIONS = 101;           // positions drawn over the range (one coordinate)
const COLORS = ["#1f77b4", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2",
                "#7f7f7f", "#bcbd22", "#17becf", "#ff7f0e"];

const state = {
  info: null,          // GET /api/model
  lang: document.body.dataset.lang || "en",
  units: "file",       // the unit system results are shown in (file, engineering, si, imperial)
  values: {},          // parameter -> value in the file's unit (current)
  base: {},            // parameter -> value of the file
  data: null,          // last successful payload of /api/analyze
  pos: 0,              // index of the drawn position
  plots: null,         // [{table, symbol}]
  table: null,         // id of the table shown
  inflight: false, pending: false, seq: 0, t0: 0,
  timer: null,
  urlTimer: undefined, // the address's pending write (saveUrl)
  tableShape: null,    // what the table drawn shows (renderTable)
  tableInView: true,   // the table's box is on the screen (or near it): watchTable
  tableStale: false,   // an answer came while the table was out of view
  history: [],         // earlier parameter sets (undo)
  lastPush: 0,
  traj: new Set(),     // points whose trajectories are drawn
  overlay: false,      // several positions drawn at once
  compare: false,      // the file's design drawn under the edited one
  original: null,      // payload of the file's design (compare)
  plotObjs: [],        // the drawn plots (marker updates)
  url: null,           // what the address restores (parameters, position, plots)
  fields: {},          // parameter -> {unit, factor}: shown in the page's units (value × factor)
  fieldsKey: "",
};

const $ = (id) => document.getElementById(id);
const T = (key) => {
  const t = state.info && state.info.texts[key];
  return t ? (t[state.lang] || t.en) : key;
};

function el(tag, attrs, text) {
  const e = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function h(tag, attrs, text) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function fmt(v) {
  if (v === null || v === undefined) return "";
  if (typeof v !== "number") return String(v);
  const a = Math.abs(v);
  let out;
  if (a !== 0 && (a >= 1e6 || a < 1e-3)) out = v.toExponential(4);
  else if (a >= 1000) out = v.toFixed(0);
  else out = Number(v.toPrecision(5)).toString();
  if (/^-0(\.0*)?$/.test(out)) out = out.slice(1);      // no "-0"
  return state.lang === "ru" ? out.replace(".", ",") : out;
}

// A number as a user types it, in any locale: "17,5" and "17.5" are 17.5; spaces
// (thousands) are ignored. {value} or {empty: true} or {error: "nan" | "range"}.
function parseNumber(text) {
  let s = String(text).trim().replace(/[\s\u00a0\u202f']/g, "");
  if (s === "") return {empty: true};
  if (s.includes(",") && !s.includes(".") && (s.match(/,/g) || []).length === 1)
    s = s.replace(",", ".");
  if (!/^[-+\u2212]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(s)) return {error: "nan"};
  const v = Number(s.replace("\u2212", "-"));
  if (!Number.isFinite(v) || Math.abs(v) > 1e12) return {error: "range"};
  return {value: v};
}

// A value checked against a parameter's physical span: {value} or {error, text}.
function checkValue(p, text) {
  const r = parseNumber(text);
  if (r.empty || r.value === undefined) return r;
  const lo = p.min, hi = p.max;
  if ((lo !== null && r.value < lo) || (hi !== null && r.value > hi) ||
      (p.integer && !Number.isInteger(r.value))) return {error: "range"};
  return r;
}

function spanText(p) {
  const q = shownParam(p);
  const lo = q.min === null ? "−∞" : fmt(q.min), hi = q.max === null ? "∞" : fmt(q.max);
  const u = unitOf(p) ? " " + unitOf(p) : "";
  return (p.integer ? T("whole") + " " : "") + `${lo} … ${hi}${u}`;
}

// a round step (1, 2 or 5 × 10^k) near x
function niceStep(x) {
  if (!(x > 0)) return 1;
  const e = Math.pow(10, Math.floor(Math.log10(x)));
  const m = x / e;
  return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * e;
}

const roundTo = (v, step) => Number((Math.round(v / step) * step).toPrecision(12));

// ---- texts ----------------------------------------------------------------------
function applyTexts() {
  document.documentElement.lang = state.lang;
  for (const e of document.querySelectorAll("[data-t]")) e.textContent = T(e.dataset.t);
  $("lang-toggle").textContent = T("language");
  if (state.info) $("title").textContent = state.info.title[state.lang] || state.info.name;
}

// ---- parameters -----------------------------------------------------------------
// The slider's span and step, in the file's unit: ±45° for an angle, half to one and a
// half times a value otherwise, within the parameter's physical span; a round step.
function sliderRange(p) {
  const v = p.value;
  if (p.integer) return [Math.max(p.min ?? -Infinity, Math.min(0, v - 5)), Math.max(v + 5, 2 * v), 1];
  let lo, hi;
  if (p.unit === "deg" || p.unit === "°") { lo = v - 45; hi = v + 45; }
  else if (p.unit === "rad") { lo = v - 0.8; hi = v + 0.8; }
  else if (v === 0) { lo = -1; hi = 1; }
  else { lo = Math.min(0.5 * v, 1.5 * v); hi = Math.max(0.5 * v, 1.5 * v); }
  if (p.min !== null) lo = Math.max(lo, p.min);
  if (p.max !== null) hi = Math.min(hi, p.max);
  const step = niceStep((hi - lo) / 400);
  lo = Math.floor(lo / step) * step; hi = Math.ceil(hi / step) * step;
  if (p.min !== null) lo = Math.max(lo, p.min);
  if (p.max !== null) hi = Math.min(hi, p.max);
  return [roundTo(lo, step), roundTo(hi, step), step];
}

function fieldText(v, p) {
  const f = p ? fieldOf(p).factor : 1;
  const t = String(Number(Number(v * f).toPrecision(f === 1 ? 12 : 6)));
  return state.lang === "ru" ? t.replace(".", ",") : t;
}

// how a parameter is shown: in the page's units (the file's value × factor)
function fieldOf(p) {
  return state.fields[p.name] || {unit: p.unit_text ? p.unit_text[state.lang] : p.unit,
                                   factor: 1};
}

function unitOf(p) {
  const u = fieldOf(p).unit;
  return u === "-" ? "" : u;
}

// the parameter as the field shows it: value, span and unit in the page's units
function shownParam(p) {
  const f = fieldOf(p).factor;
  return {value: p.value * f, unit: fieldOf(p).unit, integer: p.integer,
          min: p.min === null ? null : p.min * f, max: p.max === null ? null : p.max * f};
}

function fieldMessage(name, text) {
  const m = $("msg-" + name);
  m.textContent = text || "";
  m.hidden = !text;
  $("param-" + name).classList.toggle("invalid", !!text);
}

function buildParams() {
  const box = $("params");
  box.textContent = "";
  let fs = null, group = null;
  for (const p of state.info.parameters) {
    if (!p.editable) continue;
    if (fs === null || p.group !== group) {
      group = p.group;
      fs = h("fieldset");
      if (group) fs.appendChild(h("legend", {}, group));
      box.appendChild(fs);
    }
    state.base[p.name] = p.value;
    if (!(p.name in state.values)) state.values[p.name] = p.value;
    const v = state.values[p.name];
    const row = h("div", {class: "param", id: "param-" + p.name, title: p.comment || ""});
    row.appendChild(h("label", {for: "input-" + p.name}, p.name));
    const factor = fieldOf(p).factor;
    const [lo, hi, step] = sliderRange(shownParam(p));
    const slider = h("input", {type: "range", id: "slider-" + p.name, min: lo, max: hi,
                               step: step, value: v * factor, "aria-label": p.name});
    const input = h("input", {type: "text", inputmode: "decimal", id: "input-" + p.name,
                              value: fieldText(v, p), autocomplete: "off"});
    row.appendChild(slider);
    row.appendChild(input);
    row.appendChild(h("span", {class: "unit"}, unitOf(p)));
    const msg = h("div", {class: "field-msg", id: "msg-" + p.name, role: "alert"});
    msg.hidden = true;
    row.appendChild(msg);
    slider.addEventListener("input", () => {
      const x = roundTo(Number(slider.value), step) / factor;   // the file's unit
      input.value = fieldText(x, p);
      fieldMessage(p.name, "");
      setParam(p.name, x);
    });
    input.addEventListener("input", () => {
      const r = checkValue(shownParam(p), input.value);
      if (r.empty) {
        fieldMessage(p.name, `${T("field_empty")} ${fieldText(state.values[p.name], p)} ${unitOf(p)}`);
        return;
      }
      if (r.error) {
        fieldMessage(p.name, `${T(r.error === "nan" ? "field_nan" : "field_range")} ` +
                             spanText(p));
        return;
      }
      fieldMessage(p.name, "");
      slider.value = r.value;
      setParam(p.name, r.value / factor);
    });
    input.addEventListener("blur", () => {   // the field shows the value in force
      if (!$("msg-" + p.name).hidden) return;
      input.value = fieldText(state.values[p.name], p);
    });
    row.classList.toggle("changed", v !== p.value);
    fs.appendChild(row);
  }
}

function setParam(name, v) {
  const now = performance.now();
  if (now - state.lastPush > 700) {        // a pause starts a new step of undo
    state.history.push(Object.assign({}, state.values));
    if (state.history.length > 100) state.history.shift();
  }
  state.lastPush = now;
  state.values[name] = v;
  $("param-" + name).classList.toggle("changed", v !== state.base[name]);
  $("undo").disabled = !state.history.length;
  request();
}

function changed() {
  const out = {};
  for (const [k, v] of Object.entries(state.values)) if (v !== state.base[k]) out[k] = v;
  return out;
}

function showValues() {
  const params = Object.fromEntries(state.info.parameters.map(p => [p.name, p]));
  for (const [k, v] of Object.entries(state.values)) {
    $("input-" + k).value = fieldText(v, params[k]);
    $("slider-" + k).value = v * fieldOf(params[k]).factor;
    $("param-" + k).classList.toggle("changed", v !== state.base[k]);
    fieldMessage(k, "");
  }
  $("undo").disabled = !state.history.length;
}

function resetParams() {
  state.history.push(Object.assign({}, state.values));
  state.values = Object.assign({}, state.base);
  showValues();
  request();
}

function undo() {
  if (!state.history.length) return;
  state.values = state.history.pop();
  state.lastPush = 0;
  showValues();
  request();
}

// ---- the address: parameters, position, language, units and plots survive a reload
// Written a moment after the last redraw, not during it: the browser's history update
// (replaceState) costs tens of milliseconds, which a drag of a slider would pay at
// every step; a page left or reloaded before then writes it at once.
const URL_DELAY = 150;  // [ms]

function saveUrl() {
  clearTimeout(state.urlTimer);
  state.urlTimer = setTimeout(writeUrl, URL_DELAY);
}

function flushUrl() {
  if (state.urlTimer === undefined) return;
  clearTimeout(state.urlTimer);
  state.urlTimer = undefined;
  writeUrl();
}

function writeUrl() {
  state.urlTimer = undefined;
  const u = new URLSearchParams();
  u.set("lang", state.lang);
  u.set("units", state.units);
  u.set("pos", String(state.pos));
  for (const [k, v] of Object.entries(changed())) u.set("p." + k, String(v));
  if (state.plots) u.set("plots", state.plots.map(p => [p.table, p.symbol, p.x || "",
                                                       (p.with || []).join("+")].join("~")).join(","));
  if (state.traj.size) u.set("traj", [...state.traj].join(","));
  history.replaceState(null, "", location.pathname + "?" + u.toString());
}

function readUrl() {
  const u = new URLSearchParams(location.search);
  const out = {params: {}};
  for (const [k, v] of u.entries()) {
    if (k.startsWith("p.")) {
      const r = parseNumber(v);
      if (r.value !== undefined) out.params[k.slice(2)] = r.value;
    }
  }
  if (u.has("lang") && ["en", "ru"].includes(u.get("lang"))) out.lang = u.get("lang");
  if (u.has("units") && ["file", "engineering", "si", "imperial"].includes(u.get("units")))
    out.units = u.get("units");
  if (u.has("pos") && /^\d+$/.test(u.get("pos"))) out.pos = Number(u.get("pos"));
  if (u.has("plots")) out.plots = u.get("plots").split(",").filter(x => x.includes("~"))
    .map(x => {
      const [table, symbol, over, w] = x.split("~");
      return {table, symbol, x: over || undefined, with: w ? w.split("+") : []};
    });
  if (u.has("traj")) out.traj = u.get("traj").split(",").filter(Boolean);
  return out;
}

// ---- requests -------------------------------------------------------------------
function request() {
  state.t0 = performance.now();
  if (state.inflight) { state.pending = true; return; }
  send();
}

function positionsOf() {
  return state.info.coordinates.length > 1 ? {} : {positions: POSITIONS};
}

// POST a JSON request; the answer's JSON, or {ok: false, error} saying in words what
// went wrong (the server not answering, an answer that is not JSON)
async function post(path, extra, params) {
  let r;
  try {
    r = await fetch(path, {method: "POST", headers: {"Content-Type": "application/json"},
      body: JSON.stringify(Object.assign({params: params || changed(), lang: state.lang,
                                          units: state.units}, extra || {}))});
  } catch (e) {
    return {response: null, out: {ok: false, error: {kind: "network", message: T("server_down")}}};
  }
  return {response: r, out: null};
}

// an answer asked for with {packed: true}: each table column's values come as
// {f64: base64 of little-endian float64}; here they become the lists of numbers the
// page reads, null where a value is undefined (NaN), as in an unpacked answer; so do
// the drawing's points ([x, y] by position), coordinates and wheels' headings
function float64(p) {
  let bytes;
  if (Uint8Array.fromBase64) bytes = Uint8Array.fromBase64(p.f64);   // native (2025 on)
  else {
    const bin = atob(p.f64);
    bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  }
  return new Float64Array(bytes.buffer, bytes.byteOffset, bytes.length / 8);   // little-endian
}

function packed(v) { return v && typeof v.f64 === "string"; }

function unpack(out) {
  if (!out || !out.tables) return out;
  for (const t of out.tables) {
    for (const c of t.columns) {
      if (!packed(c.values)) continue;
      const f = float64(c.values);
      const v = new Array(f.length);
      for (let i = 0; i < f.length; i++) v[i] = Number.isFinite(f[i]) ? f[i] : null;
      c.values = v;
    }
  }
  const g = out.geometry;
  if (!g) return out;
  for (const [p, v] of Object.entries(g.points)) {
    if (!packed(v)) continue;
    const f = float64(v);
    const xy = new Array(f.length / 2);
    for (let i = 0; i < xy.length; i++) xy[i] = [f[2 * i], f[2 * i + 1]];
    g.points[p] = xy;
  }
  for (const [c, v] of Object.entries(g.q)) if (packed(v)) g.q[c] = Array.from(float64(v));
  for (const w of g.wheels || []) if (packed(w.heading)) w.heading = Array.from(float64(w.heading));
  return out;
}

async function send() {
  state.inflight = true;
  state.pending = false;
  // busy: the status only (a class on the body would restyle the whole page, the
  // table's thousand cells too, while the server computes: ~10 ms of the redraw)
  $("status").classList.add("busy");
  const t0 = state.t0;
  const seq = ++state.seq;
  $("status").textContent = T("computing");
  let {response, out} = await post("/api/analyze", Object.assign({packed: true}, positionsOf()));
  if (!out) {
    try { out = unpack(await response.json()); }
    catch (e) { out = {ok: false, error: {kind: "network", message: `${T("bad_answer")} (HTTP ${response.status})`}}; }
  }
  const answered = performance.now();
  if (seq === state.seq) {
    if (out.ok) showResult(out); else showError(out.error);
    const ms = performance.now() - t0;
    const parts = `answer ${(answered - t0).toFixed(1)} ms, drawing ${(performance.now() - answered).toFixed(1)} ms`;
    $("status").textContent = out.ok || out.error.kind !== "network"
      ? `${T("redrawn")} ${ms.toFixed(0)} ${T("ms")}` : T("no_server");
    $("status").dataset.ms = ms.toFixed(1);
    console.log(`assur: redrawn in ${ms.toFixed(1)} ms (server ${out.ms} ms, ${parts}, ` +
                `${out.ok ? "drawing" : "error: " + out.error.kind})`);
  }
  state.inflight = false;
  $("status").classList.remove("busy");
  if (state.pending) send();
}

async function loadOriginal() {
  if (state.original && state.original.units.system === state.data.units.system &&
      state.original.lang === state.lang) return;
  const {response, out} = await post("/api/analyze", Object.assign({packed: true}, positionsOf()), {});
  if (out) return;
  const o = unpack(await response.json());
  if (o.ok) { o.lang = state.lang; state.original = o; renderPose(); renderPlots(); }
}

// the coordinates of the drawn position, as DXF requests them (m, or degrees)
function positionAt() {
  const q = state.data.geometry.q;
  return state.data.coordinates.map(c => {
    const v = q[c.name][state.pos];
    return c.kind === "angle" ? v * 180 / Math.PI : v;
  });
}

async function download(kind, button) {
  const extra = positionsOf();
  if (kind === "csv" && state.table) extra.table = state.table;
  if (kind === "dxf") {
    if (!state.data) return;
    extra.at = positionAt();
  }
  if (kind === "toml") delete extra.positions;
  const label = button.textContent;
  button.disabled = true;
  button.classList.add("busy");
  button.textContent = T("preparing");
  $("download-msg").textContent = "";
  try {
    const {response, out} = await post("/api/export/" + kind, extra);
    if (out) { $("download-msg").textContent = `${T("download_failed")}: ${out.error.message}`; return; }
    const type = response.headers.get("content-type") || "";
    if (!response.ok || type.startsWith("application/json")) {
      let why = `HTTP ${response.status}`;
      try { const o = await response.json(); if (o.error) why = o.error.message; } catch (e) { /* not JSON */ }
      $("download-msg").textContent = `${T("download_failed")}: ${why}`;
      return;
    }
    const blob = await response.blob();
    const m = /filename="([^"]+)"/.exec(response.headers.get("content-disposition") || "");
    const a = h("a", {href: URL.createObjectURL(blob), download: m ? m[1] : "assur." + kind});
    document.body.appendChild(a);
    a.click();
    a.remove();
  } finally {
    button.disabled = false;
    button.classList.remove("busy");
    button.textContent = label;
  }
}

// ---- results --------------------------------------------------------------------
function showError(err) {
  $("drawing-box").classList.add("failed");
  $("error-panel").hidden = false;
  $("error-message").textContent = err.message;
  $("error-panel").dataset.kind = err.kind;
  $("plots").classList.add("pending");
  $("table-box").classList.add("pending");
}

function showResult(out) {
  const first = state.data === null;
  state.data = out;
  $("drawing-box").classList.remove("failed");
  $("error-panel").hidden = true;
  $("error-message").textContent = "";
  $("plots").classList.remove("pending");
  $("table-box").classList.remove("pending");
  $("title").textContent = out.title;
  document.title = `${out.title} — assur`;
  const key = JSON.stringify(out.fields || {});
  if (key !== state.fieldsKey) {          // the units or the language changed: the fields too
    state.fieldsKey = key;
    state.fields = out.fields || {};
    buildParams();
  }
  const n = out.geometry.n;
  if (state.pos > n - 1) state.pos = n - 1;
  buildSliders(out);
  prepareDrawing(out.geometry);
  if (state.plots === null) state.plots = out.defaults.slice();
  if (first && !state.traj.size && out.turn) {
    // a crank: the coupler curves of the points on one body only (not joints)
    const joints = new Set(out.geometry.joints);
    for (const p of Object.keys(out.geometry.points)) if (!joints.has(p)) state.traj.add(p);
  }
  if (!state.table || !out.tables.some(t => t.id === state.table))
    state.table = out.tables.length ? out.tables[0].id : null;
  buildTableSelect(out.tables);
  buildPlotSelect(out.tables);
  renderSolved(out.solved);
  renderWarnings(out.warnings);
  renderTable();
  renderPlots();
  renderPose();
  if (state.compare) loadOriginal();
}

function renderSolved(solved) {
  const ul = $("solved");
  ul.textContent = "";
  $("solved-head").hidden = ul.hidden = !solved.length;     // no empty headings
  for (const s of solved)
    ul.appendChild(h("li", {id: "solved-" + s.name},
      `${s.name} = ${fmt(s.value)} ${s.unit === "-" ? "" : s.unit} (${T("solved_value")})`));
}

function renderWarnings(ws) {
  const ul = $("warnings");
  ul.textContent = "";
  if (!ws.length) ul.appendChild(h("li", {}, T("no_warnings")));
  for (const w of ws) ul.appendChild(h("li", {}, w));
}

// ---- position: one slider, or one per coordinate of a grid -----------------------
function gridIndex(i, j) {
  const g = state.data.grid;
  for (let k = 0; k < g.i.length; k++) if (g.i[k] === i && g.j[k] === j) return k;
  return null;
}

function setPos(k) {
  if (k === null || k === undefined) return;
  state.pos = k;
  syncSliders();
  renderPose();
}

function syncSliders() {
  const d = state.data;
  if (d.grid) {
    $("coord-0").value = d.grid.i[state.pos];
    $("coord-1").value = d.grid.j[state.pos];
  } else {
    $("stroke").value = state.pos;
  }
}

function buildSliders(out) {
  const box = $("coord-sliders");
  const key = JSON.stringify([out.coordinates.map(c => c.name), !!out.grid, out.geometry.n]);
  $("stroke-row").hidden = !!out.grid;
  $("stroke").max = out.geometry.n - 1;
  if (box.dataset.key !== key) {
    box.dataset.key = key;
    box.textContent = "";
    if (out.grid) {
      out.coordinates.forEach((c, k) => {
        const vals = k === 0 ? out.grid.x : out.grid.y;
        const row = h("div", {class: "coord"});
        row.appendChild(h("label", {for: "coord-" + k}, c.name));
        const sl = h("input", {type: "range", id: "coord-" + k, min: 0, max: vals.length - 1,
                               step: 1, value: 0});
        sl.addEventListener("input", () => {
          const i = Number($("coord-0").value), j = Number($("coord-1").value);
          setPos(gridIndex(i, j));
        });
        row.appendChild(sl);
        box.appendChild(row);
      });
    }
  }
  syncSliders();
}

// ---- drawing --------------------------------------------------------------------
let geo = null;   // the geometry with its view box and cylinder sizes

function hull(pts) {
  const p = pts.map(a => [a[0], a[1]]).sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  if (p.length <= 2) return p;
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lo = [], up = [];
  for (const q of p) {
    while (lo.length >= 2 && cross(lo[lo.length - 2], lo[lo.length - 1], q) <= 0) lo.pop();
    lo.push(q);
  }
  for (const q of p.slice().reverse()) {
    while (up.length >= 2 && cross(up[up.length - 2], up[up.length - 1], q) <= 0) up.pop();
    up.push(q);
  }
  return lo.slice(0, -1).concat(up.slice(0, -1));
}

function prepareDrawing(g) {
  const [x0, y0, x1, y1] = g.bounds;
  const span = Math.max(x1 - x0, y1 - y0, 1e-6);
  const m = 0.08 * span;
  const cyl = {};
  for (const b of g.bodies) {
    if (!b.variable || b.points.length < 2) continue;
    const a = g.points[b.points[0]], c = g.points[b.points[1]];
    let lmin = Infinity, lmax = 0;
    for (let i = 0; i < g.n; i++) {
      const L = Math.hypot(c[i][0] - a[i][0], c[i][1] - a[i][1]);
      lmin = Math.min(lmin, L); lmax = Math.max(lmax, L);
    }
    const barrel = 0.7 * lmin;
    const rod = Math.min(Math.max(lmax - barrel + 0.08 * lmin, 0.35 * lmin), 0.95 * lmin);
    cyl[b.name] = [barrel, rod];
  }
  let cx = 0, cy = 0, k = 0;
  for (const v of Object.values(g.points)) for (const p of v) { cx += p[0]; cy += p[1]; k++; }
  geo = {g, span, cyl, centre: [cx / k, cy / k]};
  const svg = $("drawing");
  // y up: the SVG's y is −y of the model; the box fits every position (and the weights'
  // arrows below), scaled to the drawing box whatever the machine's proportions
  const wy = g.weights.length ? 0.14 * span : 0;
  const vw = x1 - x0 + 2 * m, vh = y1 - y0 + 2 * m + wy;
  svg.setAttribute("viewBox", `${x0 - m} ${-(y1 + m)} ${vw} ${vh}`);
  // the box takes the machine's proportions (a tall crane gets a tall box); its width
  // read (a layout of the page) only when the proportions change, not on every answer
  const box = $("drawing-box");
  const aspect = (vh / vw).toFixed(2);
  if (box.dataset.aspect !== aspect) {
    box.dataset.aspect = aspect;
    const w = box.clientWidth || 600;
    box.style.height = `${Math.round(Math.min(Math.max(w * vh / vw, 320), 720))}px`;
  }
  svg.setAttribute("preserveAspectRatio", "xMidYMid meet");
}

// labels placed where they overlap no label placed before (8 directions tried, then
// farther out), boxes estimated from the font size
function placer(fs) {
  const boxes = [];
  const hit = (b) => boxes.some(o => b[0] < o[2] && o[0] < b[2] && b[1] < o[3] && o[1] < b[3]);
  return (x, y, text, prefer) => {
    const w = 0.62 * fs * text.length, hh = fs;
    const dirs = [prefer];
    for (let a = 0; a < 8; a++) dirs.push([Math.cos(a * Math.PI / 4), Math.sin(a * Math.PI / 4)]);
    for (const r of [1.3, 2.2, 3.2]) {
      for (const d of dirs) {
        const cx = x + d[0] * r * fs, cy = y + d[1] * r * fs;
        const b = [cx - w / 2, cy - hh / 2, cx + w / 2, cy + hh / 2];
        if (!hit(b)) { boxes.push(b); return [cx, cy]; }
      }
    }
    const b = [x - w / 2, y + fs, x + w / 2, y + 2 * fs];
    boxes.push(b);
    return [x, y + 1.5 * fs];
  };
}

function drawBodies(svg, g, i, ghost) {
  const {cyl} = geo;
  const xy = {};
  for (const [p, v] of Object.entries(g.points)) xy[p] = [v[i][0], -v[i][1]];
  const mids = [];
  let k = 0;
  for (const b of g.bodies) {
    if (b.name === "0") continue;
    const pts = b.points.filter(p => p in xy).map(p => xy[p]);
    const col = ghost ? "#9aa4ae" : COLORS[k % COLORS.length];
    k++;
    const grp = el("g", ghost ? {class: "ghost"} : {id: "link-" + b.name, "data-link": b.name});
    let mid;
    if (b.name in cyl && pts.length >= 2) {
      const [a, c] = pts;
      const L = Math.hypot(c[0] - a[0], c[1] - a[1]) || 1e-12;
      const u = [(c[0] - a[0]) / L, (c[1] - a[1]) / L];
      const [barrel, rod] = cyl[b.name];
      const e1 = [a[0] + u[0] * Math.min(barrel, L), a[1] + u[1] * Math.min(barrel, L)];
      const e2 = [c[0] - u[0] * Math.min(rod, L), c[1] - u[1] * Math.min(rod, L)];
      grp.appendChild(el("line", {x1: a[0], y1: a[1], x2: e1[0], y2: e1[1],
        stroke: ghost ? col : "#4a7ab8", "stroke-width": ghost ? 4 : 9,
        "vector-effect": "non-scaling-stroke"}));
      grp.appendChild(el("line", {x1: e2[0], y1: e2[1], x2: c[0], y2: c[1],
        stroke: ghost ? col : "#222", "stroke-width": ghost ? 1.5 : 3,
        "vector-effect": "non-scaling-stroke"}));
      mid = [a[0] + u[0] * 0.5 * Math.min(barrel, L), a[1] + u[1] * 0.5 * Math.min(barrel, L)];
    } else {
      const hl = hull(pts);
      if (hl.length >= 3) {
        grp.appendChild(el("polygon", {points: hl.map(p => p.join(",")).join(" "),
          fill: ghost ? "none" : col, "fill-opacity": 0.12, stroke: col,
          "stroke-width": ghost ? 1.2 : 2.5, "stroke-dasharray": ghost ? "4,3" : "none",
          "vector-effect": "non-scaling-stroke", "stroke-linejoin": "round"}));
      } else if (hl.length === 2) {
        grp.appendChild(el("line", {x1: hl[0][0], y1: hl[0][1], x2: hl[1][0], y2: hl[1][1],
          stroke: col, "stroke-width": ghost ? 1.2 : 3, "stroke-linecap": "round",
          "stroke-dasharray": ghost ? "4,3" : "none", "vector-effect": "non-scaling-stroke"}));
      }
      mid = hl.length ? [hl.reduce((s, p) => s + p[0], 0) / hl.length,
                         hl.reduce((s, p) => s + p[1], 0) / hl.length] : pts[0];
    }
    svg.appendChild(grp);
    if (mid && !ghost) mids.push([b.name, mid, b.name in cyl ? "#4a7ab8" : col, grp]);
  }
  return {xy, mids};
}

function drawWheels(svg, g, i, ghost) {
  for (const w of g.wheels || []) {
    if (!(w.point in g.points)) continue;
    const [x, y] = g.points[w.point][i];
    const a = w.heading[i];
    const u = [Math.cos(a), Math.sin(a)], n = [-u[1], u[0]];
    const L = w.length / 2, W = w.width / 2;
    const pts = [[L, W], [-L, W], [-L, -W], [L, -W]]
      .map(([p, q]) => [x + u[0] * p + n[0] * q, -(y + u[1] * p + n[1] * q)]);
    svg.appendChild(el("polygon", {class: ghost ? "ghost wheel" : "wheel",
      "data-wheel": typeof w.name === "string" ? w.name : (w.name[state.lang] || w.name.en),
      points: pts.map(p => p.join(",")).join(" "), fill: ghost ? "none" : "#444",
      "fill-opacity": 0.55, stroke: ghost ? "#9aa4ae" : "#111", "stroke-width": 1.5,
      "vector-effect": "non-scaling-stroke"}));
  }
}

function renderPose() {
  if (!geo) return;
  const {g, span, centre} = geo;
  const i = state.pos;
  const svg = $("drawing");
  svg.textContent = "";
  const fs = 0.026 * span, hh = 0.03 * span;
  // the file's design under the edited one, several positions at once, trajectories
  if (state.compare && state.original && state.original.geometry.n === g.n) {
    drawBodies(svg, state.original.geometry, i, true);
    drawWheels(svg, state.original.geometry, i, true);
  }
  if (state.overlay) {
    for (let k = 0; k < 6; k++) {
      const j = Math.round(k * (g.n - 1) / 5);
      if (j !== i) drawBodies(svg, g, j, true);
    }
  }
  for (const p of state.traj) {
    if (!(p in g.points)) continue;
    const d = g.points[p].map((q, k) => `${k ? "L" : "M"}${q[0]},${-q[1]}`).join(" ") +
      (state.data.turn ? " Z" : "");
    svg.appendChild(el("path", {class: "trajectory", "data-point": p, d, fill: "none",
      stroke: "#b3541e", "stroke-width": 1, "stroke-dasharray": "5,3",
      "vector-effect": "non-scaling-stroke"}));
  }
  drawWheels(svg, g, i, false);
  const {xy, mids} = drawBodies(svg, g, i, false);
  for (const p of g.frame) {
    const [x, y] = xy[p];
    svg.appendChild(el("polygon", {points: `${x},${y} ${x - 0.55 * hh},${y + hh} ` +
      `${x + 0.55 * hh},${y + hh}`, fill: "#fff", stroke: "#000", "stroke-width": 1.2,
      "vector-effect": "non-scaling-stroke"}));
    svg.appendChild(el("line", {x1: x - 0.8 * hh, y1: y + hh, x2: x + 0.8 * hh, y2: y + hh,
      stroke: "#000", "stroke-width": 1.2, "vector-effect": "non-scaling-stroke"}));
  }
  const place = placer(fs);
  const joints = new Set(g.joints);
  const labels = [];
  for (const [p, [x, y]] of Object.entries(xy)) {
    const j = joints.has(p);
    const c = el("circle", {id: "pt-" + p, cx: x, cy: y, r: (j ? 0.011 : 0.007) * span,
      fill: j ? "#fff" : "#000", stroke: "#000", "stroke-width": 1.3, class: "point",
      "vector-effect": "non-scaling-stroke", "data-x": g.points[p][i][0],
      "data-y": g.points[p][i][1]});
    c.appendChild(el("title", {}, `${p}: ${T("click_trajectory")}`));
    c.addEventListener("click", () => {
      if (state.traj.has(p)) state.traj.delete(p); else state.traj.add(p);
      renderPose();
    });
    svg.appendChild(c);
    const d = [x - centre[0], y + centre[1]];
    const n = Math.hypot(d[0], d[1]) || 1;
    const [lx, ly] = place(x, y, p, [d[0] / n, d[1] / n]);
    labels.push(el("text", {x: lx, y: ly, "font-size": fs, "text-anchor": "middle",
      "dominant-baseline": "middle", class: "point-label"}, p));
  }
  for (const [name, mid, col, grp] of mids) {
    const [lx, ly] = place(mid[0], mid[1], name, [0.7, -0.7]);
    grp.appendChild(el("text", {x: lx, y: ly, "font-size": fs * 1.1, fill: col,
      "font-style": "italic", "font-weight": "bold", "text-anchor": "middle",
      "dominant-baseline": "middle", class: "link-label"}, name));
  }
  for (const t of labels) svg.appendChild(t);
  for (const w of g.weights) {
    if (!(w.point in xy)) continue;
    const [x, y] = xy[w.point];
    const L = 0.12 * span;
    svg.appendChild(el("line", {x1: x, y1: y, x2: x, y2: y + L, stroke: "#d62728",
      "stroke-width": 1.5, "vector-effect": "non-scaling-stroke"}));
    svg.appendChild(el("polygon", {points: `${x},${y + L} ${x - 0.15 * L},${y + 0.75 * L} ` +
      `${x + 0.15 * L},${y + 0.75 * L}`, fill: "#d62728"}));
    const [lx, ly] = place(x, y + L, w.name, [1, 0]);
    svg.appendChild(el("text", {x: lx, y: ly, "font-size": fs, fill: "#d62728",
      "text-anchor": "middle", "dominant-baseline": "middle"}, w.name));
  }
  $("position-text").textContent = positionText(i);
  renderCurrent();
  markPlots();
  markTable();
  saveUrl();
}

function coordText(c, i) {
  const v = state.data.geometry.q[c.name][i];   // [m or rad], shown in the page's units
  const u = state.data.units;
  const shown = c.kind === "angle" ? v / u.angle_scale : v / u.length_scale;
  const unit = c.kind === "angle" ? u.angle : u.length;
  return unit === "°" || unit === "deg" ? `${c.name} = ${fmt(shown)}°`
                                        : `${c.name} = ${fmt(shown)} ${unit}`;
}

function positionText(i) {
  if (!state.data) return "";
  const parts = state.data.coordinates.map(c => coordText(c, i));
  return parts.join(", ") + ` (${T("position")} ${i + 1}/${state.data.geometry.n})`;
}

// ---- tables ---------------------------------------------------------------------
function currentTable() {
  return state.data ? state.data.tables.find(t => t.id === state.table) : null;
}

function perPosition(t) {
  return t.columns.length && t.columns[0].values.length === state.data.geometry.n;
}

// the tables' and the plots' choices, built again only when the tables' names change
// (the language, the units), not on every answer
function buildTableSelect(tables) {
  const s = $("table-select");
  const key = JSON.stringify([state.lang, tables.map(t => [t.id, t.label, t.title])]);
  if (s.dataset.key === key) { s.value = state.table; return; }
  s.dataset.key = key;
  s.textContent = "";
  for (const t of tables) s.appendChild(h("option", {value: t.id}, `${t.label} — ${t.title}`));
  s.value = state.table;
}

function renderCurrent() {
  const t = currentTable();
  const box = $("current-values");
  box.textContent = "";
  $("current-box").hidden = !t || !perPosition(t);
  if (!t || !perPosition(t)) return;
  for (const c of t.columns) {
    const tr = h("tr", {"data-symbol": c.symbol});
    tr.appendChild(h("td", {title: c.label}, c.symbol));
    tr.appendChild(h("td", {class: "v", id: "value-" + c.symbol}, fmt(c.values[state.pos])));
    tr.appendChild(h("td", {}, c.unit === "-" ? "" : c.unit));
    box.appendChild(tr);
  }
}

// The table of the current results: built when its shape (table, columns, rows, units,
// language) changes, else only its cells' texts replaced — a parameter change then
// rewrites a thousand texts instead of building a thousand elements; and not even those
// while the table is scrolled out of view (below the drawing and the plots): then they
// are rewritten when it comes into view (watchTable). force: now, in view or not.
function renderTable(force) {
  const t = currentTable();
  const tab = $("table");
  if (!t) {
    tab.textContent = "";
    $("table-notes").textContent = "";
    state.tableShape = null;
    return;
  }
  const n = t.columns.length ? t.columns[0].values.length : 0;
  const shape = JSON.stringify([t.id, t.label, t.title, t.columns.map(c => [c.symbol, c.unit, c.label]), n]);
  const same = shape === state.tableShape && tab.rows.length === n + 1;
  state.tableStale = same && !force && !state.tableInView;
  if (state.tableStale) return;
  const notes = $("table-notes");
  notes.textContent = "";
  notes.appendChild(h("h3", {}, `${T("table")} ${t.label}. ${t.title}`));
  for (const x of t.notes) if (x) notes.appendChild(h("p", {}, x));
  if (same) {
    for (let i = 0; i < n; i++) {
      const cells = tab.rows[i + 1].cells;
      t.columns.forEach((c, k) => {
        const s = fmt(c.values[i]);
        if (cells[k].textContent !== s) cells[k].textContent = s;
      });
    }
    markTable();
    return;
  }
  state.tableShape = shape;
  tab.textContent = "";
  const head = h("tr");
  for (const c of t.columns)
    head.appendChild(h("th", {title: c.label}, c.unit === "-" ? c.symbol : `${c.symbol} [${c.unit}]`));
  tab.appendChild(head);
  const rows = document.createDocumentFragment();
  for (let i = 0; i < n; i++) {
    const tr = h("tr", {"data-row": i});
    for (const c of t.columns) tr.appendChild(h("td", {}, fmt(c.values[i])));
    rows.appendChild(tr);
  }
  tab.appendChild(rows);
  markTable();
}

// whether the table's box is on the screen (within 400 px of it): the table is brought
// up to date when it comes into view after answers that came while it was not
function watchTable() {
  if (!("IntersectionObserver" in window)) return;
  new IntersectionObserver((entries) => {
    for (const e of entries) {
      state.tableInView = e.isIntersecting;
      if (e.isIntersecting && state.tableStale) renderTable(true);
    }
  }, {rootMargin: "400px"}).observe($("table-box"));
}

// a click on a row of a per-position table picks that position (one listener)
function tableClick(e) {
  const tr = e.target.closest("tr[data-row]");
  const t = currentTable();
  if (tr && t && perPosition(t)) setPos(Number(tr.dataset.row));
}

function markTable() {
  for (const tr of document.querySelectorAll("#table tr.current")) tr.classList.remove("current");
  const t = currentTable();
  if (!t || !perPosition(t)) return;
  const tr = document.querySelector(`#table tr[data-row="${state.pos}"]`);
  if (tr) tr.classList.add("current");
}

// ---- plots ----------------------------------------------------------------------
function findColumn(tables, table, symbol) {
  const t = tables.find(x => x.id === table);
  return t ? t.columns.find(c => c.symbol === symbol) : null;
}

function buildPlotSelect(tables) {
  const s = $("add-plot");
  const nc = state.data.coordinates.length;
  const key = JSON.stringify([state.lang, nc, tables.map(t => [
    t.id, t.label, t.title, perPosition(t), t.columns.map(c => [c.symbol, c.unit, c.label])])]);
  if (s.dataset.key === key) return;
  s.dataset.key = key;
  s.textContent = "";
  s.appendChild(h("option", {value: ""}, "+ " + T("add_plot")));
  for (const t of tables) {
    if (!perPosition(t)) continue;
    const og = h("optgroup", {label: `${t.label} — ${t.title}`});
    for (const c of t.columns.slice(nc)) {
      const u = c.unit === "-" ? "" : ` [${c.unit}]`;
      og.appendChild(h("option", {value: `${t.id}\u0000${c.symbol}`},
        c.label ? `${c.symbol}${u} — ${c.label}` : `${c.symbol}${u}`));
    }
    s.appendChild(og);
  }
}

const ANGLE_UNITS = {"°": 360, "deg": 360, "rad": 2 * Math.PI};

// the abscissa of one-coordinate plots: the coordinate itself, unwrapped (a crank's
// angle runs on through the turn), in the page's units; of a path of several
// coordinates the first that moves monotonically along it; else the position number
function abscissa(d) {
  const u = d.units;
  for (const c of d.coordinates) {
    const q = d.geometry.q[c.name];
    let up = true, down = true;
    for (let i = 1; i < q.length; i++) { up = up && q[i] > q[i - 1]; down = down && q[i] < q[i - 1]; }
    if (up || down) {
      const angle = c.kind === "angle";
      const x = q.map(v => v / (angle ? u.angle_scale : u.length_scale));
      return {x, label: `${c.name} [${angle ? u.angle : u.length}]`};
    }
  }
  return {x: d.geometry.q[d.coordinates[0].name].map((_, i) => i + 1), label: T("position")};
}

function plotFormat(v) { return fmt(v); }

function renderPlots() {
  const box = $("plots");
  box.textContent = "";
  for (const o of state.plotObjs) if (o.destroy) o.destroy();
  state.plotObjs = [];
  const d = state.data;
  if (!d) return;
  const nc = d.coordinates.length;
  const orig = state.compare && state.original ? state.original : null;
  state.plots.forEach((p, k) => {
    const c = findColumn(d.tables, p.table, p.symbol);
    if (!c) return;
    const t = d.tables.find(x => x.id === p.table);
    const div = h("div", {class: "plot", id: `plot-${p.table}-${p.symbol}`});
    const u = c.unit === "-" ? "" : ` [${c.unit}]`;
    div.appendChild(h("div", {class: "title"}, `${p.symbol}${u} — ${c.label || t.title}`));
    const rm = h("button", {type: "button", class: "remove", "aria-label": T("remove")}, "×");
    rm.title = T("remove");
    rm.addEventListener("click", () => { state.plots.splice(k, 1); renderPlots(); saveUrl(); });
    div.appendChild(rm);
    const ylabel = `${p.symbol}${u}`;
    const period = ANGLE_UNITS[c.unit];
    if (d.grid) {
      // a map over the two coordinates (a click picks the position) and the curve over
      // the first with the second held where it is
      const g = d.grid;
      const z = g.y.map(() => g.x.map(() => null));
      c.values.forEach((v, i) => { z[g.j[i]][g.i[i]] = v; });
      const cx = d.tables[0].columns[0], cy = d.tables[0].columns[1];
      const map = AssurPlot.map({x: g.x, y: g.y, z, xlabel: `${cx.symbol} [${cx.unit}]`,
        ylabel: `${cy.symbol} [${cy.unit}]`, zlabel: ylabel, format: plotFormat,
        onpick: (i, j) => setPos(gridIndex(i, j))});
      map.el.classList.add("map");
      div.appendChild(map.el);
      const held = () => g.j[state.pos];
      const curve = {el: h("div", {class: "held"}), draw: null};
      const drawCurve = () => {
        const j = held();
        const ys = g.x.map((_, i) => z[j][i]);
        curve.el.textContent = "";
        const lp = AssurPlot.line({series: [{x: g.x, y: ys,
            label: `${ylabel}, ${coordText(d.coordinates[1], state.pos)}`}],
          xlabel: `${cx.symbol} [${cx.unit}]`, ylabel, period, format: plotFormat,
          onpick: (i) => setPos(gridIndex(i, held()))});
        curve.el.appendChild(lp.el);
        curve.plot = lp;
        curve.j = j;
      };
      drawCurve();
      div.appendChild(curve.el);
      state.plotObjs.push({marker: () => {
        map.marker(g.i[state.pos], g.j[state.pos]);
        if (curve.j !== held()) drawCurve();
        curve.plot.marker(g.i[state.pos]);
      }, destroy: () => { map.destroy && map.destroy(); curve.plot.destroy && curve.plot.destroy(); }});
    } else {
      const ax = abscissa(d);
      // over the coordinate, or over another column of the table (β over α)
      const xc = p.x ? t.columns.find(q => q.symbol === p.x) : null;
      const xs = xc ? xc.values : ax.x;
      const xlabel = xc ? (xc.unit === "-" ? xc.symbol : `${xc.symbol} [${xc.unit}]`) : ax.label;
      const series = [{x: xs, y: c.values, label: (p.with || []).length ? c.label || p.symbol : ""}];
      for (const w of p.with || []) {
        const wc = t.columns.find(q => q.symbol === w);
        if (wc) series.push({x: xs, y: wc.values, label: wc.label || w, dash: true});
      }
      if (orig) {
        const ot = orig.tables.find(q => q.id === p.table);
        const oc = ot && ot.columns.find(q => q.symbol === p.symbol);
        const ox = ot && xc ? ot.columns.find(q => q.symbol === p.x) : null;
        if (oc) {
          series[0].label = `${T("edited")}: ${series[0].label || p.symbol}`;
          series.push({x: ox ? ox.values : abscissa(orig).x, y: oc.values,
                       label: `${T("original")}: ${p.symbol}`, color: "#8a8a8a", dash: true});
        }
      }
      const over = h("select", {class: "over", "aria-label": T("plot_over")});
      over.appendChild(h("option", {value: ""}, `${T("plot_over")}: ${ax.label}`));
      for (const q of t.columns.slice(nc))
        if (q.symbol !== p.symbol)
          over.appendChild(h("option", {value: q.symbol}, `${T("plot_over")}: ${q.symbol}`));
      over.value = p.x || "";
      over.addEventListener("change", () => { p.x = over.value || undefined; renderPlots(); saveUrl(); });
      div.appendChild(over);
      const lp = AssurPlot.line({series, xlabel, ylabel, period, format: plotFormat,
                                 onpick: (i) => setPos(i)});
      div.appendChild(lp.el);
      state.plotObjs.push({marker: () => lp.marker(state.pos), destroy: lp.destroy});
    }
    box.appendChild(div);
  });
  markPlots();
}

function markPlots() {
  for (const o of state.plotObjs) o.marker();
}

// ---- animation ------------------------------------------------------------------
function togglePlay() {
  if (state.timer) { clearInterval(state.timer); state.timer = null; return; }
  let dir = 1;
  state.timer = setInterval(() => {
    if (!state.data) return;
    const n = state.data.geometry.n;
    if (state.data.turn) {
      state.pos = (state.pos + 1) % n;        // a crank turns on through 360°
    } else {
      if (state.pos + dir > n - 1 || state.pos + dir < 0) dir = -dir;
      state.pos += dir;
    }
    syncSliders();
    renderPose();
  }, 60);
}

// ---- start ----------------------------------------------------------------------
async function start() {
  let r;
  try {
    r = await fetch("/api/model");
    state.info = await r.json();
  } catch (e) {
    $("status").textContent = document.body.dataset.serverDown;   // from the page's texts
    return;
  }
  const saved = readUrl();
  state.lang = saved.lang || (document.body.dataset.lang || state.info.lang);
  state.units = saved.units || state.info.units;
  for (const p of state.info.parameters) {
    if (p.editable && p.name in saved.params) {
      const c = checkValue(p, String(saved.params[p.name]));
      if (c.value !== undefined) state.values[p.name] = c.value;
    }
  }
  if (saved.pos !== undefined) state.pos = saved.pos;
  if (saved.plots) state.plots = saved.plots;
  if (saved.traj) for (const p of saved.traj) state.traj.add(p);
  $("units").value = state.units;
  applyTexts();
  buildParams();
  // restored from the address: undo leads back to the file's values
  if (Object.keys(changed()).length) state.history.push(Object.assign({}, state.base));
  $("undo").disabled = !state.history.length;
  $("stroke").addEventListener("input", () => setPos(Number($("stroke").value)));
  $("play").addEventListener("click", togglePlay);
  $("reset").addEventListener("click", resetParams);
  $("undo").addEventListener("click", undo);
  document.addEventListener("keydown", (e) => {
    if ((e.ctrlKey || e.metaKey) && e.key === "z" && !(e.target instanceof HTMLInputElement)) {
      e.preventDefault();
      undo();
    }
  });
  $("overlay").addEventListener("change", () => { state.overlay = $("overlay").checked; renderPose(); });
  $("compare").addEventListener("change", () => {
    state.compare = $("compare").checked;
    if (state.compare) loadOriginal(); else { renderPose(); renderPlots(); }
  });
  $("units").addEventListener("change", () => {
    state.units = $("units").value;
    saveUrl();
    request();
  });
  $("lang-toggle").addEventListener("click", () => {
    state.lang = state.lang === "en" ? "ru" : "en";
    applyTexts();
    buildParams();
    saveUrl();
    request();
  });
  $("table-select").addEventListener("change", () => {
    state.table = $("table-select").value;
    renderTable(true);
    renderCurrent();
  });
  $("add-plot").addEventListener("change", () => {
    const v = $("add-plot").value;
    if (!v) return;
    const [table, symbol] = v.split("\u0000");
    state.plots.push({table, symbol});
    $("add-plot").value = "";
    renderPlots();
    saveUrl();
  });
  for (const b of document.querySelectorAll("[data-export]"))
    b.addEventListener("click", () => download(b.dataset.export, b));
  window.addEventListener("pagehide", flushUrl);   // a reload keeps the last change
  $("table").addEventListener("click", tableClick);
  watchTable();
  request();
}

start();
