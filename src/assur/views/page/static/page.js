// assur page: plain JavaScript, no build step. Talks to the JSON API of
// assur.app.server; draws the mechanism and the plots in SVG itself.
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
  if (a !== 0 && (a >= 1e6 || a < 1e-3)) return v.toExponential(4);
  if (a >= 1000) return v.toFixed(0);
  return Number(v.toPrecision(5)).toString();
}

// ---- texts ----------------------------------------------------------------------
function applyTexts() {
  document.documentElement.lang = state.lang;
  for (const e of document.querySelectorAll("[data-t]")) e.textContent = T(e.dataset.t);
  $("lang-toggle").textContent = T("language");
  if (state.info) $("title").textContent = state.info.title[state.lang] || state.info.name;
}

// ---- parameters -----------------------------------------------------------------
function sliderRange(v, unit) {
  if (unit === "deg") return [v - 45, v + 45, 0.1];
  if (v === 0) return [-1, 1, 0.005];
  const lo = Math.min(0.5 * v, 1.5 * v), hi = Math.max(0.5 * v, 1.5 * v);
  return [lo, hi, Math.abs(v) / 500];
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
      fs.appendChild(h("legend", {}, group || ""));
      box.appendChild(fs);
    }
    state.base[p.name] = p.value;
    state.values[p.name] = p.value;
    const row = h("div", {class: "param", id: "param-" + p.name, title: p.comment || ""});
    row.appendChild(h("label", {for: "input-" + p.name}, p.name));
    const [lo, hi, step] = sliderRange(p.value, p.unit);
    const slider = h("input", {type: "range", id: "slider-" + p.name, min: lo, max: hi,
                               step: step, value: p.value});
    const input = h("input", {type: "number", id: "input-" + p.name, step: "any",
                              value: p.value});
    row.appendChild(slider);
    row.appendChild(input);
    row.appendChild(h("span", {class: "unit"}, p.unit === "-" ? "" : p.unit));
    slider.addEventListener("input", () => {
      input.value = slider.value;
      setParam(p.name, Number(slider.value));
    });
    input.addEventListener("input", () => {
      const v = Number(input.value);
      if (input.value.trim() === "" || !Number.isFinite(v)) return;
      slider.value = v;
      setParam(p.name, v);
    });
    fs.appendChild(row);
  }
}

function setParam(name, v) {
  state.values[name] = v;
  $("param-" + name).classList.toggle("changed", v !== state.base[name]);
  request();
}

function changed() {
  const out = {};
  for (const [k, v] of Object.entries(state.values)) if (v !== state.base[k]) out[k] = v;
  return out;
}

function resetParams() {
  for (const [k, v] of Object.entries(state.base)) {
    state.values[k] = v;
    $("input-" + k).value = v;
    $("slider-" + k).value = v;
    $("param-" + k).classList.remove("changed");
  }
  request();
}

// ---- requests -------------------------------------------------------------------
function body(extra) {
  return JSON.stringify(Object.assign({params: changed(), lang: state.lang, units: state.units},
                                      extra || {}));
}

function request() {
  state.t0 = performance.now();
  if (state.inflight) { state.pending = true; return; }
  send();
}

async function send() {
  state.inflight = true;
  state.pending = false;
  const t0 = state.t0;
  const seq = ++state.seq;
  $("status").textContent = T("computing");
  let out;
  try {
    const multi = state.info.coordinates.length > 1;
    const r = await fetch("/api/analyze", {method: "POST",
      headers: {"Content-Type": "application/json"},
      body: body(multi ? {} : {positions: POSITIONS})});
    out = await r.json();
  } catch (e) {
    out = {ok: false, error: {kind: "network", message: String(e)}};
  }
  if (seq === state.seq) {
    if (out.ok) showResult(out); else showError(out.error);
    const ms = performance.now() - t0;
    $("status").textContent = `${T("redrawn")} ${ms.toFixed(0)} ${T("ms")}`;
    $("status").dataset.ms = ms.toFixed(1);
    console.log(`assur: redrawn in ${ms.toFixed(1)} ms (server ${out.ms} ms, ` +
                `${out.ok ? "drawing" : "error: " + out.error.kind})`);
  }
  state.inflight = false;
  if (state.pending) send();
}

