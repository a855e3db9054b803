// The calibration page of the hecal report (docs/report.md): builds its sections and Plotly.js
// figures from the page data that src/report/html_report.cc writes into <script id="hecal-data">
// (kind "calibration"). The fields are those of the result file (docs/result-file.md), already
// checked by report_input.cc. Helpers (el, plot, section, ...) come from web/page.js.
hecalPage.pages.calibration = function (data, root) {
  'use strict';
  const {el, fmt, table, plot, section, pageHeader, poseEllipses, frameWords, AXES, COLORS} =
      hecalPage;
  const {mul, polyTrace, triad, axisTraces, frustum, board} = hecalPage.scene3d;
  // What to do about a warning of the result file (the texts of src/estimation and src/jobs).
  const ADVICE = [
    [/measures the target at/i, 'Measure the printed target (ten squares with calipers) and set ' +
     'its size in the target description, or pass --target-scale stated if the print was ' +
     'measured and the description is right (docs/target-scale.md).'],
    [/global optimum|certified globally/i, 'Compare --method all, check for a wrong station, and ' +
     'add stations that rotate about different axes (docs/certificate.md).'],
    [/noise not given|estimated/i, 'The noise model was estimated from these residuals. If you ' +
     'know your robot\'s and camera\'s accuracy, give it with --robot-sigma MM,DEG and ' +
     '--camera-sigma MM,DEG: the σ then do not lean on this data set alone.'],
    [/model check|jackknife|understate/i, 'The model\'s σ understate the spread between ' +
     'station groups on the axes named: trust the jackknife column of the model check, and add ' +
     'stations with larger, more varied rotations.'],
    [/flagged|outlier|3-sigma|3σ/i, 'Look at the flagged stations in the residual plot (hover ' +
     'for their ids): re-measure or remove them, or check that robot and camera rows are paired.'],
    [/reject/i, 'The rejected stations did not fit the others at all: check their rows (pairing, ' +
     'a failed detection, a pose in another unit). --keep-outliers keeps them.'],
    [/convention|invers|transpos/i, 'Check the pose conventions (docs/conventions.md): ' +
     '--robot-inverse / --camera-inverse, --euler, --degrees.'],
    [/project|orthonormal/i, 'The rotations in the file were not exactly rotations: write them ' +
     'with more digits.'],
    [/plausib|unit|scale/i, 'Check the length unit (--units) and the setup (--setup).'],
  ];
  function advice(text) {
    for (const [pattern, what] of ADVICE) if (pattern.test(text)) return what;
    return 'See docs/cli.md for what this warning means.';
  }

  function quatAngleDeg(q) {
    return 2 * Math.acos(Math.min(1, Math.abs(q[0]))) * 180 / Math.PI;
  }
  function relativeAngleDeg(q1, q2) {
    const dot = Math.abs(q1[0] * q2[0] + q1[1] * q2[1] + q1[2] * q2[2] + q1[3] * q2[3]);
    return 2 * Math.acos(Math.min(1, dot)) * 180 / Math.PI;
  }
  function axisOf(q) {
    const n = Math.hypot(q[1], q[2], q[3]);
    return n > 0 ? [q[1] / n, q[2] / n, q[3] / n] : [0, 0, 1];
  }

  // ---- the answer ---------------------------------------------------------------------------
  function answer(r) {
    const unit = r.units.length;
    const s = section('The answer');
    s.appendChild(el('p', {}, `Setup ${r.setup}, method ${r.method}` +
      (r.covariance ? `, covariance ${r.covariance.method}` : ', no covariance') +
      `; ${r.stations.used.length} stations used, ${r.stations.rejected.length} rejected.`));
    for (const name of ['X', 'Z']) {
      const pose = r[name];
      const sig = r.covariance ? r.covariance.sigma[name] : null;
      s.appendChild(el('h3', {}, `${name} = ${frameWords(pose.frame)}`));
      const rows = AXES.map((a, i) => [
        `t${a}`, pose.translation[i], sig ? sig.translation_in_parent.translation[i] : '—',
        unit, `along the ${sig ? sig.translation_in_parent.frame : ''} frame's ${a} axis`]);
      const q = pose.quaternion_wxyz;
      const axis = axisOf(q);
      rows.push(['rotation', quatAngleDeg(q), '', 'deg',
                 `about the axis (${axis.map((v) => fmt(v, 3)).join(', ')}); quaternion wxyz ` +
                 `(${q.map((v) => fmt(v, 6)).join(', ')})`]);
      AXES.forEach((a, i) => rows.push([`r${a}`, '', sig ? sig.rotation_deg[i] : '—', 'deg',
        `1σ of a small rotation about ${name}'s own ${a} axis`]));
      s.appendChild(table(['', 'value', '1σ', 'unit', 'meaning'], rows));
    }
    const n = r.noise;
    s.appendChild(el('p', {}, `Noise model (per axis, ${n.estimated ? 'estimated from the residuals' : 'given'}): ` +
      `robot ${fmt(n.robot_sigma.translation)} ${unit}, ${fmt(n.robot_sigma.rotation_deg)}°; ` +
      `camera ${fmt(n.camera_sigma.translation)} ${unit}, ${fmt(n.camera_sigma.rotation_deg)}°. ` +
      `Residual RMS: ${fmt(r.residuals.rotation_rms_deg)}°, ${fmt(r.residuals.translation_rms)} ${unit}.`));
    const t = r.target;
    if (t && t.scale !== undefined) {
      let text = `Target scale (measured ÷ described size): ${fmt(t.scale, 4)} ± ` +
        `${fmt(t.scale_sigma, 4)}`;
      if (t.described && t.measured) {
        const key = Object.keys(t.described)[0];
        text += `; ${key} measured ${fmt(t.measured[key], 5)} ± ${fmt(t.measured[key + '_sigma'], 3)}` +
          ` ${unit}, described ${fmt(t.described[key], 5)} ${unit}`;
      }
      text += t.applied_scale !== 1 ? '. X and Z are at the measured size.' :
        '. X and Z are at the described size.';
      s.appendChild(el('p', {}, text));
    } else if (t) {
      s.appendChild(el('p', {}, `Target scale: not observable (${t.reason}).`));
    }
    if (r.certificate) {
      s.appendChild(el('p', {}, r.certificate.certified ?
        `Certified globally optimal (dual gap ${fmt(r.certificate.dual_gap, 2)}).` :
        'Not certified globally optimal (docs/certificate.md).'));
    }
    if (r.warnings.length === 0) s.appendChild(el('p', {}, 'No warnings.'));
    for (const w of r.warnings) {
      s.appendChild(el('div', {class: 'warning'}, el('div', {}, '⚠ ' + w),
                       el('div', {class: 'todo'}, 'What to do: ' + advice(w))));
    }
  }

  // ---- residuals ----------------------------------------------------------------------------
  function residuals(r) {
    const unit = r.units.length;
    const res = r.residuals;
    const s = section('Residuals per station', el('p', {class: 'muted'},
      `Each station's residual Z⁻¹·A·X·B: its rotation angle, its translation length and the ` +
      `residual whitened by its covariance under the noise model (≈ 1 for an inlier; flagged ` +
      `beyond 3). ${res.stations_total} used stations` +
      (res.per_station.length < res.stations_total ? `, ${res.per_station.length} plotted` : '') +
      `; rejected stations are drawn after them. Hover for the station's id (the pose file's ` +
      `id column, or its 0-based row)` + (data.robot_lines.length ? ' and its line in the robot file.' : '.')));
    const groups = [
      ['used', res.per_station.filter((p) => !p.outlier), COLORS.used, 'circle'],
      ['flagged (beyond 3σ)', res.per_station.filter((p) => p.outlier), COLORS.flagged, 'diamond'],
      ['rejected', res.rejected.map((p, k) => Object.assign({index: res.stations_total + k}, p)),
       COLORS.rejected, 'x'],
    ];
    const traces = [];
    const rows = [['rotation_deg', 'y', 'rotation (deg)'], ['translation', 'y2', `translation (${unit})`],
                  ['whitened', 'y3', 'whitened']];
    for (const [label, points, color, symbol] of groups) {
      rows.forEach(([field, yaxis], j) => traces.push({
        type: 'scatter', mode: 'markers', name: label, legendgroup: label, showlegend: j === 0,
        x: points.map((p) => p.index), y: points.map((p) => p[field]), yaxis,
        marker: {color, symbol, size: 7},
        text: points.map((p) => `station ${p.id} (used station #${p.index}` +
          (data.robot_lines.length && p.index < data.robot_lines.length
            ? `, robot file line ${data.robot_lines[p.index]})` : ')')),
        hovertemplate: `%{text}<br>${field}: %{y:.4g}<extra>${label}</extra>`}));
    }
    const end = res.stations_total + res.rejected.length;
    const lines = [['y', 3 * res.rotation_rms_deg, '3 × RMS'], ['y2', 3 * res.translation_rms, '3 × RMS'],
                   ['y3', 3, '3σ']];
    for (const [yaxis, level, label] of lines) {
      traces.push({type: 'scatter', mode: 'lines', x: [-0.5, end - 0.5], y: [level, level], yaxis,
                   line: {color: COLORS.line, dash: 'dash'}, name: label, showlegend: false,
                   hoverinfo: 'name'});
    }
    plot(s, traces, {height: 620, grid: {rows: 3, columns: 1, pattern: 'coupled'},
                     yaxis: {title: {text: rows[0][2]}}, yaxis2: {title: {text: rows[1][2]}},
                     yaxis3: {title: {text: rows[2][2]}}, xaxis: {title: {text: 'station (order used)'}},
                     legend: {orientation: 'h', y: 1.08}});
  }

  // ---- uncertainty ---------------------------------------------------------------------------
  function uncertainty(r) {
    const unit = r.units.length;
    const c = r.covariance;
    if (!c) {
      section('Uncertainty', el('p', {}, 'This result has no covariance.'));
      return;
    }
    const s = section('Uncertainty', el('p', {class: 'muted'},
      `1σ per axis of the right perturbation δ in X = X̂·Exp(δ) (covariance ${c.method}): ` +
      `rotations about, and translations along, each pose's own axes.`));
    const rot = ['rx', 'ry', 'rz'], tra = ['tx', 'ty', 'tz'];
    const bars = [];
    for (const name of ['X', 'Z']) {
      bars.push({type: 'bar', name: `${name} rotation`, x: rot, y: c.sigma[name].rotation_deg,
                 marker: {color: COLORS[name]}, legendgroup: name});
      bars.push({type: 'bar', name: `${name} translation`, x: tra, y: c.sigma[name].translation,
                 xaxis: 'x2', yaxis: 'y2', marker: {color: COLORS[name], opacity: 0.7},
                 legendgroup: name});
    }
    plot(s, bars, {title: {text: 'σ per axis'}, height: 340, barmode: 'group',
                   grid: {rows: 1, columns: 2, pattern: 'independent'},
                   yaxis: {title: {text: 'σ (deg)'}}, yaxis2: {title: {text: `σ (${unit})`}}});
    poseEllipses(s, c.X, 1, unit);
    const mc = c.model_check;
    if (!mc) return;
    s.appendChild(el('h3', {}, 'Model check: model σ against the jackknife'));
    if (!mc.possible) {
      s.appendChild(el('p', {}, 'No model check: ' + mc.reason));
      return;
    }
    s.appendChild(el('p', {class: 'muted'},
      'The jackknife leaves station groups out in turn; its σ should match the model\'s. ' +
      (mc.flagged.length ? `Flagged (model understates): ${mc.flagged.join(', ')}` +
       (mc.used ? '; the reported covariance was inflated on those axes.' : '.')
                         : 'No axis flagged.')));
    const mtraces = [];
    for (const [part, label, color] of [['sigma_model', 'model', COLORS.X],
                                         ['sigma_check', 'jackknife', COLORS.jack]]) {
      mtraces.push({type: 'bar', name: `${label}`, x: rot, y: mc[part].X.rotation_deg,
                    marker: {color}, legendgroup: label});
      mtraces.push({type: 'bar', name: label, x: tra, y: mc[part].X.translation, xaxis: 'x2',
                    yaxis: 'y2', marker: {color}, legendgroup: label, showlegend: false});
    }
    plot(s, mtraces, {title: {text: 'X: model σ and jackknife σ per axis'}, height: 340,
                      barmode: 'group', grid: {rows: 1, columns: 2, pattern: 'independent'},
                      yaxis: {title: {text: 'σ (deg)'}}, yaxis2: {title: {text: `σ (${unit})`}}});
  }

  // ---- 3D scene ------------------------------------------------------------------------------
  function scene(r) {
    const unit = r.units.length;
    const poses = data.robot_poses;
    const I = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
    const X = r.X.matrix, Z = r.Z.matrix;
    const eyeInHand = r.setup === 'eye-in-hand';
    // Scene size: the largest distance of a drawn origin from the base.
    const origins = [X, Z].concat(poses).map((T) => Math.hypot(T[0][3], T[1][3], T[2][3]));
    const size = 0.12 * Math.max(...origins, 1e-9);
    const frames = [['base', I]];
    const cams = [], boards = [];
    if (eyeInHand) {
      boards.push(board(Z, size));
      frames.push(['target (Z)', Z]);
      poses.forEach((G) => cams.push(...frustum(mul(G, X), size * 0.6)));
    } else {
      cams.push(...frustum(X, size));
      frames.push(['camera (X)', X]);
      poses.forEach((G) => boards.push(board(mul(G, Z), size * 0.6)));
    }
    const grippers = poses.map((G) => triad(G, size * 0.5));
    const traces = axisTraces(frames.map(([, T]) => triad(T, size * 1.5)).concat(grippers));
    traces.push(polyTrace('camera' + (cams.length > 5 ? 's' : ''), '#555', cams, 3));
    traces.push(polyTrace('target' + (boards.length > 1 ? 's' : ''), '#8e44ad', boards.flat(), 3));
    traces.push({type: 'scatter3d', mode: 'text+markers', name: 'frames',
                 x: frames.map(([, T]) => T[0][3]), y: frames.map(([, T]) => T[1][3]),
                 z: frames.map(([, T]) => T[2][3]), text: frames.map(([n]) => n),
                 marker: {size: 3, color: '#000'}, hoverinfo: 'text'});
    if (poses.length) {
      const flagged = new Set(r.residuals.per_station.filter((p) => p.outlier).map((p) => p.index));
      const stride = Math.max(1, Math.round(r.stations.used.length / poses.length));
      const ids = poses.map((_, k) => r.stations.used[k * stride]);
      traces.push({type: 'scatter3d', mode: 'markers', name: 'gripper poses',
                   x: poses.map((G) => G[0][3]), y: poses.map((G) => G[1][3]), z: poses.map((G) => G[2][3]),
                   text: ids.map((id) => `station ${id}`), hoverinfo: 'text',
                   marker: {size: 4, color: poses.map((_, k) => flagged.has(k * stride) ? COLORS.flagged : COLORS.used)}});
    }
    const s = section('3D scene', el('p', {class: 'muted'},
      `In the robot base frame (${unit}); drag to rotate. Axes x red, y green, z blue. ` +
      (poses.length ? 'Gripper poses as small triads (flagged stations\' markers in orange); ' +
        (eyeInHand ? 'the camera at each.' : 'the target at each.')
                    : 'The robot poses were not given (hecal report --robot FILE, or calibrate --report), ' +
                      'so the scene shows the base and the fixed ' + (eyeInHand ? 'target.' : 'camera.'))));
    plot(s, traces, {height: 560, scene: {aspectmode: 'data', xaxis: {title: {text: 'x'}},
                                          yaxis: {title: {text: 'y'}}, zaxis: {title: {text: 'z'}}},
                     margin: {l: 0, r: 0, t: 10, b: 0}});
  }

  // ---- every method --------------------------------------------------------------------------
  function methods(results, primary) {
    const unit = primary.units.length;
    const s = section('Every method', el('p', {class: 'muted'},
      `X of each method against ${primary.method}'s: the distance between the translations and ` +
      `the angle between the rotations, with each method's residual RMS and largest σ.`));
    const ok = results.filter((r) => !r.error);
    const rows = results.map((r) => {
      if (r.error) return [r.method, el('span', {class: 'error'}, 'refused: ' + r.error), '', '', '', '', ''];
      const dt = Math.hypot(...[0, 1, 2].map((i) => r.X.translation[i] - primary.X.translation[i]));
      const dr = relativeAngleDeg(r.X.quaternion_wxyz, primary.X.quaternion_wxyz);
      const sig = r.covariance ? Math.max(...r.covariance.sigma.X.translation_in_parent.translation) : NaN;
      const sigr = r.covariance ? Math.max(...r.covariance.sigma.X.rotation_deg) : NaN;
      return [r.method, dt, dr, r.residuals.translation_rms, r.residuals.rotation_rms_deg, sig, sigr];
    });
    s.appendChild(table(['method', `|ΔX t| (${unit})`, 'ΔX angle (deg)', `residual RMS (${unit})`,
                         'residual RMS (deg)', `max σ X t (${unit})`, 'max σ X r (deg)'], rows));
    const diff = (r) => Math.hypot(...[0, 1, 2].map((i) => r.X.translation[i] - primary.X.translation[i]));
    plot(s, [
      {type: 'bar', name: `|ΔX t| (${unit})`, x: ok.map((r) => r.method), y: ok.map(diff),
       marker: {color: COLORS.X}},
      {type: 'bar', name: 'ΔX angle (deg)', x: ok.map((r) => r.method),
       y: ok.map((r) => relativeAngleDeg(r.X.quaternion_wxyz, primary.X.quaternion_wxyz)),
       xaxis: 'x2', yaxis: 'y2', marker: {color: COLORS.Z}},
    ], {title: {text: `X against ${primary.method}`}, height: 360,
        grid: {rows: 1, columns: 2, pattern: 'independent'},
        yaxis: {title: {text: unit}}, yaxis2: {title: {text: 'deg'}}});
  }

  // ---- from images ---------------------------------------------------------------------------
  function images(r) {
    const im = r.images;
    const k = im.intrinsics;
    const s = section('From images', el('p', {}, `Intrinsics (${k.source}` +
      (k.rms_px !== undefined ? `, fit RMS ${fmt(k.rms_px, 3)} px` : '') + `); reprojection ` +
      `RMS ${fmt(im.reprojection_rms_px)} px over every corner at the result; pixel noise ` +
      `${fmt(im.pixel_sigma_px)} px` + (im.pixel_sigma_estimated ? ' (estimated).' : ' (given).')));
    // 1σ of (fx, fy, cx, cy, k1, k2, p1, p2, k3) when refined with X and Z (--refine-intrinsics).
    const sig = k.sigma ? k.sigma.values : null;
    const coefficients = (k.distortion && k.distortion.coefficients) || [];
    const rows = ['fx', 'fy', 'cx', 'cy'].map((n, i) => [n, k[n], sig ? sig[i] : 'not refined', 'px'])
      .concat(['k1', 'k2', 'p1', 'p2', 'k3'].slice(0, coefficients.length).map((n, i) =>
        [n, coefficients[i], sig ? sig[4 + i] : 'not refined', '']))
      .concat([['image size', `${k.width} × ${k.height}`, '', 'px']]);
    s.appendChild(table(['', 'value', '1σ', 'unit'], rows));
    const per = im.per_image;
    const perPoint = per.every((p) => p.points_px);
    const bars = plot(s, [{type: 'bar', x: per.map((p) => p.id), y: per.map((p) => p.rms_px),
              marker: {color: per.map((p) => p.outlier ? COLORS.flagged : COLORS.used)},
              hovertemplate: 'image %{x}<br>RMS %{y:.3g} px<extra>click to show</extra>'}],
         {title: {text: 'Reprojection RMS per image (flagged in orange' +
                        (perPoint ? '; click a bar to show the image)' : ')')},
          height: 340, xaxis: {title: {text: 'image (station id)'}, type: 'category'},
          yaxis: {title: {text: 'px'}}});
    if (im.skipped.length) {
      s.appendChild(table(['skipped image', 'why'], im.skipped.map((p) => [p.id, p.reason])));
    }
    if (!perPoint) {
      s.appendChild(el('div', {class: 'note'}, 'The per-point figures (residuals over the image, ' +
        'corner coverage, each image with its corners) need a result file that holds each ' +
        'image\'s corners (images.per_image[].points_px); this result file has none (an older ' +
        `hecal wrote it): calibrate again with this hecal (${data.hecal_version}) to see them.`));
      return;
    }
    hecalPage.imageFigures(s, per, k.width, k.height, data.thumbnails, [bars]);
  }

  // ---- the page ------------------------------------------------------------------------------
  const results = data.results;
  const primary = results.find((r) => !r.error && r.method === 'ml') || results.find((r) => !r.error);
  pageHeader('hecal calibration report', data);
  for (const note of data.notes) root.appendChild(el('div', {class: 'note'}, note));
  if (!primary) {
    section('No result', el('p', {class: 'error'}, 'Every method refused the data: ' +
      results.map((r) => `${r.method}: ${r.error}`).join('; ')));
    return;
  }
  answer(primary);
  residuals(primary);
  uncertainty(primary);
  scene(primary);
  if (data.all_methods) methods(results, primary);
  if (primary.images) images(primary);
};
