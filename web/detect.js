// The detect page of the hecal report (`hecal detect --report`; docs/report.md, "The detect
// page"): builds its sections from the page data of src/report/detection_page.cc (kind
// "detect"): per image the detected corners and their reprojection RMS at the image's own PnP
// pose, the per-point figures of web/images.js, and the cameras' poses around the target in 3D.
// Helpers (el, plot, section, pageHeader, scene3d, ...) come from web/page.js.
hecalPage.pages.detect = function (data, root) {
  'use strict';
  const {el, fmt, table, plot, section, pageHeader, COLORS} = hecalPage;
  const {invert, polyTrace, triad, axisTraces, frustum, board} = hecalPage.scene3d;
  const per = data.per_image;
  const k = data.intrinsics;

  pageHeader('hecal detection report', data);

  // ---- the detections ----------------------------------------------------------------------
  const s = section('Detections', el('p', {},
    `Target: ${data.target}. ${per.length} images used, ${data.skipped.length} skipped. ` +
    `Intrinsics ${k.source}: fx ${fmt(k.fx)}, fy ${fmt(k.fy)}, cx ${fmt(k.cx)}, cy ${fmt(k.cy)} ` +
    `px; images ${k.width} × ${k.height} px.`), el('p', {class: 'muted'},
    'Each image\'s RMS is that of its corners\' residuals (projected − detected) at its own ' +
    'refined PnP pose: a high one is a blurred view, a partly wrong detection, or intrinsics ' +
    'that do not fit this part of the image.'));
  const ids = per.map((p) => p.id);
  const bars = plot(s, [
    {type: 'bar', x: ids, y: per.map((p) => p.points_px.length), name: 'corners',
     marker: {color: COLORS.used}, hovertemplate: 'image %{x}<br>%{y} corners<extra>click to show</extra>'},
    {type: 'bar', x: ids, y: per.map((p) => p.rms_px), name: 'RMS (px)', xaxis: 'x2', yaxis: 'y2',
     marker: {color: COLORS.Z}, hovertemplate: 'image %{x}<br>RMS %{y:.3g} px<extra>click to show</extra>'},
  ], {title: {text: 'Per image: corners detected and reprojection RMS (click a bar to show the image)'},
      height: 460, grid: {rows: 2, columns: 1, pattern: 'independent'}, showlegend: false,
      xaxis: {type: 'category', showticklabels: false}, yaxis: {title: {text: 'corners'}},
      xaxis2: {type: 'category', title: {text: 'image (station id)'}}, yaxis2: {title: {text: 'RMS (px)'}}});
  if (data.skipped.length) {
    s.appendChild(table(['skipped image', 'why'], data.skipped.map((p) => [p.id, p.reason])));
  }
  hecalPage.imageFigures(s, per, k.width, k.height, data.thumbnails, [bars]);

  // ---- the cameras around the target -------------------------------------------------------
  const [x0, y0, x1, y1] = data.target_extent;
  const cameras = per.map((p) => invert(p.T_camera_target));  // T_target_camera
  const reach = Math.max(...cameras.map((T) => Math.hypot(T[0][3], T[1][3], T[2][3])),
                         Math.hypot(x1 - x0, y1 - y0), 1e-9);
  const size = 0.08 * reach;
  const I = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
  const traces = axisTraces([triad(I, 2 * size)].concat(cameras.map((T) => triad(T, size))));
  traces.push(polyTrace('cameras', '#555', cameras.map((T) => frustum(T, size)).flat(), 3));
  traces.push(polyTrace('target', '#8e44ad', board(I, x0, y0, x1, y1), 4));
  traces.push({type: 'scatter3d', mode: 'markers', name: 'camera centres',
               x: cameras.map((T) => T[0][3]), y: cameras.map((T) => T[1][3]),
               z: cameras.map((T) => T[2][3]),
               text: per.map((p) => `image ${p.id}: ${fmt(Math.hypot(...p.T_camera_target.slice(0, 3)
                 .map((row) => row[3])), 3)} m from the target origin`), hoverinfo: 'text',
               marker: {size: 4, color: COLORS.used}});
  const scene = section('Camera poses', el('p', {class: 'muted'},
    'Every used image\'s camera in the target frame (metres; T_target_camera, the inverse of ' +
    'the detected T_camera_target); drag to rotate. Axes x red, y green, z blue; the target\'s ' +
    'points span the purple rectangle. Views from many directions and distances constrain the ' +
    'intrinsics and the hand–eye rotation best.'));
  plot(scene, traces, {height: 560, scene: {aspectmode: 'data', xaxis: {title: {text: 'x'}},
                                            yaxis: {title: {text: 'y'}}, zaxis: {title: {text: 'z'}}},
                       margin: {l: 0, r: 0, t: 10, b: 0}});
};