async function download(kind) {
  const extra = {};
  if (kind === "csv" && state.table) extra.table = state.table;
  if (kind === "dxf" && state.data) {
    const q = state.data.geometry.q;
    const c = state.data.coordinates[0];
    if (state.data.coordinates.length === 1) {
      let v = q[c.name][state.pos];
      if (c.kind === "angle") v = v * 180 / Math.PI;
      extra.at = [v];
      extra.positions = POSITIONS;
    }
  }
  const r = await fetch("/api/export/" + kind, {method: "POST",
    headers: {"Content-Type": "application/json"}, body: body(extra)});
  const type = r.headers.get("content-type") || "";
  if (type.startsWith("application/json")) {
    const out = await r.json();
    showError(out.error || {kind: "error", message: JSON.stringify(out)});
    return;
  }
  const blob = await r.blob();
  const m = /filename="([^"]+)"/.exec(r.headers.get("content-disposition") || "");
  const a = h("a", {href: URL.createObjectURL(blob), download: m ? m[1] : "assur." + kind});
  document.body.appendChild(a);
  a.click();
  a.remove();
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
  state.data = out;
  $("drawing-box").classList.remove("failed");
  $("error-panel").hidden = true;
  $("error-message").textContent = "";
  $("plots").classList.remove("pending");
  $("table-box").classList.remove("pending");
  $("title").textContent = out.title;
  const n = out.geometry.n;
  const s = $("stroke");
  s.max = n - 1;
  if (state.pos > n - 1) state.pos = n - 1;
  s.value = state.pos;
  prepareDrawing(out.geometry);
  if (state.plots === null) state.plots = defaultPlots(out.tables);
  if (!state.table || !out.tables.some(t => t.id === state.table))
    state.table = out.tables.length ? out.tables[0].id : null;
  buildTableSelect(out.tables);
  buildPlotSelect(out.tables);
  renderSolved(out.solved);
  renderWarnings(out.warnings);
  renderTable();
  renderPlots();
  renderPose();
}

function renderSolved(solved) {
  const ul = $("solved");
  ul.textContent = "";
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
  const m = 0.12 * span;
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
  // y up: the SVG's y is −y of the model
  svg.setAttribute("viewBox", `${x0 - m} ${-(y1 + m)} ${x1 - x0 + 2 * m} ${y1 - y0 + 2.6 * m}`);
  svg.setAttribute("preserveAspectRatio", "xMidYMid meet");
}

