// assur plots (issue 24): line plots and heat maps in SVG for the interactive page.
// A plain script, no build step: it defines window.AssurPlot = {line(opts), map(opts)}.
// Every user-given text is set with textContent; all SVG is built with createElementNS.
"use strict";

(function () {
  const NS = "http://www.w3.org/2000/svg";
  const PALETTE = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
                   "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"];
  // matplotlib's viridis sampled at 0, 0.1, …, 1 (interpolated linearly in between)
  const VIRIDIS = ["#440154", "#482475", "#414487", "#355f8d", "#2a788e", "#21918c",
                   "#22a884", "#44bf70", "#7ad151", "#bddf26", "#fde725"];
  const MISSING = "#d4d4d4";     // a map's cell where nothing was assembled
  const FONT = 10;               // tick labels, legend, tooltip (viewBox px)
  const CHAR = 0.6 * FONT;       // a rough width of one character, for the margins
  const LEGEND_ROW = 14;

  // ---- small helpers ---------------------------------------------------------------
  function svgEl(tag, attrs, text) {
    const e = document.createElementNS(NS, tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  function finite(v) { return typeof v === "number" && Number.isFinite(v); }

  // Up to 4 significant digits; never "-0".
  function defaultFormat(v) {
    const r = Number(v.toPrecision(4));
    return String(r === 0 ? 0 : r);
  }

  // The caller's format made safe: a missing value prints as a dash, never "NaN".
  function safeFormat(format) {
    const f = typeof format === "function" ? format : defaultFormat;
    return (v) => (finite(v) ? String(f(v)) : "—");
  }

  function text(v) { return v === undefined || v === null ? "" : String(v); }

  // [min, max] of the finite values, [0, 1] when there is none.
  function extent(values) {
    let lo = Infinity, hi = -Infinity;
    for (const v of values) if (finite(v)) { if (v < lo) lo = v; if (v > hi) hi = v; }
    return lo <= hi ? [lo, hi] : [0, 1];
  }

  function linear(d0, d1, p0, p1) {
    return (v) => p0 + (v - d0) / (d1 - d0) * (p1 - p0);
  }

  // "Nice" ticks: steps 1, 2, 2.5 or 5 × 10^k, the smallest step giving at most 8 ticks
  // (hence at least 4). extend: the axis grows to the outer ticks, so they cover the data
  // and sit on the box's edges; otherwise the axis is [lo, hi] and the ticks lie inside.
  // A constant range is padded first. Returns {lo, hi, ticks}.
  function niceTicks(lo, hi, extend) {
    if (!(hi > lo)) { const pad = Math.abs(lo) * 0.05 || 1; lo -= pad; hi += pad; }
    const eps = 1e-9;
    for (let e = Math.floor(Math.log10((hi - lo) / 8)) - 1; ; e++) {
      for (const m of [1, 2, 2.5, 5]) {
        const step = m * Math.pow(10, e);
        const a = extend ? Math.floor(lo / step + eps) : Math.ceil(lo / step - eps);
        const b = extend ? Math.ceil(hi / step - eps) : Math.floor(hi / step + eps);
        if (b - a + 1 > 8) continue;
        // toPrecision cleans 0.30000000000000004; "+ 0" turns -0 into 0
        const at = (k) => Number((k * step).toPrecision(12)) + 0;
        const ticks = [];
        for (let k = a; k <= b; k++) ticks.push(at(k));
        return extend ? {lo: at(a), hi: at(b), ticks} : {lo, hi, ticks};
      }
    }
  }

  // A client (mouse) position in the SVG's viewBox coordinates.
  function toSvg(svg, ev) {
    const m = svg.getScreenCTM();
    return m ? new DOMPoint(ev.clientX, ev.clientY).matrixTransform(m.inverse()) : null;
  }

  // within the plot box, or less than 3 px outside (a point on the edge stays pickable)
  function inBox(p, box) {
    const m = 3;
    return p && p.x >= box.l - m && p.x <= box.r + m && p.y >= box.t - m && p.y <= box.b + m;
  }

  function show(e, on) { e.setAttribute("visibility", on ? "visible" : "hidden"); }

  // The root: a div (the tooltip's positioning context) holding an SVG that scales to the
  // container's width and keeps its aspect ratio.
  function makeRoot(W, H) {
    const el = document.createElement("div");
    el.className = "assur-plot";
    el.style.cssText = "position:relative;max-width:100%;";
    const svg = svgEl("svg", {viewBox: `0 0 ${W} ${H}`, width: "100%",
      preserveAspectRatio: "xMidYMid meet", "font-family": "sans-serif",
      style: "display:block;width:100%;max-width:100%;height:auto;overflow:hidden"});
    el.appendChild(svg);
    return {el, svg};
  }

  // The plot box {l, t, r, b} in viewBox px: room on the left for the y tick labels and
  // the rotated y title, below for the x tick labels and the x title, above for the title,
  // on the right for half the last x tick label (centred on the edge) plus `right`.
  function plotBox(opts, W, H, xlabels, ylabels, right) {
    const ylen = Math.max(0, ...ylabels.map((s) => s.length));
    const xlast = xlabels.length ? xlabels[xlabels.length - 1].length : 0;
    const l = (opts.ylabel ? 18 : 4) + ylen * CHAR + 6;
    const t = opts.title ? 22 : 8;
    const r = W - Math.max(8, xlast * CHAR / 2 + 2) - right;
    const b = H - (opts.xlabel ? 32 : 16);
    return {l, t, r, b};
  }

  // Grid (optional), frame, tick labels and the titles of the axes and the plot.
  function drawAxes(svg, box, X, Y, xt, yt, opts, fmt, grid) {
    const g = svgEl("g", {class: "axes", "font-size": FONT, fill: "#333"});
    for (const v of xt.ticks) {
      const x = X(v);
      if (grid) g.appendChild(svgEl("line", {class: "grid", x1: x, x2: x, y1: box.t, y2: box.b,
        stroke: "#e8e8e8"}));
      g.appendChild(svgEl("line", {x1: x, x2: x, y1: box.b, y2: box.b + 3, stroke: "#888"}));
      g.appendChild(svgEl("text", {class: "xtick", x, y: box.b + 13, "text-anchor": "middle"},
        fmt(v)));
    }
    for (const v of yt.ticks) {
      const y = Y(v);
      if (grid) g.appendChild(svgEl("line", {class: "grid", x1: box.l, x2: box.r, y1: y, y2: y,
        stroke: "#e8e8e8"}));
      g.appendChild(svgEl("line", {x1: box.l - 3, x2: box.l, y1: y, y2: y, stroke: "#888"}));
      g.appendChild(svgEl("text", {class: "ytick", x: box.l - 5, y: y + 3.5,
        "text-anchor": "end"}, fmt(v)));
    }
    g.appendChild(svgEl("rect", {class: "frame", x: box.l, y: box.t, width: box.r - box.l,
      height: box.b - box.t, fill: "none", stroke: "#888"}));
    const midX = (box.l + box.r) / 2, midY = (box.t + box.b) / 2;
    if (opts.xlabel) g.appendChild(svgEl("text", {class: "xlabel", x: midX, y: box.b + 28,
      "text-anchor": "middle"}, text(opts.xlabel)));
    if (opts.ylabel) g.appendChild(svgEl("text", {class: "ylabel", x: 0, y: 0,
      transform: `translate(11 ${midY}) rotate(-90)`, "text-anchor": "middle"},
      text(opts.ylabel)));
    if (opts.title) g.appendChild(svgEl("text", {class: "title", x: midX, y: 14,
      "text-anchor": "middle", "font-weight": "bold", "font-size": FONT + 1}, text(opts.title)));
    svg.appendChild(g);
  }

  // A tooltip group drawn last; show(px, py, lines) puts it beside (px, py) inside the
  // viewBox W × H, lines = [{text, color}].
  function makeTooltip(svg, W, H) {
    const g = svgEl("g", {class: "tooltip", visibility: "hidden", "pointer-events": "none",
      "font-size": FONT});
    const bg = svgEl("rect", {x: 0, y: 0, rx: 3, fill: "#fff", "fill-opacity": 0.93,
      stroke: "#999"});
    const body = svgEl("text", {x: 6, y: 13});
    g.appendChild(bg); g.appendChild(body);
    svg.appendChild(g);
    return {
      el: g,
      show(px, py, lines) {
        body.textContent = "";
        lines.forEach((ln, k) => body.appendChild(svgEl("tspan", {x: 6, dy: k ? 12 : 0,
          fill: ln.color || "#222"}, ln.text)));
        let w = 0;
        try { w = body.getBBox().width; } catch (e) { w = 0; }
        if (!w) w = Math.max(...lines.map((ln) => ln.text.length)) * CHAR;
        w += 12;
        const h = lines.length * 12 + 6;
        bg.setAttribute("width", w); bg.setAttribute("height", h);
        let tx = px + 10;
        if (tx + w > W) tx = Math.max(0, px - 10 - w);      // flip to the left of the point
        const ty = Math.min(Math.max(0, py - h / 2), Math.max(0, H - h));
        g.setAttribute("transform", `translate(${tx} ${ty})`);
        show(g, true);
      },
      hide() { show(g, false); },
    };
  }

  // ---- line plots --------------------------------------------------------------------

  // The curve's path: a new subpath (M) after a missing point and, with a period, between
  // points whose values differ by more than half of it (a wrapped angle, no line across).
  function curvePath(s, X, Y, period) {
    let d = "", prev = null;
    const n = Math.min(s.x.length, s.y.length);
    for (let i = 0; i < n; i++) {
      const x = s.x[i], y = s.y[i];
      if (!finite(x) || !finite(y)) { prev = null; continue; }
      const wrap = prev !== null && period > 0 && Math.abs(y - prev) > period / 2;
      d += `${prev === null || wrap ? "M" : "L"}${X(x).toFixed(2)},${Y(y).toFixed(2)} `;
      prev = y;
    }
    return d.trim();
  }

  function nearestIndex(xs, x) {
    let best = -1, dist = Infinity;
    for (let i = 0; i < xs.length; i++) {
      if (finite(xs[i]) && Math.abs(xs[i] - x) < dist) { dist = Math.abs(xs[i] - x); best = i; }
    }
    return best;
  }

  // Legend items left to right, wrapping at the width W: [{k, x, row}] and the row count.
  // A single series without a label has no legend.
  function legendLayout(series, W) {
    if (!series.length || (series.length === 1 && !series[0].label)) return {items: [], rows: 0};
    const items = [];
    let x = 8, row = 0;
    const room = Math.max(4, Math.floor((W - 8 - 24 - 12) / CHAR));   // characters in a row
    series.forEach((s, k) => {
      // a label longer than a row is cut with "…" (the whole label is its tooltip)
      const text = s.label.length > room ? s.label.slice(0, room - 1) + "…" : s.label;
      const w = 24 + text.length * CHAR + 12;
      if (x > 8 && x + w > W - 4) { row += 1; x = 8; }
      items.push({k, x, row, text});
      x += w;
    });
    return {items, rows: row + 1};
  }

  function drawLegend(svg, series, layout, top) {
    const g = svgEl("g", {class: "legend", "font-size": FONT, fill: "#333"});
    for (const it of layout.items) {
      const s = series[it.k], y = top + it.row * LEGEND_ROW + LEGEND_ROW / 2;
      g.appendChild(svgEl("line", {class: "swatch", x1: it.x, x2: it.x + 18, y1: y, y2: y,
        stroke: s.color, "stroke-width": 2.5, "stroke-dasharray": s.dash ? "4,2" : "none"}));
      const label = svgEl("text", {x: it.x + 22, y: y + 3.5}, it.text);
      if (it.text !== s.label) label.appendChild(svgEl("title", {}, s.label));
      g.appendChild(label);
    }
    svg.appendChild(g);
  }

  function line(opts) {
    opts = opts || {};
    const fmt = safeFormat(opts.format);
    const W = opts.width || 360, Hp = opts.height || 220;
    const series = (opts.series || []).map((s, k) => ({
      x: s.x || [], y: s.y || [], label: text(s.label),
      color: s.color || PALETTE[k % PALETTE.length], dash: !!s.dash}));
    const xsAll = [], ysAll = [];        // the drawn points' coordinates
    for (const s of series) {
      s.x.forEach((x, i) => {
        if (finite(x) && finite(s.y[i])) { xsAll.push(x); ysAll.push(s.y[i]); }
      });
    }
    const xt = niceTicks(...extent(xsAll), true), yt = niceTicks(...extent(ysAll), true);
    const legend = legendLayout(series, W);
    const H = Hp + (legend.rows ? legend.rows * LEGEND_ROW + 4 : 0);
    const {el, svg} = makeRoot(W, H);
    const box = plotBox(opts, W, Hp, xt.ticks.map(fmt), yt.ticks.map(fmt), 0);
    const X = linear(xt.lo, xt.hi, box.l, box.r), Y = linear(yt.lo, yt.hi, box.b, box.t);
    const fromX = linear(box.l, box.r, xt.lo, xt.hi);
    drawAxes(svg, box, X, Y, xt, yt, opts, fmt, true);

    const curves = svgEl("g", {class: "curves", fill: "none"});
    series.forEach((s, k) => curves.appendChild(svgEl("path", {class: "curve",
      "data-series": k, d: curvePath(s, X, Y, opts.period), stroke: s.color, "stroke-width": 1.8,
      "stroke-linejoin": "round", "stroke-dasharray": s.dash ? "5,3" : "none"})));
    svg.appendChild(curves);
    if (legend.rows) drawLegend(svg, series, legend, Hp + 2);

    // the current position (marker) and the hovered one (crosshair), hidden until used
    const over = svgEl("g", {"pointer-events": "none"});
    const cross = svgEl("line", {class: "crosshair", y1: box.t, y2: box.b, stroke: "#999",
      visibility: "hidden"});
    const mline = svgEl("line", {class: "marker", y1: box.t, y2: box.b, stroke: "#b3541e",
      "stroke-dasharray": "3,2", visibility: "hidden"});
    const dots = series.map((s, k) => svgEl("circle", {class: "marker-dot", "data-series": k,
      r: 3.2, fill: s.color, stroke: "#fff", "stroke-width": 1, visibility: "hidden"}));
    over.appendChild(cross); over.appendChild(mline);
    dots.forEach((d) => over.appendChild(d));
    svg.appendChild(over);
    const tip = makeTooltip(svg, W, H);
    const xs0 = series.length ? series[0].x : [];

    function marker(i) {
      const x = xs0[i];
      show(mline, finite(x));
      if (finite(x)) { mline.setAttribute("x1", X(x)); mline.setAttribute("x2", X(x)); }
      dots.forEach((dot, k) => {
        const xk = series[k].x[i], yk = series[k].y[i], on = finite(xk) && finite(yk);
        show(dot, on);
        if (on) { dot.setAttribute("cx", X(xk)); dot.setAttribute("cy", Y(yk)); }
      });
    }

    // the index of series 0 nearest in x to the mouse, -1 outside the plot box
    function pointed(ev) {
      const p = toSvg(svg, ev);
      return inBox(p, box) ? {i: nearestIndex(xs0, fromX(p.x)), p} : {i: -1, p};
    }

    function onMove(ev) {
      const {i, p} = pointed(ev);
      if (i < 0) { show(cross, false); tip.hide(); return; }
      const px = X(xs0[i]);
      cross.setAttribute("x1", px); cross.setAttribute("x2", px);
      show(cross, true);
      const lines = [{text: (opts.xlabel ? text(opts.xlabel) + ": " : "") + fmt(xs0[i])}];
      for (const s of series) {
        const name = s.label || text(opts.ylabel);
        lines.push({text: (name ? name + ": " : "") + fmt(s.y[i]), color: s.color});
      }
      tip.show(px, p.y, lines);
    }
    function onLeave() { show(cross, false); tip.hide(); }
    function onClick(ev) {
      const {i} = pointed(ev);
      if (i >= 0 && typeof opts.onpick === "function") opts.onpick(i);
    }
    return {el, marker, destroy: listen(svg, el, onMove, onLeave, onClick)};
  }

  // ---- heat maps -----------------------------------------------------------------------

  // viridis at t in [0, 1], as "rgb(r,g,b)"
  function viridis(t) {
    const u = Math.min(1, Math.max(0, t)) * (VIRIDIS.length - 1);
    const k = Math.min(VIRIDIS.length - 2, Math.floor(u)), f = u - k;
    const c = (hex, o) => parseInt(hex.slice(o, o + 2), 16);
    const mix = (o) => Math.round(c(VIRIDIS[k], o) * (1 - f) + c(VIRIDIS[k + 1], o) * f);
    return `rgb(${mix(1)},${mix(3)},${mix(5)})`;
  }

  // The n + 1 cell edges around n ascending grid values: midway between neighbours, the
  // outer ones half a spacing beyond the first and last values.
  function cellEdges(v) {
    const n = v.length;
    if (n === 0) return [0, 1];
    if (n === 1) { const h = Math.abs(v[0]) * 0.05 || 0.5; return [v[0] - h, v[0] + h]; }
    const e = [v[0] - (v[1] - v[0]) / 2];
    for (let i = 1; i < n; i++) e.push((v[i - 1] + v[i]) / 2);
    e.push(v[n - 1] + (v[n - 1] - v[n - 2]) / 2);
    return e;
  }

  // The colour bar right of the box: a column of bands with nice ticks, titled zlabel.
  const BAR_GAP = 10, BAR_W = 10;
  function drawColorBar(svg, box, zt, zlabel, fmt) {
    const g = svgEl("g", {class: "colorbar", "font-size": FONT, fill: "#333"});
    const x0 = box.r + BAR_GAP, Z = linear(zt.lo, zt.hi, box.b, box.t), bands = 48;
    for (let k = 0; k < bands; k++) {
      const y = box.t + (box.b - box.t) * k / bands;
      g.appendChild(svgEl("rect", {x: x0, y, width: BAR_W, height: (box.b - box.t) / bands + 0.5,
        fill: viridis(1 - (k + 0.5) / bands)}));
    }
    g.appendChild(svgEl("rect", {x: x0, y: box.t, width: BAR_W, height: box.b - box.t,
      fill: "none", stroke: "#888"}));
    let widest = 0;
    for (const v of zt.ticks) {
      const y = Z(v), label = fmt(v);
      widest = Math.max(widest, label.length);
      g.appendChild(svgEl("line", {x1: x0 + BAR_W, x2: x0 + BAR_W + 3, y1: y, y2: y,
        stroke: "#888"}));
      g.appendChild(svgEl("text", {class: "ztick", x: x0 + BAR_W + 5, y: y + 3.5}, label));
    }
    if (zlabel) {
      const x = x0 + BAR_W + 5 + widest * CHAR + 10;
      g.appendChild(svgEl("text", {class: "zlabel", x: 0, y: 0, "text-anchor": "middle",
        transform: `translate(${x} ${(box.t + box.b) / 2}) rotate(-90)`}, zlabel));
    }
    svg.appendChild(g);
  }

  function map(opts) {
    opts = opts || {};
    const fmt = safeFormat(opts.format);
    const W = opts.width || 360, H = opts.height || 220;
    const gx = opts.x || [], gy = opts.y || [], rows = opts.z || [];
    const zAt = (i, j) => { const v = rows[j] ? rows[j][i] : null; return finite(v) ? v : null; };
    const zs = [];
    for (let j = 0; j < gy.length; j++) for (let i = 0; i < gx.length; i++) zs.push(zAt(i, j));
    const ex = cellEdges(gx), ey = cellEdges(gy);
    const xt = niceTicks(ex[0], ex[ex.length - 1], false);
    const yt = niceTicks(ey[0], ey[ey.length - 1], false);
    const zt = niceTicks(...extent(zs), false);
    const zlabel = text(opts.zlabel);
    // room for the colour bar: gap, bar, tick labels, rotated title
    const zlen = Math.max(...zt.ticks.map((v) => fmt(v).length));
    const right = BAR_GAP + BAR_W + 5 + zlen * CHAR + (zlabel ? 18 : 4);
    const {el, svg} = makeRoot(W, H);
    const box = plotBox(opts, W, H, xt.ticks.map(fmt), yt.ticks.map(fmt), right);
    const X = linear(xt.lo, xt.hi, box.l, box.r), Y = linear(yt.lo, yt.hi, box.b, box.t);
    drawAxes(svg, box, X, Y, xt, yt, opts, fmt, false);

    // cells between the edges; a hair of overlap hides the seams between neighbours
    const cells = svgEl("g", {class: "cells"});
    for (let j = 0; j < gy.length; j++) {
      for (let i = 0; i < gx.length; i++) {
        const z = zAt(i, j);
        const x = X(ex[i]), y = Y(ey[j + 1]);
        cells.appendChild(svgEl("rect", {class: z === null ? "cell missing" : "cell",
          "data-i": i, "data-j": j, x, y, width: X(ex[i + 1]) - x + 0.3,
          height: Y(ey[j]) - y + 0.3,
          fill: z === null ? MISSING : viridis((z - zt.lo) / (zt.hi - zt.lo))}));
      }
    }
    svg.insertBefore(cells, svg.firstChild);   // under the axes' frame
    drawColorBar(svg, box, zt, zlabel, fmt);

    const outline = svgEl("rect", {class: "marker", fill: "none", stroke: "#ff2d55",
      "stroke-width": 2, "pointer-events": "none", visibility: "hidden"});
    svg.appendChild(outline);
    const tip = makeTooltip(svg, W, H);
    const named = (label, v) => (label ? text(label) + ": " : "") + fmt(v);

    function marker(i, j) {
      const on = i >= 0 && i < gx.length && j >= 0 && j < gy.length;
      show(outline, on);
      if (!on) return;
      const x = X(ex[i]), y = Y(ey[j + 1]);
      outline.setAttribute("x", x); outline.setAttribute("y", y);
      outline.setAttribute("width", X(ex[i + 1]) - x);
      outline.setAttribute("height", Y(ey[j]) - y);
    }

    // the cell under the mouse, or null
    function cellOf(ev) {
      const t = ev.target;
      if (!t || !t.classList || !t.classList.contains("cell")) return null;
      return {i: Number(t.getAttribute("data-i")), j: Number(t.getAttribute("data-j"))};
    }
    function onMove(ev) {
      const c = cellOf(ev);
      if (!c) { tip.hide(); return; }
      const cx = (X(ex[c.i]) + X(ex[c.i + 1])) / 2, cy = (Y(ey[c.j]) + Y(ey[c.j + 1])) / 2;
      tip.show(cx, cy, [{text: named(opts.xlabel, gx[c.i])}, {text: named(opts.ylabel, gy[c.j])},
        {text: named(zlabel, zAt(c.i, c.j))}]);
    }
    function onLeave() { tip.hide(); }
    function onClick(ev) {
      const c = cellOf(ev);
      if (c && typeof opts.onpick === "function") opts.onpick(c.i, c.j);
    }
    return {el, marker, destroy: listen(svg, el, onMove, onLeave, onClick)};
  }

  // the plot's mouse handlers on its SVG; returns its destroy(): the handlers removed,
  // the element taken out of the page
  function listen(svg, el, onMove, onLeave, onClick) {
    svg.addEventListener("mousemove", onMove);
    svg.addEventListener("mouseleave", onLeave);
    svg.addEventListener("click", onClick);
    return function destroy() {
      svg.removeEventListener("mousemove", onMove);
      svg.removeEventListener("mouseleave", onLeave);
      svg.removeEventListener("click", onClick);
      el.remove();
    };
  }

  window.AssurPlot = {line, map};
})();
