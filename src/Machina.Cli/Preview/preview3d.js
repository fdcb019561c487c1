// Machina preview: an interactive 3D view of a tool path, drawn on a canvas with no library and no network.
// Drag to turn, Shift+drag (or right-drag) to pan, wheel to zoom, buttons for the standard views.
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('machina-path').textContent);
  var canvas = document.getElementById('view');
  var ctx = canvas.getContext('2d');
  var tip = document.getElementById('tip');
  var deg = Math.PI / 180;
  var colours = data.colours;
  var all = [];
  data.segments.forEach(function (s) { s.points.forEach(function (p) { all.push(p); }); });
  data.targets.forEach(function (p) { all.push(p); });
  (data.arms || []).forEach(function (a) { a.points.forEach(function (p) { all.push(p); }); });
  if (all.length === 0) { all.push([0, 0, 0]); }
  var min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  all.forEach(function (p) { for (var i = 0; i < 3; i++) { min[i] = Math.min(min[i], p[i]); max[i] = Math.max(max[i], p[i]); } });
  var centre = [(min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2];
  var extent = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2], 1);
  // fit: pixels per mm that frame the whole drawing in this view; offU, offV: the middle of its picture (mm, from centre).
  var cam = { yaw: -35 * deg, pitch: 30 * deg, zoom: 1, panX: 0, panY: 0, fit: 1, offU: 0, offV: 0 };
  // Room kept around the drawing for the labels next to its markers (px).
  var margin = 48;
  var picks = [];

  function niceStep(rough) {
    var power = Math.pow(10, Math.floor(Math.log10(Math.max(rough, 1e-6))));
    var steps = [1, 2, 5, 10];
    for (var i = 0; i < steps.length; i++) { if (steps[i] * power >= rough) { return steps[i] * power; } }
    return 10 * power;
  }

  function size() {
    var box = canvas.parentElement.getBoundingClientRect();
    var ratio = window.devicePixelRatio || 1;
    canvas.width = Math.max(100, Math.floor(box.width * ratio));
    canvas.height = Math.max(100, Math.floor(box.height * ratio));
    canvas.style.width = box.width + 'px';
    canvas.style.height = box.height + 'px';
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    fit();
    draw();
  }

  function scale() { return cam.fit * cam.zoom; }

  // Orthographic camera: turn by yaw about Z, then tilt by pitch (90° looks straight down). In mm from the centre: [right, up].
  function turn(p) {
    var x = p[0] - centre[0], y = p[1] - centre[1], z = p[2] - centre[2];
    var cy = Math.cos(cam.yaw), sy = Math.sin(cam.yaw), cp = Math.cos(cam.pitch), sp = Math.sin(cam.pitch);
    var x1 = x * cy - y * sy, y1 = x * sy + y * cy;
    return [x1, z * cp + y1 * sp];
  }

  function project(p) {
    var w = canvas.width / (window.devicePixelRatio || 1), h = canvas.height / (window.devicePixelRatio || 1);
    var t = turn(p), s = scale();
    return [w / 2 + cam.panX + (t[0] - cam.offU) * s, h / 2 + cam.panY - (t[1] - cam.offV) * s];
  }

  // Frames the whole drawing (path, targets, arms) as this view sees it, with room for the labels, in the middle of the canvas.
  function fit() {
    var w = canvas.width / (window.devicePixelRatio || 1), h = canvas.height / (window.devicePixelRatio || 1);
    var lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    all.forEach(function (p) { var t = turn(p); for (var i = 0; i < 2; i++) { lo[i] = Math.min(lo[i], t[i]); hi[i] = Math.max(hi[i], t[i]); } });
    var du = Math.max(hi[0] - lo[0], extent / 100), dv = Math.max(hi[1] - lo[1], extent / 100);
    cam.fit = Math.max(1e-6, Math.min(Math.max(w - 2 * margin, 20) / du, Math.max(h - 2 * margin, 20) / dv));
    cam.offU = (lo[0] + hi[0]) / 2; cam.offV = (lo[1] + hi[1]) / 2;
  }

  // Where the drawing's points landed on the canvas in the last draw (px): data-drawn="left top right bottom".
  function recordDrawn() {
    var lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    all.forEach(function (p) { var s = project(p); for (var i = 0; i < 2; i++) { lo[i] = Math.min(lo[i], s[i]); hi[i] = Math.max(hi[i], s[i]); } });
    canvas.setAttribute('data-drawn', [lo[0], lo[1], hi[0], hi[1]].map(function (v) { return Math.round(v * 10) / 10; }).join(' '));
  }

  function line(points, colour, width, dash) {
    if (points.length < 2) { return; }
    ctx.beginPath();
    var a = project(points[0]);
    ctx.moveTo(a[0], a[1]);
    for (var i = 1; i < points.length; i++) { var b = project(points[i]); ctx.lineTo(b[0], b[1]); }
    ctx.strokeStyle = colour; ctx.lineWidth = width; ctx.setLineDash(dash || []);
    ctx.stroke();
    ctx.setLineDash([]);
  }

  function floorGrid() {
    var step = niceStep(extent / 8);
    var z = min[2];
    var x0 = Math.floor((min[0] - extent * 0.1) / step) * step, x1 = Math.ceil((max[0] + extent * 0.1) / step) * step;
    var y0 = Math.floor((min[1] - extent * 0.1) / step) * step, y1 = Math.ceil((max[1] + extent * 0.1) / step) * step;
    for (var x = x0; x <= x1 + 1e-9; x += step) { line([[x, y0, z], [x, y1, z]], Math.abs(x) < step / 1000 ? '#b8bec8' : '#e3e6eb', 1); }
    for (var y = y0; y <= y1 + 1e-9; y += step) { line([[x0, y, z], [x1, y, z]], Math.abs(y) < step / 1000 ? '#b8bec8' : '#e3e6eb', 1); }
    document.getElementById('grid').textContent = 'Floor grid: ' + step + ' mm squares at Z = ' + Math.round(z * 100) / 100 + ' mm';
  }

  function gizmo() {
    var h = canvas.height / (window.devicePixelRatio || 1);
    var ox = 48, oy = h - 48, len = 30;
    var cy = Math.cos(cam.yaw), sy = Math.sin(cam.yaw), cp = Math.cos(cam.pitch), sp = Math.sin(cam.pitch);
    [[1, 0, 0, '#e53935', 'X'], [0, 1, 0, '#43a047', 'Y'], [0, 0, 1, '#1e88e5', 'Z']].forEach(function (a) {
      var x1 = a[0] * cy - a[1] * sy, y1 = a[0] * sy + a[1] * cy, up = a[2] * cp + y1 * sp;
      ctx.beginPath(); ctx.moveTo(ox, oy); ctx.lineTo(ox + x1 * len, oy - up * len);
      ctx.strokeStyle = a[3]; ctx.lineWidth = 2.5; ctx.stroke();
      ctx.fillStyle = a[3]; ctx.font = 'bold 12px sans-serif';
      ctx.fillText(a[4], ox + x1 * (len + 9) - 4, oy - up * (len + 9) + 4);
    });
  }

  function marker(s, kind) {
    if (kind === 'base') { ctx.fillStyle = '#5f6b7a'; ctx.fillRect(s[0] - 9, s[1] - 4, 18, 8); return; }
    ctx.beginPath();
    if (kind === 'end') { ctx.rect(s[0] - 6, s[1] - 6, 12, 12); } else { ctx.arc(s[0], s[1], kind === 'warning' ? 8 : 7, 0, 2 * Math.PI); }
    if (kind === 'warning') { ctx.strokeStyle = colours.warning; ctx.lineWidth = 2.5; ctx.stroke(); }
    else { ctx.fillStyle = colours[kind]; ctx.fill(); ctx.strokeStyle = '#fff'; ctx.lineWidth = 2; ctx.stroke(); }
  }

  // Labels apart: each tries its own corner of its marker first (the start below right, the end above right, a warning
  // above left, the base below), then the other corners, then further along its side, and keeps the first place free of
  // the labels placed before it, of the markers and of the axes in the corner. taken: boxes [left, top, right, bottom] in px.
  function label(s, kind, text, taken) {
    var size = kind === 'base' ? 11 : 12;
    ctx.font = (kind === 'base' ? '' : 'bold ') + size + 'px sans-serif';
    var w = ctx.measureText(text).width + 2;
    var corners = {
      b: function (k) { return [s[0], s[1] + 18 + k, 'center']; },
      ar: function (k) { return [s[0] + 10, s[1] - 9 - k, 'left']; },
      br: function (k) { return [s[0] + 10, s[1] + 17 + k, 'left']; },
      al: function (k) { return [s[0] - 10, s[1] - 9 - k, 'right']; },
      bl: function (k) { return [s[0] - 10, s[1] + 17 + k, 'right']; }
    };
    var order = kind === 'end' ? ['ar', 'br', 'al', 'bl'] : kind === 'start' ? ['br', 'ar', 'bl', 'al']
      : kind === 'base' ? ['b', 'br', 'bl', 'ar', 'al'] : ['al', 'bl', 'ar', 'br'];
    var first = null, chosen = null;
    for (var step = 0; step <= 8 && !chosen; step++) {
      for (var i = 0; i < order.length && !chosen; i++) {
        var p = corners[order[i]](step * (1.5 * size + 1));
        var left = p[2] === 'left' ? p[0] : p[2] === 'center' ? p[0] - w / 2 : p[0] - w;
        var box = [left, p[1] - 1.1 * size, left + w, p[1] + 0.35 * size];
        first = first || { p: p, box: box };
        var free = taken.every(function (t) { return !(box[0] < t[2] && t[0] < box[2] && box[1] < t[3] && t[1] < box[3]); });
        if (free) { chosen = { p: p, box: box }; }
      }
    }
    chosen = chosen || first;
    taken.push(chosen.box);
    ctx.fillStyle = kind === 'warning' ? colours.warning : kind === 'base' ? '#5f6b7a' : colours[kind];
    ctx.textAlign = chosen.p[2];
    ctx.fillText(text, chosen.p[0], chosen.p[1]);
    ctx.textAlign = 'left';
    return chosen.box;
  }

  function draw() {
    var w = canvas.width / (window.devicePixelRatio || 1), h = canvas.height / (window.devicePixelRatio || 1);
    ctx.clearRect(0, 0, w, h);
    ctx.fillStyle = '#ffffff'; ctx.fillRect(0, 0, w, h);
    floorGrid();
    picks = [];
    (data.reach || []).forEach(function (r) { line(r.points, colours.reach, 1.2, [9, 4, 2, 4]); });
    (data.arms || []).forEach(function (a) {
      var colour = colours[a.label === 'start' || a.label === 'end' ? 'arm-' + a.label : 'arm-warning'];
      line(a.points, colour, 7, null);
      a.points.forEach(function (p) { var s = project(p); ctx.beginPath(); ctx.arc(s[0], s[1], 3, 0, 2 * Math.PI); ctx.fillStyle = '#fff'; ctx.fill(); ctx.strokeStyle = '#6b7684'; ctx.lineWidth = 1.2; ctx.stroke(); });
    });
    data.segments.forEach(function (s) {
      line(s.points, colours[s.kind], s.kind === 'travel' ? 1.5 : 2.4, s.kind === 'joint' ? [7, 5] : s.kind === 'travel' ? [2, 5] : null);
    });
    data.targets.forEach(function (p, i) {
      var s = project(p);
      ctx.beginPath(); ctx.arc(s[0], s[1], 2.6, 0, 2 * Math.PI);
      ctx.fillStyle = '#fff'; ctx.fill(); ctx.strokeStyle = '#5f6b7a'; ctx.lineWidth = 1; ctx.stroke();
      picks.push({ s: s, text: 'target ' + (i + 1) + ': [' + p.map(function (v) { return Math.round(v * 100) / 100; }).join(', ') + '] mm' });
    });
    var marks = [];
    if (data.start) { marks.push({ s: project(data.start), kind: 'start', text: 'start' }); }
    if (data.end) { marks.push({ s: project(data.end), kind: 'end', text: 'end' }); }
    data.warnings.forEach(function (wn) {
      if (wn.at) {
        marks.push({ s: project(wn.at), kind: 'warning', text: '!' + wn.line });
        picks.push({ s: project(wn.at), text: 'line ' + wn.line + ': ' + wn.instruction + ' ' + wn.message });
      }
    });
    if ((data.arms || []).length > 0) { marks.push({ s: project([0, 0, 0]), kind: 'base', text: 'base' }); }
    var taken = marks.map(function (m) { return m.kind === 'base' ? [m.s[0] - 9, m.s[1] - 4, m.s[0] + 9, m.s[1] + 4] : [m.s[0] - 8, m.s[1] - 8, m.s[0] + 8, m.s[1] + 8]; });
    taken.push([0, h - 96, 100, h]); // the axes, bottom left
    marks.forEach(function (m) { marker(m.s, m.kind); });
    var labels = marks.map(function (m) { return [m.text].concat(label(m.s, m.kind, m.text, taken).map(function (v) { return Math.round(v * 10) / 10; })); });
    canvas.setAttribute('data-labels', JSON.stringify(labels));
    gizmo();
    recordDrawn();
  }

  function setView(yaw, pitch) { cam.yaw = yaw * deg; cam.pitch = pitch * deg; cam.zoom = 1; cam.panX = 0; cam.panY = 0; fit(); draw(); }
  document.getElementById('v-3d').onclick = function () { setView(-35, 30); };
  document.getElementById('v-top').onclick = function () { setView(0, 90); };
  document.getElementById('v-front').onclick = function () { setView(0, 0); };
  document.getElementById('v-side').onclick = function () { setView(-90, 0); };

  var drag = null;
  canvas.addEventListener('contextmenu', function (e) { e.preventDefault(); });
  canvas.addEventListener('mousedown', function (e) { drag = { x: e.clientX, y: e.clientY, pan: e.shiftKey || e.button === 2 }; });
  window.addEventListener('mouseup', function () { drag = null; });
  window.addEventListener('mousemove', function (e) {
    if (drag) {
      var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
      drag.x = e.clientX; drag.y = e.clientY;
      if (drag.pan) { cam.panX += dx; cam.panY += dy; }
      else { cam.yaw += dx * 0.01; cam.pitch = Math.max(-90 * deg, Math.min(90 * deg, cam.pitch + dy * 0.01)); }
      draw();
      return;
    }
    var box = canvas.getBoundingClientRect();
    var mx = e.clientX - box.left, my = e.clientY - box.top, best = null, bestD = 64;
    picks.forEach(function (p) { var d = (p.s[0] - mx) * (p.s[0] - mx) + (p.s[1] - my) * (p.s[1] - my); if (d < bestD) { bestD = d; best = p; } });
    if (best) { tip.textContent = best.text; tip.style.left = (mx + 14) + 'px'; tip.style.top = (my + 10) + 'px'; tip.style.display = 'block'; }
    else { tip.style.display = 'none'; }
  });
  canvas.addEventListener('wheel', function (e) {
    e.preventDefault();
    cam.zoom = Math.max(0.05, Math.min(200, cam.zoom * Math.exp(-e.deltaY * 0.0015)));
    draw();
  }, { passive: false });
  window.addEventListener('resize', size);
  size();
})();
