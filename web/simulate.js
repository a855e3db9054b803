// The simulate page of the hecal report (docs/report.md "The simulate page",
// docs/thesis-study.md): `hecal simulate --report` writes the study's results as page data of
// kind "simulate" (src/report/simulate_page.cc); this script shows the numbers first (the tables
// `hecal simulate` prints), then the figures: RMSE of X against the first-order bound along the
// sweep, the error distributions per method, and — when the study ran them — the consistency
// of the predicted covariance (mean NEES in its 95% band, ellipsoid coverage) and the outlier
// rejection. Helpers (el, plot, section, ...) come from web/page.js.
hecalPage.pages.simulate = function (data, root) {
  'use strict';
  const {el, fmt, table, plot, section, pageHeader} = hecalPage;
  const settings = data.settings;
  const methods = data.methods;
  const PALETTE = ['#3366cc', '#dc3912', '#ff9900', '#109618', '#990099', '#0099c6', '#dd4477',
                   '#66aa00', '#b82e2e', '#316395', '#994499', '#22aa99', '#aaaa11', '#6633cc'];
  const color = (k) => PALETTE[k % PALETTE.length];

  // The sweep's axis: the one numeric field that varies, else the labels of what varies.
  const FIELDS = [['stations', 'stations', true], ['sigma_mm', 'noise level (mm, deg)', true],
                  ['robot_scale', 'robot noise scale', true],
                  ['gross_outliers', 'gross outliers per data set', true],
                  ['setup', 'setup', false], ['noise_on', 'noise on', false], ['noise', 'noise', false],
                  ['sigma_deg', 'noise level (deg)', true]];
  const varying = FIELDS.filter(([f]) => new Set(settings.map((s) => String(s[f]))).size > 1);
  const sigmaTogether = varying.length === 2 && varying[0][0] === 'sigma_mm' &&
                        varying[1][0] === 'sigma_deg';
  const numeric = (varying.length === 1 || sigmaTogether) && varying[0][2];
  const axis = numeric
    ? {x: settings.map((s) => s[varying[0][0]]), title: varying[0][1], type: 'linear'}
    : {x: settings.map((s, i) => varying.length
                         ? varying.map(([f]) => `${f} ${s[f]}`).join(', ') : s.label),
       title: 'setting', type: 'category'};

  function summaryOf(setting, method) {
    return setting.methods.find((m) => m.method === method);
  }

  // ---- the numbers ---------------------------------------------------------------------------
  function numbers() {
    const s = section('The numbers', el('p', {class: 'muted'},
      `${settings.length} setting(s) × ${data.trials_per_setting} trials × ${methods.length} ` +
      `method(s), seed ${data.seed}; covariance ${data.covariance}` +
      (data.reject_outliers ? '; every method through calibrate\'s outlier rejection' : '') +
      (data.estimate_noise ? '; noise estimated from the residuals' : '') +
      '. Errors of X against the truth: rotation angle (deg), translation distance (mm). ' +
      'Outliers: triangle threshold per setting and method. Bound: first-order RMSE of ml at ' +
      'the truth (RMS over the trials).'));
    for (const setting of settings) {
      s.appendChild(el('h3', {}, setting.label));
      s.appendChild(el('p', {}, `First-order bound: rotation ${fmt(setting.bound.rotation_deg)}°, ` +
        `translation ${fmt(setting.bound.translation_mm)} mm.`));
      s.appendChild(table(['method', 'fail', 'outl', 'rot median', 'RMSE', 'p10', 'p90', 'max (deg)',
                           'RMSE / bound', 'tra median', 'RMSE', 'p10', 'p90', 'max (mm)',
                           'RMSE / bound'],
        setting.methods.map((m) => [m.method, String(m.failures), String(m.outliers),
          m.rotation_deg.median, m.rotation_deg.rmse, m.rotation_deg.p10, m.rotation_deg.p90,
          m.rotation_deg.max, m.rotation_deg.rmse / setting.bound.rotation_deg,
          m.translation_mm.median, m.translation_mm.rmse, m.translation_mm.p10,
          m.translation_mm.p90, m.translation_mm.max,
          m.translation_mm.rmse / setting.bound.translation_mm])));
      const consistent = setting.methods.filter((m) => m.consistency);
      if (consistent.length) {
        const row = (name, c) => [name, c.mean_nees, `[${fmt(c.band[0], 3)}, ${fmt(c.band[1], 3)}]`,
          c.mean_nees >= c.band[0] && c.mean_nees <= c.band[1] ? 'ok' : 'out',
          `${fmt(100 * c.coverage_1sigma, 3)}%`, `${fmt(100 * c.coverage_2sigma, 3)}%`,
          c.sd_ratio.map((v) => fmt(v, 3)).join(' ')];
        const rows = [];
        for (const m of consistent) {
          rows.push(row(m.method, m.consistency));
          if (m.consistency_model) {
            rows.push(row(`${m.method}, model only (check inflated ${m.check_used})`,
                          m.consistency_model));
          }
        }
        s.appendChild(table(['covariance of X', 'mean NEES', '95% band', '', '1σ coverage',
                             '2σ coverage', 'sd ratio rx ry rz tx ty tz'], rows));
      }
      if (data.reject_outliers || setting.gross_outliers > 0) {
        const pct = (a, b) => (b > 0 ? `${fmt(100 * a / b, 3)}%` : '—');
        s.appendChild(table(['outlier rejection', 'found', 'all found', 'good rejected',
                             'RMSE clean (deg)', 'RMSE clean (mm)'],
          setting.methods.map((m) => [m.method,
            pct(m.rejection.outliers_rejected, m.rejection.outliers_injected),
            pct(m.rejection.trials_all_found, m.trials - m.failures),
            pct(m.rejection.good_rejected, m.rejection.good_stations),
            m.rejection.rotation_rmse_clean_deg, m.rejection.translation_rmse_clean_mm])));
      }
    }
  }

  // ---- the figures ---------------------------------------------------------------------------
  const twoPanels = (yRot, yTra, extra) => Object.assign({
    height: 420, grid: {rows: 1, columns: 2, pattern: 'independent'},
    xaxis: {title: {text: axis.title}, type: axis.type},
    xaxis2: {title: {text: axis.title}, type: axis.type},
    yaxis: {title: {text: yRot}, type: 'log'}, yaxis2: {title: {text: yTra}, type: 'log'},
    legend: {orientation: 'h', y: -0.2}}, extra || {});

  function againstBound(s) {
    const traces = [];
    const mode = settings.length > 1 ? 'lines+markers' : 'markers';
    methods.forEach((method, k) => {
      for (const [field, xa, ya] of [['rotation_deg', 'x', 'y'], ['translation_mm', 'x2', 'y2']]) {
        traces.push({type: 'scatter', mode, name: method, legendgroup: method,
                     showlegend: field === 'rotation_deg', xaxis: xa, yaxis: ya, x: axis.x,
                     y: settings.map((st) => summaryOf(st, method)[field].rmse),
                     line: {color: color(k)}, marker: {color: color(k)},
                     hovertemplate: `${method}<br>RMSE %{y:.4g}<extra></extra>`});
      }
    });
    for (const [field, xa, ya] of [['rotation_deg', 'x', 'y'], ['translation_mm', 'x2', 'y2']]) {
      traces.push({type: 'scatter', mode, name: 'first-order bound (ml at the truth)',
                   legendgroup: 'bound', showlegend: field === 'rotation_deg', xaxis: xa, yaxis: ya,
                   x: axis.x, y: settings.map((st) => st.bound[field]),
                   line: {color: '#000', dash: 'dash'}, marker: {color: '#000', symbol: 'x'}});
    }
    plot(s, traces, twoPanels('rotation RMSE (deg)', 'translation RMSE (mm)',
                              {title: {text: 'RMSE of X against the first-order bound'}}));
  }

  function distributions(s) {
    const traces = [];
    methods.forEach((method, k) => {
      for (const [field, xa, ya] of [['rotation_deg', 'x', 'y'], ['translation_mm', 'x2', 'y2']]) {
        const x = [], y = [];
        settings.forEach((st, i) => {
          for (const v of data.trials[i][k][field]) {
            if (v === null || v <= 0) continue;  // a log axis: exact (zero) errors are left out
            x.push(axis.x[i]);
            y.push(v);
          }
        });
        traces.push({type: 'box', name: method, legendgroup: method,
                     showlegend: field === 'rotation_deg', xaxis: xa, yaxis: ya, x, y,
                     marker: {color: color(k), size: 3}, boxpoints: false});
      }
    });
    plot(s, traces, twoPanels('rotation error (deg)', 'translation error (mm)', {
      title: {text: 'Error of X per trial (box: quartiles, whiskers 1.5 IQR)'}, boxmode: 'group',
      xaxis: {title: {text: axis.title}, type: 'category'},
      xaxis2: {title: {text: axis.title}, type: 'category'}}));
  }

  function consistency(s) {
    const traces = [];
    const first = settings.map((st) => st.methods.find((m) => m.consistency));
    traces.push({type: 'scatter', mode: 'lines', x: axis.x, y: first.map((m) => m.consistency.band[1]),
                 line: {width: 0}, showlegend: false, hoverinfo: 'skip'});
    traces.push({type: 'scatter', mode: 'lines', x: axis.x, y: first.map((m) => m.consistency.band[0]),
                 fill: 'tonexty', fillcolor: 'rgba(120,120,120,0.2)', line: {width: 0},
                 name: '95% band of the mean NEES (6 dof)', hoverinfo: 'skip'});
    methods.forEach((method, k) => {
      const ms = settings.map((st) => summaryOf(st, method));
      if (!ms.every((m) => m.consistency)) return;
      traces.push({type: 'scatter', mode: 'lines+markers', name: method, legendgroup: method,
                   x: axis.x, y: ms.map((m) => m.consistency.mean_nees),
                   line: {color: color(k)}, marker: {color: color(k)}});
      traces.push({type: 'bar', name: method, legendgroup: method, showlegend: false,
                   xaxis: 'x2', yaxis: 'y2', x: axis.x, y: ms.map((m) => 100 * m.consistency.coverage_2sigma),
                   marker: {color: color(k)}});
    });
    plot(s, traces, {title: {text: 'Consistency of the predicted covariance of X'}, height: 420,
                     grid: {rows: 1, columns: 2, pattern: 'independent'}, barmode: 'group',
                     xaxis: {title: {text: axis.title}, type: axis.type},
                     xaxis2: {title: {text: axis.title}, type: 'category'},
                     yaxis: {title: {text: 'mean NEES'}, type: 'log'},
                     yaxis2: {title: {text: 'trials inside the 2σ ellipsoid (%; dashed: 95.4%)'}, range: [0, 100]},
                     legend: {orientation: 'h', y: -0.2},
                     shapes: [{type: 'line', xref: 'x2 domain', x0: 0, x1: 1, yref: 'y2', y0: 95.4,
                               y1: 95.4, line: {color: '#000', dash: 'dash'}}]});
  }

  function rejection(s) {
    const traces = [];
    methods.forEach((method, k) => {
      const ms = settings.map((st) => summaryOf(st, method).rejection);
      const frac = (a, b) => ms.map((r) => (r[b] > 0 ? 100 * r[a] / r[b] : null));
      traces.push({type: 'bar', name: method, legendgroup: method, x: axis.x,
                   y: frac('outliers_rejected', 'outliers_injected'), marker: {color: color(k)}});
      traces.push({type: 'bar', name: method, legendgroup: method, showlegend: false,
                   xaxis: 'x2', yaxis: 'y2', x: axis.x, y: frac('good_rejected', 'good_stations'),
                   marker: {color: color(k)}});
    });
    plot(s, traces, {title: {text: 'Outlier rejection'}, height: 400, barmode: 'group',
                     grid: {rows: 1, columns: 2, pattern: 'independent'},
                     xaxis: {title: {text: axis.title}, type: 'category'},
                     xaxis2: {title: {text: axis.title}, type: 'category'},
                     yaxis: {title: {text: 'gross outliers found (%)'}},
                     yaxis2: {title: {text: 'good stations rejected (%)'}},
                     legend: {orientation: 'h', y: -0.2}});
  }

  pageHeader('hecal simulate: the thesis study', data);
  if (data.trials_sampled) {
    root.appendChild(el('div', {class: 'note'}, 'The distributions show an even sample of the ' +
      `${data.trials_total} trials per setting (${data.trials[0][0].rotation_deg.length} for the ` +
      'first method of the first setting); the numbers use every trial.'));
  }
  numbers();
  const figures = section('Figures', el('p', {class: 'muted'},
    'Log scales. The bound is what an efficient estimator reaches to first order; a method ' +
    'near it is as good as the data allow.'));
  againstBound(figures);
  distributions(figures);
  if (settings.every((st) => st.methods.some((m) => m.consistency))) consistency(figures);
  if (data.reject_outliers || settings.some((st) => st.gross_outliers > 0)) rejection(figures);
};