function renderPose() {
  if (!geo) return;
  const {g, span, cyl, centre} = geo;
  const i = state.pos;
  const svg = $("drawing");
  svg.textContent = "";
  const fs = 0.028 * span, hh = 0.035 * span;
  const xy = {};
  for (const [p, v] of Object.entries(g.points)) xy[p] = [v[i][0], -v[i][1]];
  let k = 0;
  for (const b of g.bodies) {
    if (b.name === "0") continue;
    const pts = b.points.filter(p => p in xy).map(p => xy[p]);
    const col = COLORS[k++ % COLORS.length];
    const grp = el("g", {id: "link-" + b.name, "data-link": b.name});
    let mid;
    if (b.name in cyl && pts.length >= 2) {
      const [a, c] = pts;
      const L = Math.hypot(c[0] - a[0], c[1] - a[1]) || 1e-12;
      const u = [(c[0] - a[0]) / L, (c[1] - a[1]) / L];
      const [barrel, rod] = cyl[b.name];
      const e1 = [a[0] + u[0] * Math.min(barrel, L), a[1] + u[1] * Math.min(barrel, L)];
      const e2 = [c[0] - u[0] * Math.min(rod, L), c[1] - u[1] * Math.min(rod, L)];
      grp.appendChild(el("line", {x1: a[0], y1: a[1], x2: e1[0], y2: e1[1], stroke: "#4a7ab8",
        "stroke-width": 9, "vector-effect": "non-scaling-stroke"}));
      grp.appendChild(el("line", {x1: e2[0], y1: e2[1], x2: c[0], y2: c[1], stroke: "#222",
        "stroke-width": 3, "vector-effect": "non-scaling-stroke"}));
      mid = [a[0] + u[0] * 0.5 * Math.min(barrel, L), a[1] + u[1] * 0.5 * Math.min(barrel, L)];
    } else {
      const hl = hull(pts);
      if (hl.length >= 3) {
        grp.appendChild(el("polygon", {points: hl.map(p => p.join(",")).join(" "),
          fill: col, "fill-opacity": 0.12, stroke: col, "stroke-width": 2.5,
          "vector-effect": "non-scaling-stroke", "stroke-linejoin": "round"}));
      } else if (hl.length === 2) {
        grp.appendChild(el("line", {x1: hl[0][0], y1: hl[0][1], x2: hl[1][0], y2: hl[1][1],
          stroke: col, "stroke-width": 3, "stroke-linecap": "round",
          "vector-effect": "non-scaling-stroke"}));
      }
      mid = hl.length ? [hl.reduce((s, p) => s + p[0], 0) / hl.length,
                         hl.reduce((s, p) => s + p[1], 0) / hl.length] : pts[0];
    }
    if (mid) grp.appendChild(el("text", {x: mid[0] + 0.3 * fs, y: mid[1] - 0.3 * fs,
      "font-size": fs * 1.1, fill: b.name in cyl ? "#4a7ab8" : col, "font-style": "italic",
      "font-weight": "bold", class: "link-label"}, b.name));
    svg.appendChild(grp);
  }
  for (const p of g.frame) {
    const [x, y] = xy[p];
    svg.appendChild(el("polygon", {points: `${x},${y} ${x - 0.55 * hh},${y + hh} ` +
      `${x + 0.55 * hh},${y + hh}`, fill: "#fff", stroke: "#000", "stroke-width": 1.2,
      "vector-effect": "non-scaling-stroke"}));
    svg.appendChild(el("line", {x1: x - 0.8 * hh, y1: y + hh, x2: x + 0.8 * hh, y2: y + hh,
      stroke: "#000", "stroke-width": 1.2, "vector-effect": "non-scaling-stroke"}));
  }
  const joints = new Set(g.joints);
  for (const [p, [x, y]] of Object.entries(xy)) {
    const j = joints.has(p);
    svg.appendChild(el("circle", {id: "pt-" + p, cx: x, cy: y, r: (j ? 0.011 : 0.007) * span,
      fill: j ? "#fff" : "#000", stroke: "#000", "stroke-width": 1.3,
      "vector-effect": "non-scaling-stroke", "data-x": g.points[p][i][0],
      "data-y": g.points[p][i][1]}));
    const d = [x - centre[0], y + centre[1]];
    const n = Math.hypot(d[0], d[1]) || 1;
    svg.appendChild(el("text", {x: x + d[0] / n * 1.4 * fs, y: y + d[1] / n * 1.4 * fs,
      "font-size": fs, "text-anchor": "middle", "dominant-baseline": "middle",
      class: "point-label"}, p));
  }
  for (const w of g.weights) {
    if (!(w.point in xy)) continue;
    const [x, y] = xy[w.point];
    const L = 0.12 * span;
    svg.appendChild(el("line", {x1: x, y1: y, x2: x, y2: y + L, stroke: "#d62728",
      "stroke-width": 1.5, "vector-effect": "non-scaling-stroke"}));
    svg.appendChild(el("polygon", {points: `${x},${y + L} ${x - 0.15 * L},${y + 0.75 * L} ` +
      `${x + 0.15 * L},${y + 0.75 * L}`, fill: "#d62728"}));
    svg.appendChild(el("text", {x: x + 0.2 * L, y: y + L, "font-size": fs, fill: "#d62728"},
      w.name));
  }
  $("position-text").textContent = positionText(i);
  renderCurrent();
  markPlots();
  markTable();
}

function positionText(i) {
  if (!state.data) return "";
  const parts = [];
  for (const c of state.data.coordinates) {
    const v = state.data.geometry.q[c.name][i];   // [m or rad], shown in the page's units
    const u = state.data.units;
    const shown = c.kind === "angle" ? v / u.angle_scale : v / u.length_scale;
    const unit = c.kind === "angle" ? u.angle : u.length;
    parts.push(unit === "°" || unit === "deg" ? `${c.name} = ${fmt(shown)}°`
                                             : `${c.name} = ${fmt(shown)} ${unit}`);
  }
  return parts.join(", ") + ` (${T("position")} ${i + 1}/${state.data.geometry.n})`;
}

// ---- tables ---------------------------------------------------------------------
function currentTable() {
  return state.data ? state.data.tables.find(t => t.id === state.table) : null;
}

function buildTableSelect(tables) {
  const s = $("table-select");
  s.textContent = "";
  for (const t of tables) s.appendChild(h("option", {value: t.id}, `${t.label} — ${t.title}`));
  s.value = state.table;
}

