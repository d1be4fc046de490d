// The page of `koppel view`: animates the scheme that koppel drew (each link is an SVG group
// in its body frame; only its transform changes), and shows the transfer functions and the
// transmission angle with uPlot, a cursor at the current input and the numbers there.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('koppel-data').textContent);
  const n = data.inputs.length;
  const svg = document.querySelector('svg.scheme');
  const scale = +svg.dataset.scale, ox = +svg.dataset.ox, oy = +svg.dataset.oy;
  const groups = Array.from(svg.querySelectorAll('g[data-coord]'));
  const labels = Array.from(svg.querySelectorAll('text[data-coord]'));
  const slider = document.getElementById('input-slider');
  const value = document.getElementById('input-value');
  const readout = document.getElementById('readout');
  const caption = document.getElementById('caption');
  const width = data.coordinates;
  let frame = 0, playing = n > 1, direction = 1, speed = 1, last = null, carry = 0;

  document.getElementById('title').textContent = data.title;
  document.getElementById('message').textContent = data.message || '';
  slider.max = String(Math.max(0, n - 1));

  function fmt(v) { return v === null || v === undefined ? '–' : Number(v).toPrecision(6); }

  // body -> global -> px, the same mapping as koppel's SVG writer (y flipped)
  function place(i) {
    const q = data.poses, base = i * width;
    for (const g of groups) {
      const c = base + +g.dataset.coord, x = q[c], y = q[c + 1], t = q[c + 2];
      const cs = Math.cos(t), sn = Math.sin(t);
      g.setAttribute('transform', 'matrix(' + [scale * cs, -scale * sn, -scale * sn, -scale * cs,
        ox + scale * x, oy - scale * y].join(' ') + ')');
    }
    for (const l of labels) {
      const c = base + +l.dataset.coord, x = q[c], y = q[c + 1], t = q[c + 2];
      const px = +l.dataset.px, py = +l.dataset.py;
      const gx = x + Math.cos(t) * px - Math.sin(t) * py, gy = y + Math.sin(t) * px + Math.cos(t) * py;
      // the offset koppel's label layout chose for the first pose
      l.setAttribute('x', (ox + scale * gx + +l.dataset.dx).toFixed(2));
      l.setAttribute('y', (oy - scale * gy + +l.dataset.dy).toFixed(2));
    }
  }

  // one uPlot chart per scalar output: the value on the left axis, its derivatives on the right
  const charts = [];
  const plots = document.getElementById('plots');
  const xs = [], rowOf = [], rowOfSample = [];
  // a null row between stretches and at gaps: uPlot leaves a gap there, never a bridging line
  for (let i = 0; i < n; ++i) {
    if (i > 0 && data.breaks.includes(i)) { xs.push((data.inputs[i - 1] + data.inputs[i]) / 2); rowOf.push(-1); }
    rowOfSample.push(xs.length); xs.push(data.inputs[i]); rowOf.push(i);
  }
  const palette = ['#1f5fa8', '#c0392b', '#2e8b57', '#7d3c98'];
  for (const chart of data.charts) {
    const title = document.createElement('div');
    title.className = 'chart-title';
    title.textContent = chart.title;
    plots.appendChild(title);
    const box = document.createElement('div');
    box.className = 'chart';
    plots.appendChild(box);
    const columns = [xs];
    const series = [{ label: data.input_label }];
    chart.series.forEach(function (s, k) {
      columns.push(rowOf.map(function (r) { return r < 0 ? null : s.values[r]; }));
      series.push({ label: s.label, stroke: palette[k % palette.length], width: 1.6, scale: k === 0 ? 'y' : 'd', spanGaps: false });
    });
    const axes = [{ label: data.input_label }, { scale: 'y', label: chart.series[0].label }];
    if (chart.series.length > 1) axes.push({ scale: 'd', side: 1, grid: { show: false }, label: 'derivatives' });
    const u = new uPlot({
      // height: the whole chart; the x axis with its label takes about 100 px of it, leaving the
      // plot area about 260 px (the floor: 240)
      width: 560, height: 360, series: series, axes: axes, legend: { show: true },
      scales: { x: { time: false } },
      cursor: { drag: { x: false, y: false } },
    }, columns, box);
    const cursor = document.createElement('div');
    cursor.className = 'koppel-cursor';
    u.over.appendChild(cursor);
    charts.push({ u: u, cursor: cursor });
  }

  function show(i) {
    frame = i;
    place(i);
    slider.value = String(i);
    const shown = data.inputs[i];
    value.textContent = data.input_label + ' = ' + fmt(shown);
    if (caption) caption.textContent = data.input_label + ' = ' + fmt(shown);
    for (const c of charts) {
      c.cursor.style.left = c.u.valToPos(shown, 'x') + 'px';
      c.u.setLegend({ idx: rowOfSample[i] });  // the legend shows the numbers at the current input
    }
    const rows = [row(data.input_label, fmt(shown))];
    for (const r of data.readout) rows.push(row(r.label, fmt(r.values[i])));
    readout.replaceChildren(...rows);
  }

  // a readout row; a name is text, never markup (it comes from the mechanism file)
  function row(label, number) {
    const tr = document.createElement('tr');
    for (const text of [label, number]) tr.appendChild(document.createElement('td')).textContent = text;
    return tr;
  }

  function tick(now) {
    if (last === null) last = now;
    const dt = Math.min(0.1, (now - last) / 1000);
    last = now;
    if (playing && n > 1) {
      // a full turn in about six seconds at 1x, whatever the sampling
      carry += dt * speed * n / 6;
      const steps = Math.floor(carry);
      carry -= steps;
      let i = frame;
      for (let k = 0; k < steps; ++k) {
        if (data.cyclic) { i = (i + 1) % n; continue; }
        if (i + direction < 0 || i + direction >= n) direction = -direction;  // back and forth in a limited range
        i += direction;
      }
      if (i !== frame) show(i);
    }
    requestAnimationFrame(tick);
  }

  document.getElementById('play').addEventListener('click', function () {
    playing = !playing;
    this.textContent = playing ? 'Pause' : 'Play';
  });
  document.getElementById('speed').addEventListener('change', function () { speed = +this.value; });
  slider.addEventListener('input', function () { show(+slider.value); });
  show(0);
  requestAnimationFrame(tick);
})();
