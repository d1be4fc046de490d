// The page of `koppel edit`: the mechanism the CLI handed over (koppel/api/editor.hpp) solved by
// koppel's own kernel in WebAssembly. Every edit (a parameter, a dragged point) makes a new
// mechanism; the module checks, admits and sweeps it. When it cannot (not assemblable, not
// admitted, no pose at the current input) the page says so and keeps the last valid state: it
// never shows numbers of a mechanism that was not solved.
(function () {
  'use strict';
  const doc = JSON.parse(document.getElementById('koppel-document').textContent);
  const $ = (id) => document.getElementById(id);
  const svg = $('scheme'), slider = $('input-slider'), message = $('message');
  const SVGNS = 'http://www.w3.org/2000/svg';
  const kWidth = 560, kHeight = 440;
  // math.js with plain numbers; `predictable`: sqrt(-1) is NaN, never a complex number
  const mathjs = math.create(math.all, { number: 'number', predictable: true });
  // muparser's names that math.js spells otherwise (koppel/core/expression.hpp)
  const kBuiltins = { pi: Math.PI, deg: Math.PI / 180, ln: Math.log };

  let module = null;
  let state = null;      // {mechanism, parameters, formulas}: the last state that solved
  let pending = null;    // the file's state when it did not solve: the sliders start from it
  let solved = null;     // its sweep: {table, frames, deadCentres}
  let undo = [];
  let frame = 0, playing = false, last = null, carry = 0;
  let view = null;       // the scheme's scale and origin, fixed until the mechanism is loaded anew
  let atBranchPoint = '';
  let formulasTrusted = true;

  function say(text, error) {
    message.textContent = text || '';
    message.className = error ? 'error' : '';
  }
  function call(name, types, args) {
    const answer = JSON.parse(module.ccall(name, 'string', types, args));
    return answer;
  }
  const clone = (o) => JSON.parse(JSON.stringify(o));

  // ---- formulas: the file's parameters in file order, then every formula of the model part
  function evaluate(formula, scope) {
    const v = mathjs.evaluate(String(formula), Object.assign({}, kBuiltins, scope));
    if (typeof v !== 'number' || !isFinite(v)) throw new Error("formula '" + formula + "' does not give a finite number");
    return v;
  }
  function setAt(object, pointer, value) {
    const keys = pointer.split('/').slice(1);
    let o = object;
    for (let i = 0; i + 1 < keys.length; ++i) o = o[keys[i]];
    o[keys[keys.length - 1]] = value;
  }
  function evaluated(s, name, value) {
    const scope = {};
    const parameters = s.parameters.map((p) => Object.assign({}, p));
    for (const p of parameters) {
      if (p.name === name) p.formula = String(value);
      p.value = p.name === name ? value : evaluate(p.formula, scope);
      scope[p.name] = p.value;
    }
    const mechanism = clone(s.mechanism);
    for (const f of s.formulas) setAt(mechanism, f.target, evaluate(f.formula, scope) * f.scale);
    mechanism.parameters = parameters.map((p) => [p.name, p.value]);
    return { mechanism: mechanism, parameters: parameters, formulas: s.formulas };
  }
  // The page's evaluation against muparser's values for the file as read: where they differ the
  // sliders are off (a formula math.js reads otherwise would give other numbers than the CLI).
  function checkFormulas() {
    const scope = {};
    try {
      for (const p of doc.parameters) {
        const v = evaluate(p.formula, scope);
        if (Math.abs(v - p.value) > 1e-12 * Math.max(1, Math.abs(p.value))) throw new Error("parameter '" + p.name + "': " + v + ' here, ' + p.value + ' in koppel');
        scope[p.name] = p.value;
      }
      for (const f of doc.formulas) {
        const v = evaluate(f.formula, scope);
        if (f.value === null || Math.abs(v - f.value) > 1e-12 * Math.max(1, Math.abs(f.value))) throw new Error(f.path + ': ' + v + ' here, ' + f.value + ' in koppel');
      }
      return '';
    } catch (e) {
      return String(e.message || e);
    }
  }

  // ---- solving: load, sweep the file's range, take the points along the same walk
  function solve(s) {
    const loaded = call('koppel_load', ['string'], [JSON.stringify(s.mechanism)]);
    if (!loaded.ok) return { error: loaded.message };
    const sw = s.mechanism.sweep;
    const table = call('koppel_sweep', ['number', 'number', 'number', 'number', 'string'], [sw.from, sw.to, sw.step, 2, atBranchPoint]);
    if (!table.ok) return { error: table.message };
    const frames = call('koppel_points', ['number', 'number', 'number', 'string'], [sw.from, sw.to, sw.step, atBranchPoint]);
    if (!frames.ok) return { error: frames.message };
    if (table.rows.length === 0) return { error: 'not assemblable: ' + (table.message || table.status) };
    if (frames.inputs.length !== table.rows.length || frames.inputs.some((x, i) => x !== table.rows[i][0]))
      return { error: 'the drawing and the table did not walk the same samples' };
    const dead = doc.mechanism.outputs.length ? call('koppel_dead_centres', ['number', 'number'], [Math.min(sw.from, sw.to), Math.max(sw.from, sw.to)]) : { ok: false };
    return { table: table, frames: frames, deadCentres: dead.ok ? dead : null, notes: loaded.notes };
  }
  // Makes `next` current when it solves with a pose at the current input, assembled there from
  // the hint (or anywhere, `anywhere`: the file as read); otherwise says why and keeps the last
  // valid state. A change the page cannot follow on the branch shown (no pose at the current
  // input next to the pose shown: koppel assembled elsewhere, and its notes say where and how) is
  // not taken silently: the page keeps the pose shown, says so in koppel's words and offers
  // koppel's assembly (the button "Take koppel's assembly"). True when it was taken.
  let offer = null;
  function adopt(next, what, anywhere, record) {
    const input = solved ? solved.table.rows[frame][0] : null;
    const result = solve(next);
    let why = result.error;
    let index = 0;
    offer = null;
    $('take-offer').hidden = true;
    if (!why && input !== null && !anywhere) {
      index = result.table.rows.findIndex((r) => r[0] === input);
      const elsewhere = (result.table.notes || []).join('; ');
      if (index < 0 || elsewhere) {
        if (state) call('koppel_load', ['string'], [JSON.stringify(state.mechanism)]);  // the module back to the pose shown
        offer = { next: next, what: what };
        $('take-offer').hidden = false;
        say((what || 'the change') + ': cannot keep the branch shown at ' + doc.input.name + ' = ' + input + ' (' +
            (elsewhere || 'no pose there on the branch koppel assembled') + '); the page keeps the pose shown: "Take koppel\'s assembly" shows the other', true);
        if (state || pending) drawParameters();
        return false;
      }
    }
    if (why) {
      if (state) call('koppel_load', ['string'], [JSON.stringify(state.mechanism)]);  // the module back to the last valid model
      say((what || 'the file as read') + ': cannot assemble (' + why + ')' + (state ? '; the page keeps the last valid pose' : ''), true);
      if (state || pending) drawParameters();  // the sliders back to the values that solved
      return false;
    }
    if (state && record !== false) undo.push(state);
    $('undo').disabled = undo.length === 0;
    state = next;
    solved = result;
    frame = Math.max(0, index);
    const t = result.table;
    // the library's notes say where the assembly was not where it was asked for (the CLI's words)
    const notes = (t.notes || []).join('; ');
    const said = t.complete ? (what ? what + ': solved' : '') : (what ? what + ': ' : '') + 'partial: ' + t.message;
    say([said, notes].filter((x) => x).join('; '), !t.complete);
    redraw();
    return true;
  }
  $('take-offer').addEventListener('click', () => { if (offer) adopt(offer.next, offer.what + ", koppel's assembly", true); });

  // ---- the scheme
  function pointsAt(i) {
    const out = [], p = solved.frames.points, links = state.mechanism.links;
    let k = i * solved.frames.points.length / solved.frames.inputs.length;
    for (const l of links) out.push(l.points.map(() => { const xy = [p[k], p[k + 1]]; k += 2; return xy; }));
    return out;
  }
  function fitView() {
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (let i = 0; i < solved.frames.inputs.length; ++i)
      for (const l of pointsAt(i)) for (const [x, y] of l) { lo = [Math.min(lo[0], x), Math.min(lo[1], y)]; hi = [Math.max(hi[0], x), Math.max(hi[1], y)]; }
    const scale = 0.8 * Math.min(kWidth / Math.max(hi[0] - lo[0], 1e-9), kHeight / Math.max(hi[1] - lo[1], 1e-9));
    view = { scale: scale, ox: kWidth / 2 - scale * (lo[0] + hi[0]) / 2, oy: kHeight / 2 + scale * (lo[1] + hi[1]) / 2 };
  }
  const px = ([x, y]) => [view.ox + view.scale * x, view.oy - view.scale * y];
  const unpx = (X, Y) => [(X - view.ox) / view.scale, (view.oy - Y) / view.scale];
  function el(name, attrs, parent) {
    const e = document.createElementNS(SVGNS, name);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    (parent || svg).appendChild(e);
    return e;
  }
  const palette = ['#1f5fa8', '#c0392b', '#2e8b57', '#7d3c98', '#b9770e', '#117a65'];
  function drawScheme() {
    svg.textContent = '';
    const m = state.mechanism, pts = pointsAt(frame);
    // coupler curves of the point outputs: the traced point over every sample
    for (const o of m.outputs.filter((o) => o.kind === 'point')) {
      const d = solved.frames.inputs.map((_, i) => px(pointsAt(i)[o.p[0]][o.p[1]]).map((v) => v.toFixed(1)).join(',')).join(' L');
      el('path', { d: 'M' + d, fill: 'none', stroke: '#7d3c98', 'stroke-width': 1.2, 'stroke-dasharray': '4 2', class: 'coupler-curve' });
    }
    m.links.forEach((l, li) => {
      const g = el('g', { class: 'link', 'data-link': l.name });
      const xy = pts[li].map(px);
      if (l.frame) return;
      const colour = palette[li % palette.length];
      if (xy.length >= 3) el('polygon', { points: xy.map((p) => p.join(',')).join(' '), fill: colour, 'fill-opacity': 0.15, stroke: colour, 'stroke-width': 3 }, g);
      else if (xy.length === 2) el('line', { x1: xy[0][0], y1: xy[0][1], x2: xy[1][0], y2: xy[1][1], stroke: colour, 'stroke-width': 4, 'stroke-linecap': 'round' }, g);
    });
    // guides, blocks and pivots first, every joint's handle and name last: a handle under a
    // slider block or on a guide line is still the pointer's to grab
    m.joints.forEach((j) => {
      const a = px(pts[j.link_a][j.point_a]), b = px(pts[j.link_b][j.point_b]);
      const frameJoint = m.links[j.link_a].frame || m.links[j.link_b].frame;
      if (j.type === 'P') {
        // the guide's line through its point along the axis, the block on it
        const dir = guideDirection(j, pts);
        const L = 2000;
        el('line', { x1: a[0] - L * dir[0], y1: a[1] + L * dir[1], x2: a[0] + L * dir[0], y2: a[1] - L * dir[1], stroke: '#555', 'stroke-width': 1, class: 'guide' });
        const angle = -Math.atan2(dir[1], dir[0]) * 180 / Math.PI;
        el('rect', { x: -14, y: -8, width: 28, height: 16, fill: '#fff', stroke: '#1d2b3a', 'stroke-width': 2, transform: 'translate(' + b[0] + ',' + b[1] + ') rotate(' + angle + ')', class: 'block' });
      } else if (frameJoint) {
        el('path', { d: 'M' + a[0] + ',' + a[1] + ' l-10,16 h20 z', fill: '#d5dbe1', stroke: '#1d2b3a', 'stroke-width': 1.5, class: 'pivot' });
      }
    });
    m.joints.forEach((j, ji) => {
      if (j.type !== 'R') return;
      const a = px(pts[j.link_a][j.point_a]);
      const c = el('circle', { cx: a[0], cy: a[1], r: 6, fill: '#fff', stroke: '#1d2b3a', 'stroke-width': 2, class: 'handle joint', 'data-joint': j.name });
      c.addEventListener('pointerdown', (e) => startDrag(e, ji));
      el('text', { x: a[0] + 9, y: a[1] - 9, 'font-size': 12, fill: '#1d2b3a', 'pointer-events': 'none' }).textContent = j.name;
    });
  }
  function linkAngle(li, pts) {
    // a link's rotation: from its body frame's points (two points not coinciding) to their global positions
    const l = state.mechanism.links[li];
    if (l.frame || l.points.length < 2) return 0;
    for (let k = 1; k < l.points.length; ++k) {
      const dl = [l.points[k].x - l.points[0].x, l.points[k].y - l.points[0].y];
      const dg = [pts[li][k][0] - pts[li][0][0], pts[li][k][1] - pts[li][0][1]];
      if (Math.hypot(dl[0], dl[1]) > 1e-12) return Math.atan2(dg[1], dg[0]) - Math.atan2(dl[1], dl[0]);
    }
    return 0;
  }
  function guideDirection(j, pts) {
    const t = linkAngle(j.link_a, pts), n = Math.hypot(j.axis[0], j.axis[1]);
    const ax = j.axis[0] / n, ay = j.axis[1] / n;
    return [Math.cos(t) * ax - Math.sin(t) * ay, Math.sin(t) * ax + Math.cos(t) * ay];
  }

  // ---- dragging an R joint (moveJoint below), solved from the current pose (the hint), so that
  // it stays on its branch
  let drag = null;
  function startDrag(e, ji) {
    e.preventDefault();
    drag = { joint: ji, before: state, scheduled: false, moved: false };
    svg.setPointerCapture(e.pointerId);
  }
  // the mechanism follows the pointer, solved once per animation frame (a sweep of the file's
  // range is a few milliseconds); the whole drag is one step of undo
  function dragTo() {
    drag.scheduled = false;
    if (drag.to && moveJoint(state.mechanism.joints[drag.joint].name, drag.to[0], drag.to[1], false)) drag.moved = true;
  }
  svg.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const r = svg.getBoundingClientRect();
    drag.to = unpx(e.clientX - r.left, e.clientY - r.top);
    if (!drag.scheduled) {
      drag.scheduled = true;
      requestAnimationFrame(() => { if (drag) dragTo(); });
    }
  });
  svg.addEventListener('pointerup', () => {
    if (!drag) return;
    if (drag.to) dragTo();
    if (drag.moved) {
      undo.push(drag.before);
      $('undo').disabled = false;
    }
    drag = null;
  });
  // The pose at the current frame as the assembly hint: the solver assembles next to it, so
  // every loop stays on its branch through a change (a parameter, a dragged joint). Where it
  // cannot assemble there, koppel searches a turn and says so (the notes, as the CLI words them).
  function hintFromPose(m, pts) {
    m.hint.input = (doc.input.angle ? Math.PI / 180 : 1) * solved.table.rows[frame][0];
    m.hint.points = [];
    m.links.forEach((l, li) => { if (!l.frame) l.points.forEach((p, pi) => m.hint.points.push({ link: li, point: pi, x: pts[li][pi][0], y: pts[li][pi][1] })); });
  }
  const kParameterName = /^\s*[A-Za-z_][A-Za-z0-9_]*\s*$/;
  // A dragged revolute joint: a frame pivot moves in the frame only (the link on it keeps its
  // lengths); any other joint's point moves on both its links. A coordinate the file writes as a
  // plain parameter (B0: [d1, 0]) changes that parameter; one written as another formula becomes
  // a number, and the page says which.
  function moveJoint(name, x, y, record) {
    const m = clone(state.mechanism), pts = pointsAt(frame);
    const ji = m.joints.findIndex((j) => j.name === name);
    if (ji < 0 || m.joints[ji].type !== 'R') throw new Error("no R joint '" + name + "'");
    const j = m.joints[ji];
    const onFrame = m.links[j.link_a].frame ? [[j.link_a, j.point_a]] : m.links[j.link_b].frame ? [[j.link_b, j.point_b]] : null;
    const moved = onFrame || [[j.link_a, j.point_a], [j.link_b, j.point_b]];
    let formulas = state.formulas;
    const parameters = [], numbers = [];
    for (const [li, pi] of moved) {
      const t = linkAngle(li, pts), o = pts[li][0], l0 = m.links[li].points[0];
      // global -> the link's body frame at the current pose
      const gx = x - o[0], gy = y - o[1];
      const local = { x: Math.cos(t) * gx + Math.sin(t) * gy + l0.x, y: -Math.sin(t) * gx + Math.cos(t) * gy + l0.y };
      for (const c of ['x', 'y']) {
        m.links[li].points[pi][c] = local[c];
        const target = '/links/' + li + '/points/' + pi + '/' + c;
        const f = formulas.find((g) => g.target === target);
        if (!f) continue;
        const parameter = kParameterName.test(f.formula) && f.scale === 1 && state.parameters.find((p) => p.name === f.formula.trim());
        if (parameter) {
          parameters.push([parameter.name, local[c]]);
        } else {
          numbers.push(m.links[li].name + '.' + m.links[li].points[pi].name + ' ' + c + " was '" + f.formula + "'");
          formulas = formulas.filter((g) => g !== f);  // a number now, no longer a formula
        }
      }
    }
    let next = { mechanism: m, parameters: state.parameters, formulas: formulas.filter((f) => !f.target.startsWith('/hint/')) };
    try {
      for (const [p, v] of parameters) next = evaluated(next, p, v);
    } catch (e) {
      say('moving ' + name + ': ' + e.message, true);
      return false;
    }
    hintFromPose(next.mechanism, pts);
    for (const h of next.mechanism.hint.points) if ((h.link === j.link_a && h.point === j.point_a) || (h.link === j.link_b && h.point === j.point_b)) { h.x = x; h.y = y; }
    const what = 'moved ' + name + (parameters.length ? ' (' + parameters.map(([p, v]) => p + ' = ' + +v.toPrecision(12)).join(', ') + ')' : '') +
      (numbers.length ? '; now numbers: ' + numbers.join(', ') : '');
    return adopt(next, what, false, record);
  }

  // ---- charts: every scalar output with its 1st and 2nd order transfer functions; the
  // transmission angle alone; dead centres and singular points marked, gaps shaded
  const plots = $('plots');
  let charts = [];
  function drawCharts() {
    plots.textContent = '';
    charts = [];
    const key = document.createElement('div');
    key.className = 'chart-title';
    key.textContent = 'dashed lines: dead centres (green), limit points (red), branch points (purple); shaded: beyond the branch';
    plots.appendChild(key);
    const t = solved.table, xs = t.rows.map((r) => r[0]);
    const marks = [];
    for (const s of t.singular_points) marks.push({ x: s.input, colour: s.kind === 'limit' ? '#c0392b' : '#7d3c98', label: s.kind });
    if (solved.deadCentres) for (const p of solved.deadCentres.points) marks.push({ x: p.input, colour: '#2e8b57', label: 'dead centre (' + p.kind + ')' });
    for (const o of state.mechanism.outputs) {
      if (o.kind === 'point') continue;
      const names = o.kind === 'transmission' ? [o.name] : [o.name, o.name + '_d1', o.name + '_d2'];
      const columns = [xs];
      const series = [{ label: doc.input.name + ' [' + doc.input.unit + ']' }];
      names.forEach((n, k) => {
        const c = t.columns.indexOf(n);
        columns.push(t.rows.map((r) => r[c]));
        series.push({ label: n + ' [' + t.units[c] + ']', stroke: palette[k], width: 1.6, scale: k === 0 ? 'y' : 'd' });
      });
      const title = document.createElement('div');
      title.className = 'chart-title';
      title.textContent = o.kind === 'transmission' ? o.name + ': transmission angle' : o.name + ' and its transfer functions';
      plots.appendChild(title);
      const box = document.createElement('div');
      box.className = 'chart';
      plots.appendChild(box);
      const axes = [{ label: series[0].label }, { scale: 'y', label: series[1].label }];
      if (names.length > 1) axes.push({ scale: 'd', side: 1, grid: { show: false }, label: 'derivatives' });
      const u = new uPlot({
        // the plot area about 260 px tall (at least 240)
        width: 560, height: 360, series: series, axes: axes, scales: { x: { time: false } }, cursor: { drag: { x: false, y: false } },
        hooks: { draw: [(u) => {
          const ctx = u.ctx, top = u.bbox.top, h = u.bbox.height;
          ctx.save();
          for (const g of t.gaps) {  // the parts of the range the branch cannot be driven through
            const a = u.valToPos(Math.min(g[0], g[1]), 'x', true), b = u.valToPos(Math.max(g[0], g[1]), 'x', true);
            ctx.fillStyle = 'rgba(192,57,43,0.12)';
            ctx.fillRect(a, top, Math.max(b - a, 2), h);
          }
          for (const mk of marks) {
            const x = u.valToPos(mk.x, 'x', true);
            ctx.strokeStyle = mk.colour; ctx.setLineDash([5, 3]); ctx.lineWidth = 1.5;
            ctx.beginPath(); ctx.moveTo(x, top); ctx.lineTo(x, top + h); ctx.stroke();
          }
          ctx.restore();
        }] },
      }, columns, box);
      const cursor = document.createElement('div');
      cursor.className = 'koppel-cursor';
      u.over.appendChild(cursor);
      charts.push({ u: u, cursor: cursor });
    }
  }

  function show(i) {
    frame = i;
    slider.value = String(i);
    const row = solved.table.rows[i];
    $('input-value').textContent = doc.input.name + ' = ' + Number(row[0].toPrecision(10)) + ' ' + doc.input.unit + (row[row.length - 1] ? ' (singular)' : '');
    drawScheme();
    for (const c of charts) {
      c.cursor.style.left = c.u.valToPos(row[0], 'x') + 'px';
      c.u.setLegend({ idx: i });
    }
    // a column's name is text, never markup (it comes from the mechanism file)
    const rows = [];
    solved.table.columns.forEach((c, k) => {
      if (k === 0 || k + 1 >= row.length) return;
      const tr = document.createElement('tr');
      for (const text of [c, row[k] === null ? '–' : String(Number(row[k]).toPrecision(8))]) tr.appendChild(document.createElement('td')).textContent = text;
      rows.push(tr);
    });
    $('readout').replaceChildren(...rows);
    // at a branch point the other branch is offered
    $('branch').hidden = !solved.table.singular_points.some((s) => s.kind === 'branch-point' && Math.abs(s.input - row[0]) <= Math.abs(state.mechanism.sweep.step));
  }
  function redraw() {
    if (!view) fitView();
    slider.max = String(solved.table.rows.length - 1);
    drawCharts();
    drawParameters();
    show(Math.min(frame, solved.table.rows.length - 1));
  }

  // ---- parameter sliders
  function drawParameters() {
    const table = $('parameters');
    table.textContent = '';
    for (const p of (state || pending).parameters) {
      const tr = document.createElement('tr');
      const span = Math.max(Math.abs(p.value), 1);
      // the parameter's name as text, never markup
      const range = document.createElement('input'), box = document.createElement('input');
      range.type = 'range'; box.type = 'number';
      tr.appendChild(document.createElement('td')).textContent = p.name;
      tr.appendChild(document.createElement('td')).appendChild(range);
      tr.appendChild(document.createElement('td')).appendChild(box);
      range.min = String(p.value - span); range.max = String(p.value + span); range.step = String(span / 200); range.value = String(p.value);
      box.value = String(p.value); box.step = 'any';
      const unread = doc.parameters.find((q) => q.name === p.name && q.unread);
      range.disabled = box.disabled = !formulasTrusted || !!unread;
      if (unread) tr.title = unread.unread;
      range.addEventListener('change', () => api.set(p.name, +range.value));
      // an emptied box is no number (+'' would be 0)
      box.addEventListener('change', () => api.set(p.name, box.value.trim() === '' ? NaN : +box.value));
      table.appendChild(tr);
    }
  }

  // ---- play and scrub
  function tick(now) {
    if (last === null) last = now;
    const dt = Math.min(0.1, (now - last) / 1000);
    last = now;
    const n = solved ? solved.table.rows.length : 0;
    if (playing && n > 1) {
      carry += dt * n / 6;  // the range in about six seconds
      const steps = Math.floor(carry);
      carry -= steps;
      if (steps) show((frame + steps) % n);
    }
    requestAnimationFrame(tick);
  }
  $('play').addEventListener('click', function () { playing = !playing; this.textContent = playing ? 'Pause' : 'Play'; });
  slider.addEventListener('input', () => show(+slider.value));
  $('undo').addEventListener('click', () => {
    const previous = undo.pop();
    if (!previous) return;
    const result = solve(previous);
    if (result.error) { say('undo: ' + result.error, true); return; }
    state = previous; solved = result;
    frame = Math.min(frame, result.table.rows.length - 1);
    $('undo').disabled = undo.length === 0;
    say('undone');
    redraw();
  });
  $('branch').addEventListener('click', () => {
    atBranchPoint = atBranchPoint === 'switch' ? '' : 'switch';
    const result = solve(state);
    if (result.error) { say('switching branch: ' + result.error, true); atBranchPoint = atBranchPoint ? '' : 'switch'; return; }
    solved = result;
    say(atBranchPoint ? 'switched branch at the branch points' : 'through the branch points on the same branch');
    redraw();
  });

  // ---- exports
  function download(name, blob) {
    const a = document.createElement('a');
    a.href = URL.createObjectURL(blob);
    a.download = name;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }
  const base = state => state.mechanism.name || 'mechanism';
  const schemeSvg = () => new XMLSerializer().serializeToString(svg);
  $('export-yaml').addEventListener('click', () => {
    const e = exportYaml();
    if (e.notes.length) say('the export: ' + e.notes.join('; '), !e.sameBranch);
    download(base(state) + '.yaml', new Blob([e.text], { type: 'text/yaml' }));
  });
  $('export-svg').addEventListener('click', () => download(base(state) + '.svg', new Blob([schemeSvg()], { type: 'image/svg+xml' })));
  $('export-png').addEventListener('click', () => {
    const img = new Image();
    img.onload = () => {
      const c = document.createElement('canvas');
      c.width = kWidth; c.height = kHeight;
      const ctx = c.getContext('2d');
      ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, kWidth, kHeight);
      ctx.drawImage(img, 0, 0);
      c.toBlob((b) => download(base(state) + '.png', b), 'image/png');
    };
    img.src = 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(schemeSvg());
  });

  // ---- the YAML export: the user's own text (doc.source) with the values the page changed
  // written in place by the library's rule (koppel_splice, as `--set` and `synth fit -o` write):
  // formulas, comments, units, masses and loads stay as written. A parameter set here is written
  // as its number; a coordinate a drag made a number is written at its key; once the design
  // changed, the assembly is written at the pose shown (an `assembly:` block appended when the
  // file has none), so that koppel reads the file back on the branch the page shows. The page
  // then loads the mechanism as the exported file gives it and says when it assembles otherwise.
  // A mechanism that came from no file is written anew (koppel_yaml).
  function valueAt(object, pointer) {
    let o = object;
    for (const k of pointer.split('/').slice(1)) o = o[k];
    return o;
  }
  function exportYaml() {
    if (!doc.source) {
      const y = call('koppel_yaml', [], []);
      if (!y.ok) throw new Error(y.message);
      return { text: y.yaml, notes: [], sameBranch: true };
    }
    const s = state || pending, places = doc.source.places, edits = [], notes = [];
    const edit = (path, value, what) => {
      const p = places[path];
      if (!p) throw new Error(what + ' is written over several lines in ' + doc.source.file + ': the page cannot change it in place');
      edits.push({ begin: p[0], end: p[1], quote: p[2], number: value, what: what });
    };
    for (const p of s.parameters) {
      const was = doc.parameters.find((q) => q.name === p.name);
      if (was && p.formula !== was.formula) edit('parameters.' + p.name, p.value, "parameter '" + p.name + "'");
    }
    const kept = new Set(s.formulas.map((f) => f.target));
    for (const f of doc.formulas) {
      if (kept.has(f.target) || f.target.startsWith('/hint/')) continue;
      edit(f.path, valueAt(s.mechanism, f.target) / f.scale, "'" + f.path + "'");
    }
    let text = doc.source.text, sameBranch = true;
    const splice = () => {
      const r = call('koppel_splice', ['string'], [JSON.stringify({ text: text, file: doc.source.file, edits: edits })]);
      if (!r.ok) throw new Error(r.message);
      return r.text;
    };
    if (edits.length && state && solved && !readsBackAsShown(fileHint(s))) {
      // the file's own assembly would put a loop on another branch: the pose shown goes into it
      const hint = assemblyAtPose();
      const written = new Set();
      for (const f of doc.formulas) {
        if (!f.path.startsWith('assembly.') || written.has(f.path)) continue;
        written.add(f.path);
        edit(f.path, hint.values[f.path], "'" + f.path + "'");
      }
      // a file with an assembly block of no points (only its input) pins no loop: its check
      // assembles from the input alone; a block koppel cannot write into is never doubled
      const hasBlock = /^assembly\s*:/m.test(text);
      if (!written.size && !hasBlock) text = appendAssembly(text, hint);
      const pinned = hint.fromFile || (!written.size && !hasBlock);
      sameBranch = readsBackAsShown(hintOf(pinned ? hint : { input: hint.input, points: [] }));
      notes.push(sameBranch ? (written.size ? "its 'assembly:' block" : "an 'assembly:' block appended") + ' holds the pose shown, so that koppel reads it on this branch'
                            : "koppel assembles the exported file on another branch than the one shown: add the points that pin it to its 'assembly:' block");
    }
    return { text: splice(), notes: notes, sameBranch: sameBranch };
  }
  // The hint the file's assembly block gives the mechanism s: its formulas evaluated with s's parameters.
  function fileHint(s) {
    const scope = {};
    for (const p of s.parameters) scope[p.name] = p.value;
    const holder = { hint: clone(doc.mechanism.hint) };
    for (const f of doc.formulas) if (f.target.startsWith('/hint/')) setAt(holder, f.target, evaluate(f.formula, scope) * f.scale);
    return holder.hint;
  }
  // The assembly at the pose shown: the input, and per key of the file's assembly block (or, with
  // none, per joint not on the frame: link.point) the global position of its point.
  function assemblyAtPose() {
    // a block of points without an input is read at the file's own hint input: the pose there
    let at = frame;
    const fileInput = doc.formulas.some((f) => f.path === 'assembly.input');
    if (!fileInput && doc.formulas.some((f) => f.path.startsWith('assembly.points.'))) {
      const target = doc.mechanism.hint.input / (doc.input.angle ? Math.PI / 180 : 1);
      const k = solved.table.rows.findIndex((r) => Math.abs(r[0] - target) <= 1e-9 * Math.max(1, Math.abs(target)));
      if (k >= 0) at = k;
    }
    const m = state.mechanism, pts = pointsAt(at), input = solved.table.rows[at][0];
    const values = { 'assembly.input': input }, keys = [];
    const position = (key) => {
      const dot = key.indexOf('.');
      for (let li = 0; li < m.links.length; ++li) {
        if (m.links[li].frame) continue;
        if (dot >= 0 && key.slice(0, dot) === m.links[li].name) {
          const pi = m.links[li].points.findIndex((p) => p.name === key.slice(dot + 1));
          if (pi >= 0) return pts[li][pi];
        }
        const pi = m.links[li].points.findIndex((p) => p.name === key);
        if (pi >= 0) return pts[li][pi];
      }
      return null;
    };
    const fileKeys = [...new Set(doc.formulas.filter((f) => f.path.startsWith('assembly.points.')).map((f) => f.path.slice(16, -3)))];
    if (fileKeys.length) {
      for (const k of fileKeys) keys.push(k);
    } else {
      for (const j of m.joints) {
        if (m.links[j.link_a].frame || m.links[j.link_b].frame) continue;
        keys.push(m.links[j.link_a].name + '.' + m.links[j.link_a].points[j.point_a].name);
      }
    }
    const points = [];
    for (const k of keys) {
      const xy = position(k);
      if (!xy) continue;
      values['assembly.points.' + k + '[0]'] = xy[0];
      values['assembly.points.' + k + '[1]'] = xy[1];
      points.push([k, xy]);
    }
    return { input: input, points: points, values: values, fromFile: fileKeys.length > 0 };
  }
  function appendAssembly(text, hint) {
    const number = (v) => String(+v.toPrecision(15));
    const entries = hint.points.map(([k, xy]) => JSON.stringify(k) + ': [' + number(xy[0]) + ', ' + number(xy[1]) + ']');
    return text + (text.endsWith('\n') ? '' : '\n') + '# the pose koppel edit showed when this file was exported: it keeps every loop on that branch\n' +
      'assembly: {input: ' + number(hint.input) + ', points: {' + entries.join(', ') + '}}\n';
  }
  // The hint an assembly block of these points makes (a bare point name: every link that has it).
  function hintOf(hint) {
    const m = state.mechanism, out = { input: (doc.input.angle ? Math.PI / 180 : 1) * hint.input, points: [] };
    for (const [k, xy] of hint.points) {
      m.links.forEach((l, li) => {
        if (l.frame) return;
        const dot = k.indexOf('.');
        if (dot >= 0 && k.slice(0, dot) === l.name) {
          const pi = l.points.findIndex((p) => p.name === k.slice(dot + 1));
          if (pi >= 0) out.points.push({ link: li, point: pi, x: xy[0], y: xy[1] });
          return;
        }
        const pi = l.points.findIndex((p) => p.name === k);
        if (pi >= 0) out.points.push({ link: li, point: pi, x: xy[0], y: xy[1] });
      });
    }
    return out;
  }
  // Whether the mechanism shown, assembled from `hint` as koppel reads the exported file, walks
  // the file's range through the poses shown (1e-9 of its size).
  function readsBackAsShown(hint) {
    const m = clone(state.mechanism), sw = m.sweep;
    m.hint = hint;
    const loaded = call('koppel_load', ['string'], [JSON.stringify(m)]);
    let same = false;
    if (loaded.ok) {
      const f = call('koppel_points', ['number', 'number', 'number', 'string'], [sw.from, sw.to, sw.step, '']);
      const mine = solved.frames;
      if (f.ok && f.inputs.length === mine.inputs.length && f.inputs.every((x, i) => x === mine.inputs[i])) {
        let worst = 0, size = 1;
        for (let k = 0; k < mine.points.length; ++k) { worst = Math.max(worst, Math.abs(f.points[k] - mine.points[k])); size = Math.max(size, Math.abs(mine.points[k])); }
        same = worst <= 1e-9 * size;
      }
    }
    call('koppel_load', ['string'], [JSON.stringify(state.mechanism)]);  // the module back to the mechanism shown
    return same;
  }

  // ---- the scripting API
  const api = {
    // the table of `koppel analyze --format json` for the current mechanism
    sweep(from, to, step, order) {
      const t = call('koppel_sweep', ['number', 'number', 'number', 'number', 'string'], [from, to, step, order === undefined ? 2 : order, atBranchPoint]);
      if (!t.ok) throw new Error(t.message);
      return { columns: t.columns, rows: t.rows, complete: t.complete, status: t.status, message: t.message };
    },
    // a parameter to a value, the file's formulas evaluated again; {ok, message}
    set(name, value) {
      // a value is a finite number: '' or null or [] is not 0, true is not 1, 'x' is no formula to blame
      if (typeof value !== 'number' || !Number.isFinite(value)) {
        const why = name + ': expected a finite number, got ' + (typeof value === 'string' ? "'" + value + "'" : String(value));
        say(why, true);
        return { ok: false, message: why };
      }
      if (!formulasTrusted) return { ok: false, message: message.textContent };
      const base = state || pending;
      if (!base.parameters.some((p) => p.name === name)) return { ok: false, message: "'" + name + "' is not a parameter of this file" };
      // a parameter no formula reads would change nothing: refused as `--set` refuses it
      const unread = doc.parameters.find((p) => p.name === name && p.unread);
      if (unread) { say(unread.unread, true); return { ok: false, message: unread.unread }; }
      let next;
      try { next = evaluated(base, name, +value); } catch (e) { say(name + ' = ' + value + ': ' + e.message, true); return { ok: false, message: e.message }; }
      if (state && solved) hintFromPose(next.mechanism, pointsAt(frame));
      const ok = adopt(next, name + ' = ' + value, !state);
      return { ok: ok, message: message.textContent };
    },
    moveJoint(name, x, y) { return { ok: moveJoint(name, x, y, true), message: message.textContent }; },
    // the YAML export: the user's file with the page's changes written in place (exportYaml)
    toYaml() { return exportYaml().text; },
    // the same with what the page says of it: {text, notes, sameBranch}
    exportYaml() { return exportYaml(); },
    parameters() { return (state || pending).parameters.map((p) => ({ name: p.name, value: p.value })); },
    state() {
      return { input: solved ? solved.table.rows[frame][0] : null, frame: frame, message: message.textContent, error: message.className === 'error' };
    },
    ready: null,
  };
  window.koppel = api;
  api.ready = KoppelModule().then((m) => {
    module = m;
    $('title').textContent = doc.title;
    const why = checkFormulas();
    if (why) { formulasTrusted = false; }
    const first = { mechanism: doc.mechanism, parameters: doc.parameters, formulas: doc.formulas };
    if (!adopt(first, '', true)) {
      // nothing to show but the message: the sliders stay, so that a parameter can fix it
      pending = first;
      drawParameters();
      return api;
    }
    const notes = [];
    if (why) notes.push('the parameter sliders are off: the page evaluates a formula otherwise than koppel (' + why + ')');
    if (doc.has_loads) notes.push(doc.source ? "the file's masses and loads are not part of the page (its YAML export keeps them as written)" : "the file's masses and loads are not part of the page (its YAML export leaves them out)");
    if (notes.length) say(notes.join('; '), false);
    requestAnimationFrame(tick);
    return api;
  });
})();