function renderCurrent() {
  const t = currentTable();
  const box = $("current-values");
  box.textContent = "";
  if (!t) return;
  for (const c of t.columns) {
    const tr = h("tr", {"data-symbol": c.symbol});
    tr.appendChild(h("td", {title: c.label}, c.symbol));
    tr.appendChild(h("td", {class: "v", id: "value-" + c.symbol}, fmt(c.values[state.pos])));
    tr.appendChild(h("td", {}, c.unit === "-" ? "" : c.unit));
    box.appendChild(tr);
  }
}

function renderTable() {
  const t = currentTable();
  const tab = $("table");
  tab.textContent = "";
  $("table-notes").textContent = "";
  if (!t) return;
  $("table-notes").appendChild(h("h3", {}, `${T("table")} ${t.label}. ${t.title}`));
  for (const n of t.notes) if (n) $("table-notes").appendChild(h("p", {}, n));
  const head = h("tr");
  for (const c of t.columns)
    head.appendChild(h("th", {title: c.label}, `${c.symbol} [${c.unit}]`));
  tab.appendChild(head);
  const n = t.columns.length ? t.columns[0].values.length : 0;
  for (let i = 0; i < n; i++) {
    const tr = h("tr", {"data-row": i});
    for (const c of t.columns) tr.appendChild(h("td", {}, fmt(c.values[i])));
    tab.appendChild(tr);
  }
  markTable();
}

function markTable() {
  for (const tr of document.querySelectorAll("#table tr.current")) tr.classList.remove("current");
  const tr = document.querySelector(`#table tr[data-row="${state.pos}"]`);
  if (tr) tr.classList.add("current");
}

// ---- plots ----------------------------------------------------------------------
function findColumn(tables, table, symbol) {
  const t = tables.find(x => x.id === table);
  return t ? t.columns.find(c => c.symbol === symbol) : null;
}

function defaultPlots(tables) {
  // transmission numbers, force, pressure, capacity, a reaction, the steered axle's share
  const out = [];
  const pick = (id, test, max) => {
    const t = tables.find(x => x.id === id);
    if (!t) return;
    let k = 0;
    for (const c of t.columns.slice(state.data.coordinates.length))
      if (test(c.symbol) && k < max) { out.push({table: id, symbol: c.symbol}); k++; }
  };
  pick("3.1", s => /^I/.test(s), 2);
  pick("4.1", s => /^(F|p|P|G)/.test(s), 4);
  pick("5.1", s => /^R.*[^xy]$/.test(s), 1);
  pick("6.1", s => /^dR/.test(s), 1);
  return out;
}

function buildPlotSelect(tables) {
  const s = $("add-plot");
  s.textContent = "";
  s.appendChild(h("option", {value: ""}, "+ " + T("add_plot")));
  const nc = state.data.coordinates.length;
  for (const t of tables) {
    const og = h("optgroup", {label: `${t.label} — ${t.title}`});
    for (const c of t.columns.slice(nc))
      og.appendChild(h("option", {value: `${t.id}\u0000${c.symbol}`}, `${c.symbol} [${c.unit}]`));
    s.appendChild(og);
  }
}

function renderPlots() {
  const box = $("plots");
  box.textContent = "";
  const d = state.data;
  const nc = d.coordinates.length;
  state.plots.forEach((p, k) => {
    const c = findColumn(d.tables, p.table, p.symbol);
    if (!c) return;
    const t = d.tables.find(x => x.id === p.table);
    const xs = nc === 1 ? t.columns[0].values : c.values.map((_, i) => i);
    const div = h("div", {class: "plot", id: `plot-${p.table}-${p.symbol}`});
    div.appendChild(h("div", {class: "title"}, `${p.symbol} [${c.unit}] — ${p.table}`));
    const rm = h("button", {type: "button"}, "×");
    rm.title = T("remove");
    rm.addEventListener("click", () => { state.plots.splice(k, 1); renderPlots(); });
    div.appendChild(rm);
    div.appendChild(plotSvg(xs, c.values, COLORS[k % COLORS.length]));
    box.appendChild(div);
  });
  markPlots();
}

