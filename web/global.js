// The target-free page of the hecal report (docs/report.md "The global page", docs/global.md):
// `hecal report GLOBAL.json` and `calibrate --method global --report` write the result of the
// certified global calibration as page data of kind "global" (src/report/global_page.cc: the
// checked result file plus the answer worked out in degrees and millimetres). Sections: the
// answer (X with its frames spelled out and 1σ; the target-free method has no Z), the
// certificate, the residuals per motion (pair of stations), the uncertainty (σ per axis, 95%
// ellipses, the model check) and the matches removed. Helpers come from web/page.js.
hecalPage.pages.global = function (data, root) {
  'use strict';
  const {el, fmt, table, plot, section, pageHeader, poseEllipses, frameWords, AXES, COLORS} =
      hecalPage;
  const r = data.result, a = data.answer, n = data.noise;
  const cov = r.covariance, cert = r.certificate;
  const DEG = 180 / Math.PI;

  pageHeader('hecal target-free calibration report', data);

  // ---- the answer ----------------------------------------------------------------------------
  const s = section('The answer', el('p', {}, `Setup ${r.setup}, method global (target-free: ` +
    `point matches between station images, no calibration target, so no Z); ${r.matches.inliers} ` +
    `matches kept, ${r.matches.removed.length} removed; covariance: ${cov.method}.`));
  s.appendChild(el('h3', {}, `X = ${frameWords(r.X.frame)}`));
  const parent = cov.translation_in_parent;
  const rows = AXES.map((ax, i) => [`t${ax}`, a.matrix_mm[i][3], parent.translation[i] * 1000, 'mm',
    `along the ${parent.frame} frame's ${ax} axis`]);
  rows.push(['rotation', a.angle_deg, '', 'deg', `about the axis (${a.axis.map((v) => fmt(v, 3))
    .join(', ')}); quaternion wxyz (${a.quaternion_wxyz.map((v) => fmt(v, 6)).join(', ')})`]);
  AXES.forEach((ax, i) => rows.push([`r${ax}`, '', a.sigma.rotation_deg[i], 'deg',
    `1σ of a small rotation about X's own ${ax} axis`]));
  s.appendChild(table(['', 'value', '1σ', 'unit', 'meaning'], rows));
  s.appendChild(el('p', {}, `The certified L∞ optimum (before the L2 polish) is ` +
    `${fmt(a.l_infinity_from_X.angle_deg)}° and ${fmt(a.l_infinity_from_X.distance_mm)} mm from X. ` +
    `Noise (${n.robot_sigma === 'given' ? 'robot given, ray estimated' : 'estimated'}): ray ` +
    `${fmt(n.ray_sigma_rad)} rad; robot per pose ${fmt(n.robot_rotation_sigma_deg)}°, ${fmt(n.robot_translation_sigma_mm)} mm. ` +
    `Polish: residual RMS ${fmt(r.polish.rms_rad)} rad over ${r.polish.pairs} pairs.`));
  s.appendChild(el('h3', {}, 'The certificate'));
  s.appendChild(table(['', 'value'], [
    ['largest ray error at the optimum (rad)', `in [${fmt(cert.lower)}, ${fmt(cert.upper)}]`],
    ['certified', cert.certified ? 'yes: the gap closed' : `no: stopped by ${cert.stopped_by}`],
    ['requested gap', `${fmt(cert.epsilon)} rad or ${fmt(100 * cert.relative_gap)}% of the optimum`],
    ['search', `${cert.cubes} cubes, ${cert.lps} LPs, ${fmt(cert.search_seconds)} s ` +
               `(budget ${fmt(cert.time_budget_s)} s, ${cert.max_cubes} cubes)`],
    ['translation searched up to', `${fmt(cert.reach_m)} m`]]));
  if (r.warnings.length === 0) s.appendChild(el('p', {}, 'No warnings.'));
  for (const w of r.warnings) {
    s.appendChild(el('div', {class: 'warning'}, el('div', {}, '⚠ ' + w),
      el('div', {class: 'todo'}, 'See docs/global.md ("The search and the certificate", ' +
        '"Limits") for what this means and which flag changes it.')));
  }

  // ---- residuals per motion ------------------------------------------------------------------
  if (!r.motions) {
    section('Residuals per motion', el('p', {class: 'note'},
      'This result file has no per-motion residuals (written by an older hecal).'));
  } else {
    const m = r.motions;
    const names = m.map((x) => `${x.first} → ${x.second}`);
    const rs = section('Residuals per motion', el('p', {class: 'muted'},
      `Each motion (a pair of stations): the RMS and largest Sampson angle of its kept matches ` +
      `at X (radians of ray), and its matches kept and removed. ${m.length} motions.`));
    plot(rs, [
      {type: 'bar', name: 'RMS', x: names, y: m.map((x) => x.rms_rad), marker: {color: COLORS.used}},
      {type: 'scatter', mode: 'markers', name: 'largest', x: names, y: m.map((x) => x.max_rad),
       marker: {color: COLORS.flagged, symbol: 'diamond', size: 8}},
      {type: 'bar', name: 'kept', x: names, y: m.map((x) => x.pairs), xaxis: 'x2', yaxis: 'y2',
       marker: {color: COLORS.X}},
      {type: 'bar', name: 'removed', x: names, y: m.map((x) => x.removed), xaxis: 'x2', yaxis: 'y2',
       marker: {color: COLORS.rejected}}],
      {height: 560, grid: {rows: 2, columns: 1, pattern: 'independent'}, barmode: 'stack',
       yaxis: {title: {text: 'residual (rad)'}}, yaxis2: {title: {text: 'matches'}},
       xaxis: {type: 'category'}, xaxis2: {type: 'category', title: {text: 'motion'}},
       legend: {orientation: 'h', y: 1.08}});
  }

  // ---- uncertainty ---------------------------------------------------------------------------
  const us = section('Uncertainty', el('p', {class: 'muted'},
    '1σ per axis of the right perturbation δ in X = X̂·Exp(δ): with the robot\'s pose error ' +
    'marginalised (the covariance written) and with every match taken as independent (too ' +
    'small when the robot poses are noisy, docs/global.md).'));
  const rot = ['rx', 'ry', 'rz'], tra = ['tx', 'ty', 'tz'];
  const bars = [];
  for (const [label, sig, color] of [['covariance of X', a.sigma, COLORS.X],
                                     ['matches independent', a.sigma_independent_pairs, COLORS.line]]) {
    bars.push({type: 'bar', name: label, legendgroup: label, x: rot, y: sig.rotation_deg,
               marker: {color}});
    bars.push({type: 'bar', name: label, legendgroup: label, showlegend: false, x: tra,
               y: sig.translation_mm, xaxis: 'x2', yaxis: 'y2', marker: {color}});
  }
  plot(us, bars, {title: {text: 'σ per axis'}, height: 340, barmode: 'group',
                  grid: {rows: 1, columns: 2, pattern: 'independent'},
                  yaxis: {title: {text: 'σ (deg)'}}, yaxis2: {title: {text: 'σ (mm)'}}});
  poseEllipses(us, cov.X, 1000, 'mm');
  const mc = cov.model_check;
  us.appendChild(el('h3', {}, 'Model check: model σ against the jackknife over the stations'));
  if (!mc.possible) {
    us.appendChild(el('p', {}, 'No model check: ' + mc.reason));
  } else {
    us.appendChild(el('p', {class: 'muted'}, mc.flagged.length
      ? `Flagged (the model understates): ${mc.flagged.join(', ')}` +
        (mc.used ? '; the covariance written was inflated on those axes.' : '.')
      : 'No axis flagged.'));
    const check = [];
    for (const [label, part, color] of [['model', 'sigma_model', COLORS.X],
                                        ['jackknife', 'sigma_check', COLORS.jack]]) {
      check.push({type: 'bar', name: label, legendgroup: label, x: rot,
                  y: mc[part].X.rotation_rad.map((v) => v * DEG), marker: {color}});
      check.push({type: 'bar', name: label, legendgroup: label, showlegend: false, x: tra,
                  y: mc[part].X.translation_m.map((v) => v * 1000), xaxis: 'x2', yaxis: 'y2',
                  marker: {color}});
    }
    plot(us, check, {height: 340, barmode: 'group', grid: {rows: 1, columns: 2, pattern: 'independent'},
                     yaxis: {title: {text: 'σ (deg)'}}, yaxis2: {title: {text: 'σ (mm)'}}});
  }

  // ---- matches -------------------------------------------------------------------------------
  const ms = section('Matches', el('p', {}, `${r.matches.inliers} kept. Thresholds: L∞ rounds ` +
    `${fmt(r.matches.threshold_rad)} rad; from the pixel σ (${fmt(r.matches.pixel_sigma)}) ` +
    `${fmt(r.matches.pixel_threshold_rad)} rad; the data's error scale ` +
    `${fmt(r.matches.error_scale_rad)} rad.`));
  const removed = r.matches.removed;
  const byStage = {};
  for (const x of removed) byStage[x.by] = (byStage[x.by] || 0) + 1;
  ms.appendChild(table(['removed by', 'matches'], Object.entries(byStage).map(([k, v]) => [k, String(v)])));
  const LIST = 200;
  if (removed.length) {
    const details = el('details', {}, el('summary', {}, `The removed matches` +
      (removed.length > LIST ? ` (the first ${LIST} of ${removed.length})` : '')));
    details.appendChild(table(['motion', 'match id', 'removed by'], removed.slice(0, LIST)
      .map((x) => [`${x.first} → ${x.second}`, String(x.id), x.by])));
    ms.appendChild(details);
  }
};
