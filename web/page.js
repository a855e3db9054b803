// The shell of every hecal report page (docs/report.md): shared helpers and the dispatch on the
// page data's "kind" (src/report/html_report.cc writes the data into <script id="hecal-data">
// and this file, then each page kind's script, which registers itself in hecalPage.pages).
// Every figure is a <div class="plot">: the browser test (tests/report/) checks each rendered.
const hecalPage = (function () {
  'use strict';
  const root = document.getElementById('report');
  const CHI2_95_2D = 5.991;  // 95% quantile of χ² with 2 degrees of freedom
  const AXES = ['x', 'y', 'z'];
  const COLORS = {used: '#3366cc', flagged: '#e08a00', rejected: '#c0392b', line: '#888',
                  X: '#3366cc', Z: '#109618', jack: '#e08a00'};

  function el(tag, attrs, ...children) {
    const node = document.createElement(tag);
    for (const [key, value] of Object.entries(attrs || {})) node.setAttribute(key, value);
    for (const child of children) {
      if (child === null || child === undefined) continue;
      node.appendChild(typeof child === 'string' ? document.createTextNode(child) : child);
    }
    return node;
  }
  function fmt(x, digits) {
    if (!isFinite(x)) return String(x);
    return Number(x).toPrecision(digits || 4);
  }
  function table(head, rows) {
    return el('table', {}, el('tr', {}, ...head.map((h) => el('th', {}, h))),
              ...rows.map((r) => el('tr', {}, ...r.map((c) =>
                typeof c === 'number' ? el('td', {class: 'num'}, fmt(c)) : el('td', {}, c)))));
  }
  function plot(parent, traces, layout) {
    const div = el('div', {class: 'plot'});
    parent.appendChild(div);
    const base = {margin: {l: 60, r: 20, t: 40, b: 50}, font: {size: 12},
                  paper_bgcolor: '#fff', plot_bgcolor: '#fff', hovermode: 'closest'};
    Plotly.newPlot(div, traces, Object.assign(base, layout),
                   {displaylogo: false, responsive: true});
    return div;
  }
  function section(title, ...children) {
    const s = el('section', {}, el('h2', {}, title), ...children);
    root.appendChild(s);
    return s;
  }

  // The page's title and the line every page starts with (its size, offline).
  function pageHeader(heading, data) {
    root.appendChild(el('h1', {}, heading));
    root.appendChild(el('p', {class: 'muted'}, `${data.title} — hecal ${data.hecal_version}; this ` +
      `page is ${(data.page_bytes / 1e6).toFixed(2)} MB, Plotly.js included, and loads nothing ` +
      `from the network.`));
  }
  // The curve of the 2×2 block (i, j) of covariance C, scaled by `unit` (e.g. rad → deg), at k σ:
  // [xs, ys] around the origin (72 segments).
  function ellipse(C, i, j, unit, k) {
    const a = C[i][i] * unit * unit, b = C[i][j] * unit * unit, d = C[j][j] * unit * unit;
    const tr = (a + d) / 2, det = a * d - b * b;
    const disc = Math.sqrt(Math.max(0, tr * tr - det));
    const l1 = tr + disc, l2 = Math.max(0, tr - disc);
    const theta = Math.abs(b) > 1e-300 ? Math.atan2(l1 - a, b) : (a >= d ? 0 : Math.PI / 2);
    const xs = [], ys = [];
    for (let n = 0; n <= 72; ++n) {
      const t = 2 * Math.PI * n / 72;
      const u = k * Math.sqrt(l1) * Math.cos(t), v = k * Math.sqrt(l2) * Math.sin(t);
      xs.push(u * Math.cos(theta) - v * Math.sin(theta));
      ys.push(u * Math.sin(theta) + v * Math.cos(theta));
    }
    return [xs, ys];
  }

  function render() {
    const data = JSON.parse(document.getElementById('hecal-data').textContent);
    const page = hecalPage.pages[data.kind];
    if (!page) {
      root.appendChild(el('p', {class: 'error'}, `This hecal cannot show a page of kind ${data.kind}.`));
      return;
    }
    page(data, root);
  }
  return {root, el, fmt, table, plot, section, pageHeader, ellipse, render, CHI2_95_2D, AXES, COLORS,
          pages: {}};
})();
