// The contour study page of the hecal report (docs/report.md "The contour study page",
// docs/contour.md#the-experiments): `hecal contour study --report` writes the study's steps as
// page data of kind "contour_study" (src/report/contour_study_file.cc); this script shows the
// numbers (each step's errors per pose component, Monte Carlo against the Unscented Transform),
// then the contour paper's figures as Plotly.js plots:
//   Fig. 3 (id "fig3"): mean error ± 2σ against the motion, one panel per pose component,
//          UT solid, Monte Carlo dashed;
//   Fig. 4 (id "fig4"): at one step, every 2×2 block of the pose covariance as 2σ ellipses
//          (UT solid, Monte Carlo dashed) with the Monte Carlo poses and the 13 sigma points.
// scripts/docs-figures.sh screenshots both for docs/contour/. Helpers come from web/page.js.
hecalPage.pages.contour_study = function (data, root) {
  'use strict';
  const {el, fmt, table, plot, section, pageHeader, ellipse} = hecalPage;
  const comps = data.components, units = data.units, steps = data.steps;
  const UT = '#1f77b4', MC = '#d62728', SAMPLES = '#2ca02c';
  const unitOf = data.motion_label.endsWith('(deg)') ? '°' : ' mm';

  pageHeader('hecal contour study: UT against Monte Carlo', data);
  const moved = {tx: 0, ty: 1, tz: 2, rx: 3, ry: 4, rz: 5}[data.motion];

  // ---- the numbers ---------------------------------------------------------------------------
  const row = (step, j) => [`${data.motion} = ${fmt(step.value)}`, comps[j], step.mc_mean[j],
    step.mc_sd[j], step.ut_mean[j], step.ut_sd[j], step.ut_sd[j] / step.mc_sd[j],
    step.bias[j] ? 'flagged' : ''];
  const head = ['step', 'component', 'MC mean error', 'MC σ', 'UT mean error', 'UT σ',
                'UT σ / MC σ', 'bias'];
  const s = section('The numbers', el('p', {class: 'muted'},
    `Motion along ${data.motion}, ${steps.length} step(s); ${data.samples} Monte Carlo samples ` +
    `per step, seed ${data.seed}; pixel noise ${fmt(data.pixel_noise)} px per coordinate; ` +
    `target ${fmt(data.z0_mm)} mm away, f = ${fmt(data.focal_mm)} mm, pixels ` +
    `${fmt(data.pixel_size_mm)} mm. Errors against the true motion in mm (Tx, Ty, Tz) and ` +
    'degrees (Rx, Ry, Rz); bias: the UT\'s bias check (docs/contour.md#the-bias-check).'));
  s.appendChild(el('h3', {}, `The moved component, ${comps[moved]}`));
  s.appendChild(table(head, steps.map((step) => row(step, moved))));
  const every = el('details', {}, el('summary', {}, 'Every component of every step'));
  every.appendChild(table(head, steps.flatMap((step) => comps.map((c, j) => row(step, j)))));
  s.appendChild(every);

  // ---- Fig. 3 --------------------------------------------------------------------------------
  const fig3 = section('Fig. 3: pose error against the motion', el('p', {class: 'muted'},
    `Mean error ± 2σ for a motion along ${data.motion}: UT solid, Monte Carlo ` +
    `(${data.samples} samples) dashed (the contour paper's Fig. 3).`));
  const traces = [], layout = {height: 620, grid: {rows: 2, columns: 3, pattern: 'independent'},
                               legend: {orientation: 'h', y: -0.12}, annotations: []};
  const x = steps.map((st) => st.value);
  const mode = steps.length > 1 ? 'lines' : 'markers';
  comps.forEach((c, j) => {
    const n = j === 0 ? '' : String(j + 1);
    for (const [name, mean, sd, color, dash] of [['UT', 'ut_mean', 'ut_sd', UT, 'solid'],
                                                 ['MC', 'mc_mean', 'mc_sd', MC, 'dash']]) {
      const m = steps.map((st) => st[mean][j]);
      const up = steps.map((st) => st[mean][j] + 2 * st[sd][j]);
      const down = steps.map((st) => st[mean][j] - 2 * st[sd][j]);
      const common = {type: 'scatter', mode, x, xaxis: 'x' + n, yaxis: 'y' + n, legendgroup: name};
      traces.push(Object.assign({name: `${name} mean`, y: m, showlegend: j === 0,
                                 line: {color, dash, width: 2}, marker: {color}}, common));
      traces.push(Object.assign({name: `${name} ±2σ`, y: up, showlegend: j === 0,
                                 line: {color, dash, width: 1}, marker: {color, symbol: 'triangle-up'}},
                                common, {legendgroup: name + '2s'}));
      traces.push(Object.assign({name: `${name} ±2σ`, y: down, showlegend: false,
                                 line: {color, dash, width: 1}, marker: {color, symbol: 'triangle-down'}},
                                common, {legendgroup: name + '2s'}));
    }
    layout['xaxis' + n] = {title: {text: data.motion_label}};
    layout['yaxis' + n] = {title: {text: `${c} error (${units[j]})`}, zeroline: true};
  });
  plot(fig3, traces, layout).id = 'fig3';

  // ---- Fig. 4 --------------------------------------------------------------------------------
  const cov = data.covariance;
  const fig4 = section(`Fig. 4: pose covariance at ${data.motion} = ${fmt(cov.value)}${unitOf}`,
    el('p', {class: 'muted'},
      'Every pair of pose components: the errors of the Monte Carlo poses ' +
      `(${cov.mc_samples.length} shown), the 13 sigma points of the UT, and the 2σ ellipses of ` +
      'the UT (solid) and Monte Carlo (dashed) covariances (the contour paper\'s Fig. 4). ' +
      'Errors in mm and degrees. --covariance-at chooses the step.'));
  const t4 = [], l4 = {height: 760, grid: {rows: 3, columns: 5, pattern: 'independent'},
                       legend: {orientation: 'h', y: -0.08}, margin: {l: 50, r: 10, t: 30, b: 40}};
  let panel = 0;
  for (let a = 0; a < 6; ++a) {
    for (let b = a + 1; b < 6; ++b) {
      const n = panel === 0 ? '' : String(panel + 1);
      const axes = {xaxis: 'x' + n, yaxis: 'y' + n};
      const first = panel === 0;
      t4.push(Object.assign({type: 'scatter', mode: 'markers', name: 'MC poses',
                             legendgroup: 'mc', showlegend: first,
                             x: cov.mc_samples.map((p) => p[a]), y: cov.mc_samples.map((p) => p[b]),
                             marker: {color: SAMPLES, size: 2, opacity: 0.5}, hoverinfo: 'skip'}, axes));
      t4.push(Object.assign({type: 'scatter', mode: 'markers', name: 'sigma points',
                             legendgroup: 'sigma', showlegend: first,
                             x: cov.sigma_points.map((p) => p[a]), y: cov.sigma_points.map((p) => p[b]),
                             marker: {color: UT, symbol: 'x', size: 7}}, axes));
      for (const [name, mean, C, color, dash] of [['MC 2σ', cov.mc_mean, cov.mc_covariance, MC, 'dash'],
                                                  ['UT 2σ', cov.ut_mean, cov.ut_covariance, UT, 'solid']]) {
        const [ex, ey] = ellipse(C, a, b, 1, 2);
        t4.push(Object.assign({type: 'scatter', mode: 'lines', name, legendgroup: name,
                               showlegend: first, x: ex.map((v) => v + mean[a]),
                               y: ey.map((v) => v + mean[b]), line: {color, dash, width: 2},
                               hoverinfo: 'name'}, axes));
      }
      t4.push(Object.assign({type: 'scatter', mode: 'markers', name: 'MC mean', legendgroup: 'mean',
                             showlegend: first, x: [cov.mc_mean[a]], y: [cov.mc_mean[b]],
                             marker: {color: MC, size: 7}}, axes));
      l4['xaxis' + n] = {title: {text: `${comps[a]} (${units[a]})`, standoff: 2}};
      l4['yaxis' + n] = {title: {text: `${comps[b]} (${units[b]})`, standoff: 2}};
      ++panel;
    }
  }
  plot(fig4, t4, l4).id = 'fig4';
};