function plotSvg(xs, ys, color) {
  const W = 300, H = 150, L = 46, R = 8, Tp = 8, B = 20;
  const svg = el("svg", {viewBox: `0 0 ${W} ${H}`, preserveAspectRatio: "none"});
  const fin = ys.map((y, i) => [xs[i], y]).filter(p => p[1] !== null && Number.isFinite(p[1]));
  if (!fin.length) return svg;
  let x0 = Math.min(...xs), x1 = Math.max(...xs);
  let y0 = Math.min(...fin.map(p => p[1])), y1 = Math.max(...fin.map(p => p[1]));
  if (x1 === x0) x1 = x0 + 1;
  if (y1 === y0) { y0 -= Math.abs(y0) * 0.05 + 1e-9; y1 += Math.abs(y1) * 0.05 + 1e-9; }
  const X = x => L + (x - x0) / (x1 - x0) * (W - L - R);
  const Y = y => Tp + (y1 - y) / (y1 - y0) * (H - Tp - B);
  svg.appendChild(el("rect", {x: L, y: Tp, width: W - L - R, height: H - Tp - B,
    fill: "none", stroke: "#ccc"}));
  for (const [v, y] of [[y1, Tp + 4], [y0, H - B]])
    svg.appendChild(el("text", {x: L - 3, y: y, "font-size": 9, "text-anchor": "end"}, fmt(v)));
  svg.appendChild(el("text", {x: L, y: H - 6, "font-size": 9}, fmt(x0)));
  svg.appendChild(el("text", {x: W - R, y: H - 6, "font-size": 9, "text-anchor": "end"},
    fmt(x1)));
  let dpath = "", pen = false;
  ys.forEach((y, i) => {
    if (y === null || !Number.isFinite(y)) { pen = false; return; }
    dpath += `${pen ? "L" : "M"}${X(xs[i]).toFixed(2)},${Y(y).toFixed(2)} `;
    pen = true;
  });
  svg.appendChild(el("path", {d: dpath, fill: "none", stroke: color, "stroke-width": 1.8}));
  svg.appendChild(el("line", {class: "marker", x1: 0, x2: 0, y1: Tp, y2: H - B,
    stroke: "#b3541e", "stroke-dasharray": "3,2"}));
  svg.appendChild(el("circle", {class: "marker-dot", r: 3, fill: "#b3541e", cx: -10, cy: -10}));
  svg.dataset.x0 = x0; svg.dataset.x1 = x1; svg.dataset.y0 = y0; svg.dataset.y1 = y1;
  svg._xs = xs; svg._ys = ys; svg._X = X; svg._Y = Y;
  return svg;
}

function markPlots() {
  for (const svg of document.querySelectorAll("#plots svg")) {
    if (!svg._xs) continue;
    const x = svg._X(svg._xs[state.pos]);
    const line = svg.querySelector(".marker");
    line.setAttribute("x1", x); line.setAttribute("x2", x);
    const y = svg._ys[state.pos];
    const dot = svg.querySelector(".marker-dot");
    if (y !== null && Number.isFinite(y)) { dot.setAttribute("cx", x); dot.setAttribute("cy", svg._Y(y)); }
  }
}

// ---- animation ------------------------------------------------------------------
function togglePlay() {
  if (state.timer) { clearInterval(state.timer); state.timer = null; return; }
  let dir = 1;
  state.timer = setInterval(() => {
    if (!state.data) return;
    const n = state.data.geometry.n;
    if (state.pos + dir > n - 1 || state.pos + dir < 0) dir = -dir;
    state.pos += dir;
    $("stroke").value = state.pos;
    renderPose();
  }, 60);
}

// ---- start ----------------------------------------------------------------------
async function start() {
  const r = await fetch("/api/model");
  state.info = await r.json();
  if (!document.body.dataset.lang) state.lang = state.info.lang;
  state.units = state.info.units;
  $("units").value = state.units;
  applyTexts();
  buildParams();
  $("stroke").addEventListener("input", () => {
    state.pos = Number($("stroke").value);
    renderPose();
  });
  $("play").addEventListener("click", togglePlay);
  $("reset").addEventListener("click", resetParams);
  $("units").addEventListener("change", () => {
    state.units = $("units").value;
    request();
  });
  $("lang-toggle").addEventListener("click", () => {
    state.lang = state.lang === "en" ? "ru" : "en";
    applyTexts();
    request();
  });
  $("table-select").addEventListener("change", () => {
    state.table = $("table-select").value;
    renderTable();
    renderCurrent();
  });
  $("add-plot").addEventListener("change", () => {
    const v = $("add-plot").value;
    if (!v) return;
    const [table, symbol] = v.split("\u0000");
    state.plots.push({table, symbol});
    $("add-plot").value = "";
    renderPlots();
  });
  for (const b of document.querySelectorAll("[data-export]"))
    b.addEventListener("click", () => download(b.dataset.export));
  request();
}

start();
