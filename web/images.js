// The per-point image figures of the hecal report (docs/report.md, "From images" and "The detect
// page"), shared by the calibration page (web/calibration.js) and the detect page
// (web/detect.js): from each image's detected corners and their reprojection residuals
// (pixels, per_image[].points_px and .residuals_px; residual = projected − detected), the
// residuals as a vector field over the image, the corners' coverage of the image as a heat map,
// a clickable list of the images, and a viewer that shows one image — its thumbnail when the page
// has it (src/report/page_thumbnails.cc) — under its corners and residual arrows. Image axes in
// pixels, the origin at the centre of the top-left pixel, y down.
hecalPage.imageFigures = (function () {
  'use strict';
  const {el, fmt, plot, COLORS} = hecalPage;
  const MAX_ARROWS = 5000;   // the vector field draws at most this many arrows (an even sample)
  const ARROW_SHARE = 0.04;  // the 95th-percentile residual is drawn this share of the diagonal

  // The image frame: x right, y down, pixel centres at integers.
  function frameAxes(width, height) {
    return {
      xaxis: {title: {text: 'u (px)'}, range: [-0.5, width - 0.5], constrain: 'domain',
              zeroline: false, showgrid: false},
      yaxis: {title: {text: 'v (px), down'}, range: [height - 0.5, -0.5], scaleanchor: 'x',
              constrain: 'domain', zeroline: false, showgrid: false},
    };
  }
  function outline(width, height) {
    return {type: 'rect', x0: -0.5, y0: -0.5, x1: width - 0.5, y1: height - 0.5,
            line: {color: '#888', width: 1}, layer: 'below'};
  }
  // A "nice" number (1, 2 or 5 × 10^k) near x.
  function nice(x) {
    const p = Math.pow(10, Math.floor(Math.log10(x)));
    const m = x / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }
  // The arrows' magnification: the 95th-percentile residual length drawn as ARROW_SHARE of the
  // image diagonal, rounded to a nice number; the same for every figure of the page.
  function arrowScale(per, width, height) {
    const lengths = [];
    for (const p of per) for (const r of p.residuals_px) lengths.push(Math.hypot(r[0], r[1]));
    lengths.sort((a, b) => a - b);
    const p95 = lengths.length ? lengths[Math.floor(0.95 * (lengths.length - 1))] : 0;
    return p95 > 0 ? nice(ARROW_SHARE * Math.hypot(width, height) / p95) : 1;
  }
  // Arrows from each corner along its residual × scale, as line segments (one trace) and the
  // corners as dots; `stride` keeps every stride-th point.
  function arrowTraces(points, residuals, scale, stride, name) {
    const x = [], y = [], cx = [], cy = [], text = [];
    for (let k = 0; k < points.length; k += stride) {
      const [u, v] = points[k], [du, dv] = residuals[k];
      x.push(u, u + scale * du, null);
      y.push(v, v + scale * dv, null);
      cx.push(u);
      cy.push(v);
      text.push(`${name(k)}<br>corner (${fmt(u, 6)}, ${fmt(v, 6)}) px<br>residual ` +
                `(${fmt(du, 3)}, ${fmt(dv, 3)}) px, |r| ${fmt(Math.hypot(du, dv), 3)} px`);
    }
    return [
      {type: 'scatter', mode: 'lines', x, y, name: `residual × ${scale}`,
       line: {color: COLORS.flagged, width: 1.5}, hoverinfo: 'skip'},
      {type: 'scatter', mode: 'markers', x: cx, y: cy, name: 'detected corner', text,
       marker: {color: COLORS.used, size: 4}, hovertemplate: '%{text}<extra></extra>'},
    ];
  }

  // The cells of about 1/24 of the image's width that the field's means and the coverage use.
  function cells(width, height) {
    const size = Math.max(1, Math.round(width / 24));
    const nx = Math.ceil(width / size), ny = Math.ceil(height / size);
    const of = (u, v) => [Math.min(ny - 1, Math.max(0, Math.floor((v + 0.5) / size))),
                          Math.min(nx - 1, Math.max(0, Math.floor((u + 0.5) / size)))];
    return {size, nx, ny, of};
  }

  function vectorField(parent, per, width, height, scale) {
    const total = per.reduce((n, p) => n + p.points_px.length, 0);
    const stride = Math.max(1, Math.ceil(total / MAX_ARROWS));
    const points = [], residuals = [], names = [];
    per.forEach((p) => p.points_px.forEach((q, k) => {
      points.push(q);
      residuals.push(p.residuals_px[k]);
      names.push(`image ${p.id}, corner ${k}`);
    }));
    // The mean residual of the corners in each cell: the systematic part, which the noise hides.
    const grid = cells(width, height);
    const sums = new Map();
    points.forEach(([u, v], k) => {
      const key = grid.of(u, v).join(',');
      const s = sums.get(key) || [0, 0, 0, 0, 0];
      s[0] += u; s[1] += v; s[2] += residuals[k][0]; s[3] += residuals[k][1]; s[4] += 1;
      sums.set(key, s);
    });
    const means = [...sums.values()].filter((s) => s[4] >= 3);
    const example = nice(1 / scale * 0.04 * Math.hypot(width, height));
    parent.appendChild(el('h3', {}, 'Reprojection residuals over the image'));
    parent.appendChild(el('p', {class: 'muted'},
      `Every used image's corners in one frame; each orange line runs from the detected corner ` +
      `along its residual (projected − detected) magnified ${scale}× (a residual of ` +
      `${fmt(example, 2)} px is drawn ${fmt(example * scale, 3)} px long). The black lines are ` +
      `the mean residual of the corners in each cell of ${grid.size} × ${grid.size} px (at ` +
      `least 3 corners), at the same magnification: the systematic part. A pattern — growing ` +
      `towards the edges, turning about the centre — is a lens model that does not fit; noise ` +
      `points every way and averages out. Click a legend entry to hide it. ${total} corners` +
      (stride > 1 ? `; ${Math.ceil(total / stride)} drawn (1 in ${stride}: above ` +
       `${MAX_ARROWS} the corners are decimated; the means use every corner).` : '.')));
    const meanTraces = arrowTraces(means.map((s) => [s[0] / s[4], s[1] / s[4]]),
                                   means.map((s) => [s[2] / s[4], s[3] / s[4]]), scale, 1,
                                   (k) => `mean of ${means[k][4]} corners`);
    meanTraces[0].name = `cell mean × ${scale}`;
    meanTraces[0].line = {color: '#000', width: 3};
    meanTraces[1].name = 'cell centroid';
    meanTraces[1].marker = {color: '#000', size: 5};
    plot(parent, arrowTraces(points, residuals, scale, stride, (k) => names[k]).concat(meanTraces),
         Object.assign({height: 560, shapes: [outline(width, height)],
                        legend: {orientation: 'h', y: 1.06}}, frameAxes(width, height)));
  }

  // Detected corners per cell (cells above); the share of cells with a corner says how much of
  // the image (and so of the lens) the data constrain.
  function coverage(parent, per, width, height) {
    const grid = cells(width, height);
    const cell = grid.size, nx = grid.nx, ny = grid.ny;
    const counts = Array.from({length: ny}, () => new Array(nx).fill(0));
    let total = 0;
    for (const p of per) {
      for (const [u, v] of p.points_px) {
        const [i, j] = grid.of(u, v);
        counts[i][j] += 1;
        total += 1;
      }
    }
    const covered = counts.reduce((n, row) => n + row.filter((c) => c > 0).length, 0);
    parent.appendChild(el('h3', {}, 'Corner coverage of the image'));
    parent.appendChild(el('p', {class: 'muted'},
      `Detected corners of every used image per cell of ${cell} × ${cell} px: ${total} corners ` +
      `in ${covered} of ${nx * ny} cells (${fmt(100 * covered / (nx * ny), 3)}% of the image). ` +
      `Empty cells, above all near the edges and corners of the image, are where the lens ` +
      `distortion is least constrained: add views with the target there.`));
    const centres = (n) => Array.from({length: n}, (_, k) => -0.5 + (k + 0.5) * cell);
    plot(parent, [{type: 'heatmap', x: centres(nx), y: centres(ny),
                   z: counts.map((row) => row.map((c) => (c > 0 ? c : null))),
                   colorscale: 'Viridis', colorbar: {title: {text: 'corners'}}, xgap: 1, ygap: 1,
                   hovertemplate: 'cell at (%{x:.0f}, %{y:.0f}) px: %{z} corners<extra></extra>'}],
         Object.assign({height: 520, shapes: [outline(width, height)]},
                       frameAxes(width, height)));
  }

  // The image viewer and its list of entries; returns show(id).
  function viewer(parent, per, width, height, scale, thumbnails) {
    const byId = new Map(per.map((p) => [p.id, p]));
    const thumbs = (thumbnails && thumbnails.by_id) || {};
    parent.appendChild(el('h3', {}, 'One image: its corners and residuals'));
    const has = thumbnails ? thumbnails.count : 0;
    parent.appendChild(el('p', {class: 'muted'},
      `Click an image in the list below (or its bar in the per-image plot) to show it with its ` +
      `detected corners and residuals (× ${scale}, as above). ` +
      (has === 0 ? 'This page has no thumbnails (the images were not at hand: hecal report ' +
                   'RESULT.json --images DIR adds them).'
        : `Thumbnails: ${has} of ${thumbnails.images} images, grey JPEG ` +
          `${(thumbnails.bytes / 1e6).toFixed(2)} MB of this page` +
          (has < thumbnails.images ? ` (at most ${has} per page: the first ones; the others ` +
                                     'show their corners only).' : '.'))));
    const div = plot(parent, [], {height: 520});
    div.id = 'image-viewer';
    function show(id) {
      const p = byId.get(id);
      if (!p) return;
      const images = thumbs[id] ? [{source: thumbs[id], xref: 'x', yref: 'y', x: -0.5, y: -0.5,
                                    sizex: width, sizey: height, xanchor: 'left',
                                    yanchor: 'top', sizing: 'stretch', layer: 'below'}] : [];
      const title = `image ${p.id}` + (p.file ? ` (${p.file})` : '') + `: ${p.points_px.length} ` +
                    `corners, RMS ${fmt(p.rms_px, 3)} px` + (thumbs[id] ? '' : '; no thumbnail');
      div.dataset.image = id;
      Plotly.react(div, arrowTraces(p.points_px, p.residuals_px, scale, 1, (k) => `corner ${k}`),
                   Object.assign({height: 520, title: {text: title}, images,
                                  shapes: [outline(width, height)], hovermode: 'closest',
                                  margin: {l: 60, r: 20, t: 40, b: 50},
                                  legend: {orientation: 'h', y: -0.12}},
                                 frameAxes(width, height)),
                   {displaylogo: false, responsive: true});
    }
    const rows = per.map((p) => {
      const row = el('tr', {class: 'image-entry', 'data-image': p.id, title: 'show this image'},
                     el('td', {}, p.id), el('td', {}, p.file || ''),
                     el('td', {class: 'num'}, String(p.points_px.length)),
                     el('td', {class: 'num'}, fmt(p.rms_px, 3)),
                     el('td', {}, p.outlier ? 'flagged' : ''),
                     el('td', {}, thumbs[p.id] ? 'yes' : ''));
      row.addEventListener('click', () => {
        show(p.id);
        div.scrollIntoView({block: 'nearest'});
      });
      return row;
    });
    const head = ['image', 'file', 'corners', 'RMS (px)', '', 'thumbnail'];
    parent.appendChild(el('div', {class: 'scroll'},
      el('table', {class: 'entries'}, el('tr', {}, ...head.map((h) => el('th', {}, h))), ...rows)));
    if (per.length) show(per[0].id);
    return show;
  }

  // The figures in `parent` for the used images `per` ({id, file, rms_px, outlier, points_px,
  // residuals_px}) of width × height px; a click on a bar of the plots `clickable` (x = image
  // id) shows that image.
  return function (parent, per, width, height, thumbnails, clickable) {
    const scale = arrowScale(per, width, height);
    vectorField(parent, per, width, height, scale);
    coverage(parent, per, width, height);
    const show = viewer(parent, per, width, height, scale, thumbnails);
    for (const div of clickable || []) div.on('plotly_click', (e) => show(String(e.points[0].x)));
  };
})();
