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

  // "T_base_camera" → "the camera's pose in the robot base frame".
  function frameWords(frame) {
    const m = /^T_([a-z]+)_([a-z]+)$/.exec(frame);
    if (!m) return frame;
    const names = {base: 'robot base', gripper: 'gripper (flange)', camera: 'camera',
                   target: 'calibration target'};
    return `${frame}: the ${names[m[2]] || m[2]}'s pose in the ${names[m[1]] || m[1]} frame ` +
           `(maps ${m[2]} coordinates to ${m[1]} coordinates)`;
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

  // The figure of X's 95% error ellipses for each pair of axes (marginal 2×2 blocks, χ²₂) from the
  // 6×6 covariance C of (ω, v) in radians and a length unit; `scale` turns that unit into `unit`.
  function poseEllipses(parent, C, scale, unit) {
    const rot = ['rx', 'ry', 'rz'], tra = ['tx', 'ty', 'tz'];
    const colors = ['#3366cc', '#dc3912', '#109618'];
    const traces = [];
    [[0, 1], [0, 2], [1, 2]].forEach(([i, j], k) => {
      const [rx, ry] = ellipse(C, i, j, 180 / Math.PI, Math.sqrt(CHI2_95_2D));
      traces.push({type: 'scatter', mode: 'lines', x: rx, y: ry, name: `${rot[i]}–${rot[j]}`,
                   line: {color: colors[k]}, legendgroup: String(k)});
      const [tx, ty] = ellipse(C, i + 3, j + 3, scale, Math.sqrt(CHI2_95_2D));
      traces.push({type: 'scatter', mode: 'lines', x: tx, y: ty, name: `${tra[i]}–${tra[j]}`,
                   xaxis: 'x2', yaxis: 'y2', line: {color: colors[k], dash: 'dot'},
                   legendgroup: String(k)});
    });
    return plot(parent, traces, {
      title: {text: '95% ellipses of X\'s error (pairs of axes, marginal)'}, height: 400,
      grid: {rows: 1, columns: 2, pattern: 'independent'},
      xaxis: {title: {text: 'rotation (deg)'}, scaleanchor: 'y'}, yaxis: {title: {text: 'rotation (deg)'}},
      xaxis2: {title: {text: `translation (${unit})`}, scaleanchor: 'y2'},
      yaxis2: {title: {text: `translation (${unit})`}}});
  }

  // ---- 3D scenes (the calibration page's robot scene, the detect page's cameras) ------------
  // Poses are 4×4 row arrays; polylines are arrays of [x, y, z] points.
  const scene3d = (function () {
    const AXIS_COLORS = ['#d62728', '#2ca02c', '#1f77b4'];  // x red, y green, z blue
    function mul(A, B) {
      return A.map((row) => B[0].map((_, j) => row.reduce((s, v, k) => s + v * B[k][j], 0)));
    }
    function apply(T, p) {
      return [0, 1, 2].map((i) => T[i][0] * p[0] + T[i][1] * p[1] + T[i][2] * p[2] + T[i][3]);
    }
    // The inverse of a rigid transform: [Rᵀ, −Rᵀt].
    function invert(T) {
      const R = [0, 1, 2].map((i) => [0, 1, 2].map((j) => T[j][i]));
      const t = R.map((row) => -(row[0] * T[0][3] + row[1] * T[1][3] + row[2] * T[2][3]));
      return [[...R[0], t[0]], [...R[1], t[1]], [...R[2], t[2]], [0, 0, 0, 1]];
    }
    // Polylines as one trace: segments separated by nulls.
    function polyTrace(name, color, lines, width) {
      const x = [], y = [], z = [];
      for (const line of lines) {
        for (const p of line) { x.push(p[0]); y.push(p[1]); z.push(p[2]); }
        x.push(null); y.push(null); z.push(null);
      }
      return {type: 'scatter3d', mode: 'lines', name, x, y, z, line: {color, width: width || 4},
              hoverinfo: 'name'};
    }
    // A pose's x, y, z axes of length `size`: three segments.
    function triad(T, size) {
      const o = apply(T, [0, 0, 0]);
      return [0, 1, 2].map((a) => [o, apply(T, [a === 0 ? size : 0, a === 1 ? size : 0, a === 2 ? size : 0])]);
    }
    // Triads as three traces, one per axis colour.
    function axisTraces(triads, width) {
      return [0, 1, 2].map((a) => polyTrace(`${AXES[a]} axes`, AXIS_COLORS[a],
                                            triads.map((t) => t[a]), width || 5));
    }
    // A camera at T looking along its z axis (x right, y down), of depth s.
    function frustum(T, s) {
      const o = apply(T, [0, 0, 0]);
      const c = [[-0.6, -0.45], [0.6, -0.45], [0.6, 0.45], [-0.6, 0.45]].map(([u, v]) => apply(T, [u * s, v * s, s]));
      return [[o, c[0]], [o, c[1]], [o, c[2]], [o, c[3]], [c[0], c[1], c[2], c[3], c[0]]];
    }
    // A planar target at T: the rectangle [x0, x1] × [y0, y1] of its z = 0 plane (a square of
    // side `x0` when only that is given).
    function board(T, x0, y0, x1, y1) {
      if (y0 === undefined) [x1, y1, x0, y0] = [x0, x0, 0, 0];
      return [[[x0, y0], [x1, y0], [x1, y1], [x0, y1], [x0, y0]].map(([u, v]) => apply(T, [u, v, 0]))];
    }
    return {mul, apply, invert, polyTrace, triad, axisTraces, frustum, board};
  })();

  function render() {
    const data = JSON.parse(document.getElementById('hecal-data').textContent);
    const page = hecalPage.pages[data.kind];
    if (!page) {
      root.appendChild(el('p', {class: 'error'}, `This hecal cannot show a page of kind ${data.kind}.`));
      return;
    }
    page(data, root);
  }
  return {root, el, fmt, table, plot, section, pageHeader, ellipse, poseEllipses, frameWords, render,
          scene3d, CHI2_95_2D, AXES, COLORS, pages: {}};
})();
