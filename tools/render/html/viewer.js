/* viewer.js - the browser side of neat-duel's HTML pages: replays a duel, charts a run or an experiment, from the page's embedded JSON. */
(function () {
  'use strict';

  // The test hook (docs: html-spec.md); `ready` turns true only after the first draw.
  const hook = {ready: false, kind: null, frames: 0, errors: []};
  window.duelPage = hook;
  window.addEventListener('error', (e) => hook.errors.push(String(e.message || 'error')));

  const SVGNS = 'http://www.w3.org/2000/svg';
  const COL = {
    page: '#1e2227', board: '#f4f1e8', edge: '#9a968c', food: '#2ca02c', outline: '#202020',
    side: ['#1f77b4', '#ff7f0e'], trail: ['#89b4ce', '#f9b87b'], ray: ['rgba(31,119,180,0.5)', 'rgba(255,127,14,0.5)'],
    pos: '#8fa8c8', neg: '#e0524a', off: '#2b3038', on: '#ffcf33', cold: '#4fb3ff', muted: '#9aa0a8',
  };
  const SIDES = ['west', 'east'];
  const IN_NAMES = ['bias', 'food_ahead', 'food_left', 'food_back_left', 'food_back_right', 'food_right',
    'robot_ahead', 'robot_left', 'robot_back_left', 'robot_back_right', 'robot_right', 'energy_diff', 'wall'];
  const OUT_NAMES = ['turn_left', 'turn_right', 'forward'];
  // Short labels under the graph's input row: arrows give the sector's direction (ahead = up).
  const SHORT = {bias: 'b', food_ahead: 'f\u2191', food_left: 'f\u2196', food_back_left: 'f\u2199',
    food_back_right: 'f\u2198', food_right: 'f\u2197', robot_ahead: 'r\u2191', robot_left: 'r\u2196',
    robot_back_left: 'r\u2199', robot_back_right: 'r\u2198', robot_right: 'r\u2197', energy_diff: '\u0394e',
    wall: 'w', turn_left: 'left', turn_right: 'right', forward: 'fwd'};
  const SPEEDS = [0.25, 0.5, 1, 2, 4, 8];
  const STEPS_PER_S = 30;

  // ---- small helpers -------------------------------------------------------------------------

  // Every string from the data goes through textContent or setAttribute, never parsed as HTML.
  function setAttrs(e, attrs) {
    for (const k in attrs || {}) {
      const v = attrs[k];
      if (v == null || v === false) continue;
      if (k === 'text') e.textContent = String(v);
      else e.setAttribute(k, String(v));
    }
  }
  function h(tag, attrs, kids) {
    const e = document.createElement(tag);
    setAttrs(e, attrs);
    if (kids != null) e.append(...[].concat(kids).filter((k) => k != null));
    return e;
  }
  function sv(tag, attrs, parent) {
    const e = document.createElementNS(SVGNS, tag);
    setAttrs(e, attrs);
    if (parent) parent.appendChild(e);
    return e;
  }
  // Control characters would be invisible: show them as Unicode control pictures.
  function clean(v) {
    const s = typeof v === 'string' ? v : v == null ? '' : String(v);
    return s.replace(/[\u0000-\u001f\u007f]/g, (c) => String.fromCharCode(c === '\u007f' ? 0x2421 : 0x2400 + c.charCodeAt(0)));
  }
  function fmt(v) {
    if (typeof v !== 'number') return clean(v);
    if (!isFinite(v) || Number.isInteger(v)) return String(v);
    return Math.abs(v) >= 1000 ? v.toFixed(1) : String(+v.toPrecision(4));
  }
  // Only relative sibling paths the C writer made; anything else gets no link.
  function safeHref(p) {
    return typeof p === 'string' && /^[A-Za-z0-9._\/-]+\.html$/.test(p) && p[0] !== '/' &&
      !p.split('/').some((seg) => seg === '..' || seg === '');
  }
  const swatch = (s) => h('span', {class: 'sw sw' + s});
  const clamp = (v, a, b) => Math.min(b, Math.max(a, v));
  function hexRgb(c) { return [1, 3, 5].map((i) => parseInt(c.slice(i, i + 2), 16)); }
  const RGB = {off: hexRgb(COL.off), on: hexRgb(COL.on), cold: hexRgb(COL.cold)};
  function mix(a, b, f) { return 'rgb(' + a.map((x, i) => Math.round(x + (b[i] - x) * f)).join(',') + ')'; }
  const actFill = (a) => (a >= 0 ? mix(RGB.off, RGB.on, Math.min(1, a)) : mix(RGB.off, RGB.cold, Math.min(1, -a)));

  // Base64 of little-endian typed data; DataView reads it the same on any machine.
  function decode(b64, Type) {
    if (typeof b64 !== 'string' || b64 === '') return new Type(0);
    const bin = atob(b64), bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    const size = Type.BYTES_PER_ELEMENT, out = new Type(Math.floor(bytes.length / size)), dv = new DataView(bytes.buffer);
    for (let i = 0; i < out.length; i++) {
      out[i] = size === 2 ? dv.getInt16(2 * i, true) : Type === Uint32Array ? dv.getUint32(4 * i, true) : dv.getInt32(4 * i, true);
    }
    return out;
  }

  // ---- the duel model ------------------------------------------------------------------------

  function checkNet(net) {
    if (!net || typeof net !== 'object') return null;
    const nIn = net.inputs | 0, nOut = net.outputs | 0, H = net.hidden | 0, N = nIn + nOut + H;
    if (nIn < 1 || nOut < 1 || H < 0 || N > 4096) throw new Error('a network has a bad size');
    const conns = (Array.isArray(net.conns) ? net.conns : []).map((c, i) => ({
      src: c[0] | 0, dst: c[1] | 0, w: +c[2] || 0, rec: !!(Array.isArray(net.recurrent) && net.recurrent[i]),
    })).filter((c) => c.src >= 0 && c.src < N && c.dst >= 0 && c.dst < N);
    const arr = (a, v) => (Array.isArray(a) ? a[v] : undefined);
    const names = [];
    for (let v = 0; v < N; v++) {
      const dflt = v < nIn ? IN_NAMES[v] || 'in' + v : v < nIn + nOut ? OUT_NAMES[v - nIn] || 'out' + (v - nIn) : 'h' + v;
      names.push(typeof arr(net.names, v) === 'string' ? clean(net.names[v]) : dflt);
    }
    const depth = [], dead = [];
    for (let v = 0; v < N; v++) {
      const dd = arr(net.depth, v);
      depth.push(Number.isInteger(dd) && dd > 0 ? dd : 1);
      dead.push(!!arr(net.dead, v));
    }
    return {nIn, nOut, H, N, conns, names, depth, dead};
  }

  function model(d) {
    const n = d.n, f = d.frames || {};
    if (!Number.isInteger(n) || n < 1) throw new Error('the game has no frames');
    const m = {n, pos: decode(f.pos, Int32Array), food: decode(f.food, Uint32Array), inp: decode(f.in, Int16Array),
      out: decode(f.out, Int16Array)};
    if (m.pos.length < 8 * n || m.food.length < n || m.inp.length < 26 * n || m.out.length < 6 * n) {
      throw new Error('the frame data is shorter than its ' + n + ' frames');
    }
    m.w = Object.assign({name: '?', id: '', radius: 10, food_radius: 5, food_range: 850, robot_range: 850,
      start_energy: 1200, board: 600}, d.world || {});
    m.sides = [0, 1].map((s) => {
      const sd = (Array.isArray(d.sides) && d.sides[s]) || {};
      const net = checkNet(sd.net);
      const hid = net ? decode((f.hid || [])[s], Int16Array) : null;
      if (net && hid.length < net.H * n) throw new Error('the ' + SIDES[s] + ' network\u2019s frame data is short');
      return {name: clean(sd.name), step: clean(sd.step), net, hid};
    });
    m.fx = Array.isArray(d.food_xy) ? d.food_xy.map(Number) : [];
    m.events = (Array.isArray(d.events) ? d.events : []).filter((e) => Array.isArray(e) && Number.isInteger(e[0]))
      .sort((a, b) => a[0] - b[0]);
    m.energy = [0, 1].map((s) => Float64Array.from({length: n}, (_, t) => m.pos[8 * t + 4 * s + 3] / 65536));
    return m;
  }
  function robot(m, t, s) {
    const o = 8 * t + 4 * s, hd = m.pos[o + 2];
    return {x: m.pos[o] / 65536, y: m.pos[o + 1] / 65536,
      heading: hd === -2147483648 ? Math.PI : hd * Math.PI / 2147483648, energy: m.pos[o + 3] / 65536};
  }
  // The last frame is the final state with zero in/out: the networks show the last step's values.
  const netFrame = (m, t) => (t === m.n - 1 && m.n > 1 ? m.n - 2 : t);
  const ins = (m, s, f) => Array.from({length: 13}, (_, v) => m.inp[26 * f + 13 * s + v] / 32768);
  const outs = (m, s, f) => Array.from({length: 3}, (_, k) => m.out[6 * f + 3 * s + k] / 32768);
  function activations(m, s, f) {
    const net = m.sides[s].net;
    if (!net) return null;
    const i = ins(m, s, f), o = outs(m, s, f), a = [];
    for (let v = 0; v < net.nIn; v++) a.push(v < 13 ? i[v] : 0);
    for (let k = 0; k < net.nOut; k++) a.push(k < 3 ? o[k] : 0);
    for (let k = 0; k < net.H; k++) a.push(m.sides[s].hid[f * net.H + k] / 32768);
    return a;
  }
  function eventText(e) {
    const who = (s) => (s === 0 || s === 1 ? SIDES[s] : 'both');
    if (e[1] === 'eat') return who(e[2]) + ' eats food ' + fmt(e[3]);
    if (e[1] === 'collision') return e[2] === -1 ? 'collision (draw)' : 'collision (' + who(e[2]) + ')';
    return clean(e[1]);
  }

  // ---- the network graph: inputs at the bottom, hidden rows by depth, outputs on top ----------

  function netGraph(parent, net) {
    const MAXROW = 10, W = 400, PADX = 12, TOP = 28, BOT = 30, GAP = 50;
    const byDepth = new Map();
    for (let v = net.nIn + net.nOut; v < net.N; v++) {
      if (!byDepth.has(net.depth[v])) byDepth.set(net.depth[v], []);
      byDepth.get(net.depth[v]).push(v);
    }
    const range = (a, b) => Array.from({length: b - a}, (_, i) => a + i);
    const rows = [range(0, net.nIn)];
    for (const dd of [...byDepth.keys()].sort((a, b) => a - b)) {
      const vs = byDepth.get(dd);
      for (let i = 0; i < vs.length; i += MAXROW) rows.push(vs.slice(i, i + MAXROW));
    }
    rows.push(range(net.nIn, net.nIn + net.nOut));
    const HGT = TOP + BOT + GAP * (rows.length - 1);
    const xy = new Array(net.N), srcs = Array.from({length: net.N}, () => []);
    for (const c of net.conns) srcs[c.dst].push(c.src);
    rows.forEach((row, r) => {
      const y = HGT - BOT - r * GAP;
      if (r > 0 && r < rows.length - 1) {
        // Order a hidden row by the mean x of its already placed sources: fewer crossings.
        const key = (v) => { const p = srcs[v].filter((u) => xy[u]); return p.length ? p.reduce((s, u) => s + xy[u][0], 0) / p.length : W / 2; };
        row = row.map((v) => [v, key(v)]).sort((a, b) => a[1] - b[1]).map((p) => p[0]);
      }
      row.forEach((v, i) => { xy[v] = [PADX + (i + 0.5) * (W - 2 * PADX) / row.length, y]; });
    });
    const svg = sv('svg', {viewBox: '0 0 ' + W + ' ' + HGT, class: 'net-svg', role: 'img', 'aria-label': 'network graph'}, parent);
    const gE = sv('g', {}, svg), gN = sv('g', {}, svg);
    const edges = net.conns.map((c) => {
      const [x1, y1] = xy[c.src], [x2, y2] = xy[c.dst];
      let d;
      // A self-loop goes out sideways: above and below a node are its label and its inputs.
      if (c.src === c.dst) d = 'M' + (x1 + 7) + ',' + (y1 - 5) + ' C' + (x1 + 34) + ',' + (y1 - 24) + ' ' + (x1 + 34) + ',' + (y1 + 24) + ' ' + (x1 + 7) + ',' + (y1 + 5);
      else if (y1 > y2 + 1 && !c.rec) d = 'M' + x1 + ',' + y1 + ' L' + x2 + ',' + y2;
      else {
        // Backward, sideways or recurrent: bow the line out so it does not run along a row.
        const dx = x2 - x1, dy = y2 - y1, len = Math.hypot(dx, dy) || 1, bow = 0.2 * len + 12;
        d = 'M' + x1 + ',' + y1 + ' Q' + ((x1 + x2) / 2 - dy / len * bow) + ',' + ((y1 + y2) / 2 + dx / len * bow) + ' ' + x2 + ',' + y2;
      }
      const p = sv('path', {d, fill: 'none', stroke: c.w >= 0 ? COL.pos : COL.neg,
        'stroke-width': (0.5 + 0.45 * Math.min(Math.abs(c.w), 6)).toFixed(2), 'stroke-dasharray': c.rec ? '4 3' : null}, gE);
      sv('title', {text: net.names[c.src] + ' \u2192 ' + net.names[c.dst] + ': ' + c.w.toFixed(3) + (c.rec ? ' (recurrent)' : '')}, p);
      return p;
    });
    const nodes = [];
    for (let v = 0; v < net.N; v++) {
      const isOut = v >= net.nIn && v < net.nIn + net.nOut;
      const c = sv('circle', {cx: xy[v][0], cy: xy[v][1], r: isOut ? 11 : v < net.nIn ? 8 : 9, class: 'node' + (net.dead[v] ? ' dead' : ''), fill: COL.off}, gN);
      const tip = sv('title', {text: net.names[v]}, c);
      nodes.push({c, tip, fill: '', lit: null});
      if (v < net.nIn || isOut) {
        const name = net.names[v];
        sv('text', {x: xy[v][0], y: xy[v][1] + (isOut ? -16 : 21), 'text-anchor': 'middle', class: 'lbl', text: SHORT[name] || name.slice(0, 4)}, gN);
      }
    }
    return function update(act) {
      for (let v = 0; v < net.N; v++) {
        const a = act[v], nd = nodes[v], f = actFill(a), lit = a > 0.5;
        if (f !== nd.fill) { nd.c.setAttribute('fill', f); nd.fill = f; }
        if (lit !== nd.lit) { nd.c.classList.toggle('lit', lit); nd.lit = lit; }
        nd.tip.textContent = net.names[v] + ' = ' + a.toFixed(3) + (net.dead[v] ? ' (dead)' : '');
      }
      // A connection is as visible as its source's activation: the eye follows the signal.
      net.conns.forEach((c, i) => edges[i].setAttribute('stroke-opacity', (0.18 + 0.82 * Math.min(1, Math.abs(act[c.src]))).toFixed(2)));
    };
  }

  // Name, bar, value per input/output; energy_diff (input 11) is signed, its bar grows from the middle.
  function bars(parent, title, names, signedAt) {
    const box = h('div', {class: 'bar-group'}, h('div', {class: 'bar-title', text: title}));
    parent.append(box);
    const rows = names.map((name) => {
      const fill = h('div', {class: 'bar-fill'}), val = h('span', {class: 'bar-val'});
      const row = h('div', {class: 'bar-row'}, [h('span', {class: 'bar-name', text: name, title: name}), h('div', {class: 'bar-track'}, fill), val]);
      box.append(row);
      return {row, fill, val};
    });
    return function update(vals) {
      rows.forEach((r, i) => {
        const v = vals[i], signed = i === signedAt;
        r.fill.style.left = (signed ? 50 + 50 * Math.min(0, clamp(v, -1, 1)) : 0) + '%';
        r.fill.style.width = (signed ? 50 * Math.abs(clamp(v, -1, 1)) : 100 * clamp(v, 0, 1)) + '%';
        r.val.textContent = v.toFixed(2);
        r.row.classList.toggle('lit', v > 0.5);
      });
    };
  }

  function netPanel(parent, m, s) {
    const sd = m.sides[s], net = sd.net;
    const panel = h('section', {class: 'net-panel'});
    parent.append(panel);
    // A long path loses its start here (the header has it whole).
    const parts = sd.name.split('/'), short = sd.name.length > 40 && parts.length > 2 ? '\u2026/' + parts.slice(-2).join('/') : sd.name;
    const head = h('div', {class: 'net-head', title: sd.name}, [swatch(s), h('b', {text: SIDES[s] + ' '}), h('span', {class: 'name', text: short})]);
    panel.append(head);
    let info = 'step: ' + (sd.step || '?');
    if (net) {
      const rec = net.conns.filter((c) => c.rec).length;
      info += ' \u00b7 ' + net.H + ' hidden, ' + net.conns.length + ' connections' + (rec ? ' (' + rec + ' recurrent)' : '');
    } else info += ' \u00b7 no network drawn';
    panel.append(h('div', {class: 'muted small', text: info}));
    const note = h('div', {class: 'note small'});
    panel.append(note);
    const graph = net ? netGraph(panel, net) : null;
    const bx = h('div', {class: 'bars'});
    panel.append(bx);
    const inNames = net ? net.names.slice(0, Math.min(13, net.nIn)).concat(IN_NAMES.slice(net.nIn)) : IN_NAMES;
    const outNames = net ? net.names.slice(net.nIn, net.nIn + Math.min(3, net.nOut)).concat(OUT_NAMES.slice(net.nOut)) : OUT_NAMES;
    const bIn = bars(bx, 'inputs', inNames, 11), bOut = bars(bx, 'outputs', outNames, -1);
    return function update(t) {
      const f = netFrame(m, t);
      note.textContent = t !== m.n - 1 ? '' : m.n === 1 ? 'final state' : net ? 'final state; network values of the last step' : 'final state; inputs and outputs of the last step';
      bIn(ins(m, s, f));
      bOut(outs(m, s, f));
      const act = activations(m, s, f);
      if (graph) graph(act);
      return act;
    };
  }

  // ---- the duel viewer (kind "duel", and each embedded game) ---------------------------------

  let activeViewer = null; // the viewer the keyboard drives: the page's or the open overlay's

  function duelViewer(root, d) {
    const m = model(d), n = m.n, w = m.w, B = +w.board || 600;
    let t = 0, playing = false, speedIx = 2, raf = 0, last = null, acc = 0, lastState = null;
    const opt = {rays: true, readings: true, trails: true};

    // Header: names, outcome, food, world.
    const head = h('div', {class: 'duel-head'});
    const names = h('div', {class: 'names'});
    [0, 1].forEach((s) => names.append(h('span', {class: 'who'}, [swatch(s), h('b', {text: SIDES[s] + ': '}), h('span', {class: 'name', text: m.sides[s].name})])));
    const win = d.winner === 0 || d.winner === 1 ? d.winner : -1;
    const outcome = h('div', {class: 'outcome'}, [win >= 0 ? swatch(win) : null, h('span', {text: clean(d.outcome) || 'no outcome recorded'})]);
    const fc = d.food_config;
    const meta = h('div', {class: 'muted small', text: (fc === -1 ? 'training food' : 'food configuration ' + fmt(fc)) +
      ' \u00b7 world ' + clean(w.name) + (w.id ? ' (' + clean(w.id) + ')' : '') + ' \u00b7 ' + (n - 1) + ' steps',
      title: 'radius ' + w.radius + ', food radius ' + w.food_radius + ', food range ' + w.food_range + ', robot range ' + w.robot_range + ', start energy ' + w.start_energy});
    head.append(names, outcome, meta);
    root.append(head);

    const main = h('div', {class: 'duel-main'});
    const left = h('div', {class: 'duel-left'}), right = h('div', {class: 'nets'});
    main.append(left, right);
    root.append(main);

    const boardWrap = h('div', {class: 'board-wrap'}), canvas = h('canvas', {'aria-label': 'the board'});
    boardWrap.append(canvas);
    left.append(boardWrap);
    // willReadFrequently: pixel() reads back often; without it Chromium warns in the console.
    const ctx = canvas.getContext('2d', {willReadFrequently: true});

    // Controls.
    const btn = (text, title, fn) => { const b = h('button', {type: 'button', text, title}); b.addEventListener('click', fn); return b; };
    const bPlay = btn('\u25b6 play', 'play / pause (space)', () => (playing ? pause() : play()));
    const speedSel = h('select', {title: 'speed (+ / -)'}, SPEEDS.map((v, i) => h('option', {value: i, text: v + '\u00d7'})));
    speedSel.value = String(speedIx);
    speedSel.addEventListener('change', () => { speedIx = +speedSel.value; });
    const tLabel = h('span', {class: 'tlabel'});
    const toggles = Object.keys(opt).map((k) => {
      const cb = h('input', {type: 'checkbox'});
      cb.checked = opt[k];
      cb.addEventListener('change', () => { opt[k] = cb.checked; render(); });
      return h('label', {class: 'small'}, [cb, ' ' + (k === 'rays' ? 'sector rays' : k)]);
    });
    const controls = h('div', {class: 'controls'}, [
      btn('|\u25c0', 'first frame (Home)', () => goto(0)), btn('\u25c0', 'step back (\u2190)', () => goto(t - 1)), bPlay,
      btn('\u25b6', 'step forward (\u2192)', () => goto(t + 1)), btn('\u25b6|', 'last frame (End)', () => goto(n - 1)),
      speedSel, tLabel]);
    const scrub = h('input', {type: 'range', min: 0, max: n - 1, step: 1, value: 0, class: 'scrub', 'aria-label': 'step'});
    scrub.addEventListener('input', () => goto(+scrub.value));
    left.append(controls, scrub, h('div', {class: 'controls'}, toggles));

    const energyWrap = h('div', {class: 'energy-wrap', title: 'energy; click to seek'}), eCanvas = h('canvas');
    energyWrap.append(eCanvas);
    left.append(h('div', {class: 'sub', text: 'energy'}), energyWrap);
    const eCtx = eCanvas.getContext('2d');
    const seekFromChart = (e) => {
      const r = eCanvas.getBoundingClientRect(), L = 34, R = 8;
      goto(Math.round(clamp((e.clientX - r.left - L) / Math.max(1, r.width - L - R), 0, 1) * (n - 1)));
    };
    energyWrap.addEventListener('pointerdown', (e) => { energyWrap.setPointerCapture(e.pointerId); seekFromChart(e); });
    energyWrap.addEventListener('pointermove', (e) => { if (e.buttons & 1) seekFromChart(e); });

    const evList = h('ul', {class: 'events'});
    const evItems = m.events.map((e) => {
      const li = h('li', {text: 'step ' + e[0] + ': ' + eventText(e), title: 'go to the frame after it'});
      li.addEventListener('click', () => goto(Math.min(n - 1, e[0] + 1)));
      evList.append(li);
      return li;
    });
    const evNone = h('li', {class: 'muted', text: 'none yet'});
    evList.append(evNone);
    left.append(h('div', {class: 'sub', text: 'events so far'}), evList);
    left.append(h('div', {class: 'keys', text: 'keys: space play/pause \u00b7 \u2190 \u2192 step \u00b7 shift+\u2190 \u2192 10 steps \u00b7 Home/End \u00b7 + \u2212 speed'}));

    const panels = [0, 1].map((s) => netPanel(right, m, s));

    // Board geometry in device pixels: the board's square inset by a 1-pixel (CSS) edge.
    const g = {W: 0, dpr: 1, e: 1, sc: 1};
    const px = (x) => g.e + x * g.sc, py = (y) => g.e + (B - y) * g.sc;
    function layout() {
      const dpr = window.devicePixelRatio || 1, css = boardWrap.clientWidth || 480;
      const W = Math.max(50, Math.round(css * dpr));
      if (W !== canvas.width) { canvas.width = W; canvas.height = W; }
      g.W = W; g.dpr = dpr; g.e = Math.max(1, Math.round(dpr)); g.sc = (W - 2 * g.e) / B;
      const ew = Math.max(50, Math.round((energyWrap.clientWidth || 480) * dpr)), eh = Math.max(20, Math.round((energyWrap.clientHeight || 100) * dpr));
      if (ew !== eCanvas.width || eh !== eCanvas.height) { eCanvas.width = ew; eCanvas.height = eh; }
      energyBase = null;
    }

    function drawBoard(rb, mask) {
      const c = ctx, W = g.W, sc = g.sc, e = g.e;
      c.setTransform(1, 0, 0, 1, 0, 0);
      c.fillStyle = COL.edge; c.fillRect(0, 0, W, W);
      c.fillStyle = COL.board; c.fillRect(e, e, W - 2 * e, W - 2 * e);
      c.save();
      c.beginPath(); c.rect(e, e, W - 2 * e, W - 2 * e); c.clip();
      c.lineCap = 'round'; c.lineJoin = 'round';
      if (opt.trails && t > 0) {
        for (let s = 0; s < 2; s++) {
          c.beginPath();
          for (let k = 0; k <= t; k++) { const o = 8 * k + 4 * s; c.lineTo(px(m.pos[o] / 65536), py(m.pos[o + 1] / 65536)); }
          c.strokeStyle = COL.trail[s]; c.lineWidth = Math.max(1, 0.25 * w.radius * sc); c.stroke();
        }
      }
      if (opt.rays) {
        // The five sector boundaries, from the rim to beyond the board (the clip ends them).
        c.lineWidth = Math.max(1, g.dpr);
        for (let s = 0; s < 2; s++) {
          const r = rb[s];
          c.beginPath();
          for (let k = 0; k < 5; k++) {
            const a = r.heading + (2 * k + 1) * Math.PI / 5, ca = Math.cos(a), sa = Math.sin(a);
            c.moveTo(px(r.x + ca * w.radius), py(r.y + sa * w.radius));
            c.lineTo(px(r.x + ca * 2 * B), py(r.y + sa * 2 * B));
          }
          c.strokeStyle = COL.ray[s]; c.stroke();
        }
      }
      if (opt.readings) {
        // A reading r > 0 puts the nearest object on an arc across its sector at (1 - r) * range.
        c.lineWidth = Math.max(1.5, 2.2 * g.dpr);
        for (let s = 0; s < 2; s++) {
          const r = rb[s];
          for (let k = 0; k < 5; k++) {
            for (const [off, range, col] of [[1, w.food_range, COL.food], [6, w.robot_range, COL.side[1 - s]]]) {
              const v = m.inp[26 * t + 13 * s + off + k] / 32768;
              if (!(v > 0)) continue;
              const dist = (1 - v) * range, a1 = r.heading + (2 * k - 1) * Math.PI / 5, a2 = a1 + 2 * Math.PI / 5;
              c.beginPath(); c.arc(px(r.x), py(r.y), Math.max(0.5, dist * sc), -a2, -a1);
              c.strokeStyle = col; c.stroke();
            }
          }
        }
      }
      c.fillStyle = COL.food;
      for (let i = 0; 2 * i + 1 < m.fx.length && i < 32; i++) {
        if (!((mask >>> i) & 1)) continue;
        c.beginPath(); c.arc(px(m.fx[2 * i]), py(m.fx[2 * i + 1]), w.food_radius * sc, 0, 2 * Math.PI); c.fill();
      }
      for (let s = 0; s < 2; s++) {
        const r = rb[s], x = px(r.x), y = py(r.y), R = w.radius * sc, ca = Math.cos(r.heading), sa = -Math.sin(r.heading);
        c.beginPath(); c.arc(x, y, R, 0, 2 * Math.PI);
        c.fillStyle = COL.side[s]; c.fill();
        c.lineWidth = Math.max(1, 0.12 * R); c.strokeStyle = COL.outline; c.stroke();
        // The white heading triangle, 0.2 to 0.9 of the radius along the heading (as duel_render).
        c.beginPath();
        c.moveTo(x + ca * 0.9 * R, y + sa * 0.9 * R);
        c.lineTo(x + ca * 0.2 * R - sa * 0.45 * R, y + sa * 0.2 * R + ca * 0.45 * R);
        c.lineTo(x + ca * 0.2 * R + sa * 0.45 * R, y + sa * 0.2 * R - ca * 0.45 * R);
        c.closePath(); c.fillStyle = '#ffffff'; c.fill();
      }
      c.restore();
    }

    // The energy lines change only with the size: drawn once to an offscreen canvas, then copied.
    let energyBase = null;
    // The y range hugs the data (rounded to hundreds) so that small differences stay visible.
    const eMax = Math.ceil((Math.max(+w.start_energy || 0, ...m.energy[0], ...m.energy[1]) + 1) / 100) * 100;
    const eMin = Math.max(0, Math.floor(Math.min(...m.energy[0], ...m.energy[1]) / 100) * 100 - 100);
    const L = 34, R = 8, T = 6, BOT = 14;
    function drawEnergy() {
      const W = eCanvas.width, H = eCanvas.height, dpr = g.dpr, cw = W / dpr, ch = H / dpr;
      const ex = (k) => L + (cw - L - R) * k / Math.max(1, n - 1), ey = (v) => T + (ch - T - BOT) * (eMax - v) / (eMax - eMin);
      if (!energyBase) {
        energyBase = document.createElement('canvas');
        energyBase.width = W; energyBase.height = H;
        const c = energyBase.getContext('2d');
        c.setTransform(dpr, 0, 0, dpr, 0, 0);
        c.font = '10px sans-serif'; c.fillStyle = COL.muted; c.strokeStyle = '#3a4048'; c.lineWidth = 1;
        c.textAlign = 'right'; c.textBaseline = 'middle';
        for (const v of [eMin, Math.round((eMin + eMax) / 200) * 100, eMax]) {
          c.beginPath(); c.moveTo(L, ey(v)); c.lineTo(cw - R, ey(v)); c.stroke();
          c.fillText(String(v), L - 4, ey(v));
        }
        c.textAlign = 'left'; c.textBaseline = 'alphabetic';
        c.fillText('0', L, ch - 2); c.textAlign = 'right'; c.fillText(String(n - 1), cw - R, ch - 2);
        for (let s = 0; s < 2; s++) {
          c.beginPath();
          for (let k = 0; k < n; k++) c.lineTo(ex(k), ey(m.energy[s][k]));
          c.strokeStyle = COL.side[s]; c.lineWidth = 1.6; c.stroke();
        }
        for (const e of m.events) {
          if (e[1] !== 'eat' || (e[2] !== 0 && e[2] !== 1)) continue;
          const k = Math.min(n - 1, e[0] + 1);
          c.beginPath(); c.arc(ex(k), ey(m.energy[e[2]][k]), 2.2, 0, 2 * Math.PI); c.fillStyle = COL.food; c.fill();
        }
      }
      eCtx.setTransform(1, 0, 0, 1, 0, 0);
      eCtx.clearRect(0, 0, W, H);
      eCtx.drawImage(energyBase, 0, 0);
      eCtx.setTransform(dpr, 0, 0, dpr, 0, 0);
      eCtx.strokeStyle = '#e8e8e8'; eCtx.lineWidth = 1;
      eCtx.beginPath(); eCtx.moveTo(ex(t), T); eCtx.lineTo(ex(t), ch - BOT); eCtx.stroke();
    }

    function render() {
      const rb = [robot(m, t, 0), robot(m, t, 1)], mask = m.food[t];
      drawBoard(rb, mask);
      drawEnergy();
      const act = panels.map((p) => p(t));
      tLabel.textContent = 'step ' + t + ' / ' + (n - 1) + (t === n - 1 ? ' (final state)' : '');
      scrub.value = String(t);
      let any = false;
      m.events.forEach((e, i) => { const past = e[0] < t; evItems[i].hidden = !past; any = any || past; });
      evNone.hidden = any;
      bPlay.textContent = playing ? '\u275a\u275a pause' : '\u25b6 play';
      lastState = {t, robots: rb, food_mask: mask, act, lit: act.map((a) => (a ? a.map((v) => v > 0.5) : null))};
    }

    function goto(k) { pause(); t = clamp(Math.round(+k) || 0, 0, n - 1); render(); }
    function tick(now) {
      if (!playing) return;
      if (last !== null) {
        acc += Math.min(0.25, (now - last) / 1000) * STEPS_PER_S * SPEEDS[speedIx];
        const k = Math.floor(acc);
        if (k > 0) {
          acc -= k; t = Math.min(n - 1, t + k);
          if (t >= n - 1) playing = false;
          render();
          if (!playing) return;
        }
      }
      last = now;
      raf = requestAnimationFrame(tick);
    }
    function play() {
      if (t >= n - 1) t = 0;
      playing = true; last = null; acc = 0;
      render();
      raf = requestAnimationFrame(tick);
    }
    function pause() { if (playing) { playing = false; cancelAnimationFrame(raf); render(); } }
    function key(e) {
      if (e.ctrlKey || e.metaKey || e.altKey) return false;
      const tag = e.target && e.target.tagName;
      if (tag === 'SELECT' || tag === 'TEXTAREA' || (tag === 'INPUT' && e.target.type !== 'range' && e.target.type !== 'checkbox')) return false;
      const big = e.shiftKey ? 10 : 1;
      switch (e.key) {
        case ' ': playing ? pause() : play(); break;
        case 'ArrowLeft': goto(t - big); break;
        case 'ArrowRight': goto(t + big); break;
        case 'Home': goto(0); break;
        case 'End': goto(n - 1); break;
        case '+': case '=': speedIx = Math.min(SPEEDS.length - 1, speedIx + 1); speedSel.value = String(speedIx); break;
        case '-': case '_': speedIx = Math.max(0, speedIx - 1); speedSel.value = String(speedIx); break;
        default: return false;
      }
      return true;
    }

    // Redraw when the column or the pixel ratio changes (zoom, moving to another screen).
    let seen = '';
    const onResize = () => {
      const k = boardWrap.clientWidth + 'x' + energyWrap.clientWidth + 'x' + window.devicePixelRatio;
      if (k !== seen) { seen = k; layout(); render(); }
    };
    const ro = new ResizeObserver(onResize);
    layout();
    render();
    ro.observe(boardWrap); ro.observe(energyWrap);
    window.addEventListener('resize', onResize);

    return {
      frames: n, goto, key,
      state: () => JSON.parse(JSON.stringify(lastState)),
      pixel(x, y) {
        const i = clamp(Math.floor(px(+x)), 0, g.W - 1), j = clamp(Math.floor(py(+y)), 0, g.W - 1);
        return Array.from(ctx.getImageData(i, j, 1, 1).data);
      },
      destroy() { pause(); ro.disconnect(); window.removeEventListener('resize', onResize); },
    };
  }

  document.addEventListener('keydown', (e) => {
    if (e.key === 'Escape' && overlay) { closeOverlay(); e.preventDefault(); return; }
    if (activeViewer && activeViewer.key(e)) e.preventDefault();
  });
  // A focused button or checkbox acts on space's keyup: the viewer already took that space.
  document.addEventListener('keyup', (e) => {
    const tag = e.target && e.target.tagName;
    if (e.key === ' ' && activeViewer && (tag === 'BUTTON' || (tag === 'INPUT' && e.target.type === 'checkbox'))) e.preventDefault();
  });

  // ---- embedded games: an overlay with the same viewer ---------------------------------------

  let overlay = null, overlayViewer = null, overlayOpener = null, pageViewer = null;
  function openOverlay(d, i, opener) {
    closeOverlay();
    const g = Array.isArray(d.embedded) ? d.embedded[i] : null;
    const close = h('button', {type: 'button', class: 'close', text: 'close \u00d7', title: 'close (Escape)'});
    const holder = h('div');
    const box = h('div', {class: 'overlay-box'}, [h('div', {class: 'overlay-bar'}, [h('h2', {text: g ? clean(g.title) : 'game'}), close]), holder]);
    overlay = h('div', {class: 'overlay', role: 'dialog', 'aria-modal': 'true'}, box);
    overlay.addEventListener('click', (e) => { if (e.target === overlay) closeOverlay(); });
    close.addEventListener('click', closeOverlay);
    document.body.append(overlay);
    document.body.classList.add('noscroll');
    overlayOpener = opener || null;
    close.focus();
    try {
      if (!g || g.kind !== 'duel') throw new Error('embedded game ' + i + ' is not a duel');
      overlayViewer = duelViewer(holder, g);
      activeViewer = overlayViewer;
    } catch (err) {
      holder.append(h('p', {class: 'msg', text: 'This game cannot be shown: ' + err.message}));
    }
  }
  function closeOverlay() {
    if (!overlay) return;
    if (overlayViewer) overlayViewer.destroy();
    overlay.remove();
    document.body.classList.remove('noscroll');
    overlay = overlayViewer = null;
    activeViewer = pageViewer;
    if (overlayOpener) overlayOpener.focus();
  }

  // ---- tables and charts (run and experiment pages) ------------------------------------------

  function table(columns, rows) {
    const tb = h('tbody');
    for (const r of Array.isArray(rows) ? rows : []) tb.append(h('tr', {}, (Array.isArray(r) ? r : []).map((v) => h('td', {text: fmt(v), class: typeof v === 'number' ? 'num' : null}))));
    return h('div', {class: 'scroll'}, h('table', {}, [h('thead', {}, h('tr', {}, (columns || []).map((c) => h('th', {text: clean(c)})))), tb]));
  }
  const col = (tbl, name) => (tbl && Array.isArray(tbl.columns) ? tbl.columns.indexOf(name) : -1);
  function niceStep(raw) {
    const p = Math.pow(10, Math.floor(Math.log10(raw))), f = raw / p;
    return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10) * p;
  }
  function ticks(a, b, k) {
    const st = niceStep((b - a) / k), out = [];
    for (let v = Math.floor(a / st) * st; v <= Math.ceil(b / st) * st + st / 2; v += st) out.push(+v.toPrecision(12));
    return out;
  }
  const PALETTE = ['#4e9ad6', '#ff9f43', '#5cc46a', '#e8615a', '#a987d8', '#b08a74', '#f08fc8', '#a0a0a0', '#cfd45a', '#45cbd8'];

  // series: [{label, color, dash, pts: [[x, y], ...] sorted by x}]. Hover shows the nearest values.
  function lineChart(title, series) {
    const fig = h('figure', {class: 'chart'}, h('figcaption', {text: title}));
    series = series.filter((s) => s.pts.length);
    const all = series.flatMap((s) => s.pts);
    if (!all.length) { fig.append(h('p', {class: 'muted', text: 'no data'})); return fig; }
    const W = 480, H = 210, L = 46, R = 12, T = 10, B = 24;
    let x0 = Math.min(...all.map((p) => p[0])), x1 = Math.max(...all.map((p) => p[0]));
    if (x1 === x0) x1 = x0 + 1;
    const lo = Math.min(0, ...all.map((p) => p[1])), hi = Math.max(0, ...all.map((p) => p[1]));
    const yt = ticks(lo, hi > lo ? hi : lo + 1, 4);
    const y0 = yt[0], y1 = yt[yt.length - 1];
    const X = (v) => L + (W - L - R) * (v - x0) / (x1 - x0), Y = (v) => T + (H - T - B) * (1 - (v - y0) / (y1 - y0));
    const svg = sv('svg', {viewBox: '0 0 ' + W + ' ' + H, class: 'chart-svg', role: 'img', 'aria-label': title});
    for (const v of yt) {
      sv('line', {x1: L, x2: W - R, y1: Y(v), y2: Y(v), class: 'grid'}, svg);
      sv('text', {x: L - 5, y: Y(v) + 3, 'text-anchor': 'end', text: fmt(v)}, svg);
    }
    for (const v of ticks(x0, x1, 5).filter((v) => v >= x0 && v <= x1)) sv('text', {x: X(v), y: H - 6, 'text-anchor': 'middle', text: fmt(v)}, svg);
    const lines = series.map((s) => sv('polyline', {points: s.pts.map((p) => X(p[0]).toFixed(1) + ',' + Y(p[1]).toFixed(1)).join(' '),
      fill: 'none', stroke: s.color, 'stroke-width': 1.4, 'stroke-dasharray': s.dash ? '5 3' : null}, svg));
    const cursor = sv('line', {y1: T, y2: H - B, class: 'cursor', visibility: 'hidden'}, svg);
    const tip = h('div', {class: 'tip', hidden: ''});
    fig.append(h('div', {class: 'chart-area'}, [svg, tip]));
    // Pointing at a legend entry brings its line forward: overlaid runs are otherwise a tangle.
    const focus = (i) => lines.forEach((l, j) => { l.classList.toggle('hi', j === i); l.classList.toggle('dim', i >= 0 && j !== i); });
    fig.append(h('div', {class: 'legend'}, series.map((s, i) => {
      const k = h('i', {class: 'key' + (s.dash ? ' dash' : '')});
      k.style.borderColor = s.color;
      const e = h('span', {}, [k, clean(s.label)]);
      e.addEventListener('pointerenter', () => focus(i));
      e.addEventListener('pointerleave', () => focus(-1));
      return e;
    })));
    const nearest = (pts, x) => {
      let lo = 0, hi = pts.length - 1;
      while (lo < hi) { const mid = (lo + hi) >> 1; if (pts[mid][0] < x) lo = mid + 1; else hi = mid; }
      return lo > 0 && x - pts[lo - 1][0] < pts[lo][0] - x ? pts[lo - 1] : pts[lo];
    };
    svg.addEventListener('pointermove', (e) => {
      const r = svg.getBoundingClientRect(), x = x0 + ((e.clientX - r.left) * W / r.width - L) / (W - L - R) * (x1 - x0);
      const px = nearest(series[0].pts, x)[0];
      cursor.setAttribute('x1', X(px)); cursor.setAttribute('x2', X(px)); cursor.setAttribute('visibility', 'visible');
      tip.replaceChildren(h('div', {text: 'generation ' + fmt(px)}), ...series.map((s) => {
        const p = nearest(s.pts, px);
        const dot = h('i', {class: 'dot'});
        dot.style.background = s.color;
        return h('div', {}, [dot, clean(s.label) + ': ' + (p[0] === px ? fmt(p[1]) : '\u2013')]);
      }));
      tip.hidden = false;
      const cr = fig.getBoundingClientRect(), left = e.clientX - cr.left + 14;
      tip.style.left = (left + 180 > cr.width ? left - 200 : left) + 'px';
      tip.style.top = (e.clientY - cr.top + 10) + 'px';
    });
    svg.addEventListener('pointerleave', () => { tip.hidden = true; cursor.setAttribute('visibility', 'hidden'); });
    return fig;
  }

  function genSeries(gens, column, pop) {
    const gi = col(gens, 'generation'), pi = col(gens, 'population'), ci = col(gens, column);
    if (gi < 0 || ci < 0 || !Array.isArray(gens.rows)) return [];
    return gens.rows.filter((r) => Array.isArray(r) && (pop == null || r[pi] === pop) && typeof r[gi] === 'number' && typeof r[ci] === 'number')
      .map((r) => [r[gi], r[ci]]).sort((a, b) => a[0] - b[0]);
  }
  function populations(gens) {
    const pi = col(gens, 'population');
    return pi < 0 ? [null] : [...new Set(gens.rows.map((r) => r[pi]).filter((p) => typeof p === 'string'))].sort();
  }
  const popColor = (p, i) => (p === 'A' ? COL.side[0] : p === 'B' ? COL.side[1] : PALETTE[i % PALETTE.length]);

  function ladderTable(levels, against, d) {
    against = (Array.isArray(against) ? against : []).map(clean);
    const heads = ['level', 'generation', 'pop.', 'hidden', 'conns'].concat(against, against.length ? ['total'] : [], ['games']);
    const tb = h('tbody');
    for (const lv of Array.isArray(levels) ? levels : []) {
      const tr = h('tr', {}, [lv.level, lv.generation, lv.population, lv.hidden, lv.connections].map((v) => h('td', {text: fmt(v), class: 'num'})));
      const lad = lv.ladder;
      const wl = (w, l) => h('td', {class: 'num', text: lad ? fmt(w) + '\u2013' + fmt(l) : '\u2014'});
      for (const b of against) tr.append(wl(lad && lad.wins && lad.wins[b], lad && lad.losses && lad.losses[b]));
      if (against.length) tr.append(wl(lad && lad.total_wins, lad && lad.total_losses));
      const games = h('td', {class: 'games'});
      for (const gm of Array.isArray(lv.games) ? lv.games : []) {
        const label = clean(gm && gm.label) || 'game';
        if (gm && safeHref(gm.href)) games.append(h('a', {href: gm.href, text: label}));
        else if (gm && Number.isInteger(gm.embed) && Array.isArray(d.embedded) && gm.embed >= 0 && gm.embed < d.embedded.length) {
          const b = h('button', {type: 'button', class: 'link', text: label, title: 'open this game here'});
          b.addEventListener('click', () => openOverlay(d, gm.embed, b));
          games.append(b);
        } else games.append(h('span', {class: 'muted', text: label}));
      }
      tr.append(games);
      tb.append(tr);
    }
    return h('div', {class: 'scroll'}, h('table', {class: 'ladder'}, [h('thead', {}, h('tr', {}, heads.map((c) => h('th', {text: c})))), tb]));
  }

  // ---- pages ----------------------------------------------------------------------------------

  function pageHook(kind, d) {
    // Run and experiment pages: the hook drives the embedded game that is open (open(i) opens one).
    const need = () => { if (!overlayViewer) throw new Error('no game is open'); return overlayViewer; };
    Object.assign(hook, {kind, frames: 0, embedded: Array.isArray(d.embedded) ? d.embedded.length : 0,
      open: (i) => { openOverlay(d, i, null); return overlayViewer ? overlayViewer.frames : 0; }, close: closeOverlay,
      goto: (t) => need().goto(t), state: () => need().state(), pixel: (x, y) => need().pixel(x, y), ready: true});
  }

  function duelPage(app, d) {
    app.append(h('h1', {text: clean(d.title) || 'duel'}));
    const root = h('div', {class: 'duel'});
    app.append(root);
    pageViewer = activeViewer = duelViewer(root, d);
    app.append(h('footer', {class: 'muted small', text: clean(d.generator)}));
    Object.assign(hook, {kind: 'duel', frames: pageViewer.frames, goto: pageViewer.goto, state: pageViewer.state, pixel: pageViewer.pixel});
    hook.ready = true;
  }

  function runPage(app, d) {
    app.append(h('h1', {text: clean(d.title) || 'run'}), h('div', {class: 'muted', text: 'run ' + clean(d.run) + ' \u00b7 ' + clean(d.generator)}));
    const cfg = Array.isArray(d.config) ? d.config : [];
    app.append(h('details', {class: 'config'}, [h('summary', {text: 'configuration (' + cfg.length + ' entries)'}), table(['section', 'key', 'value'], cfg)]));
    const gens = d.generations && Array.isArray(d.generations.rows) ? d.generations : {columns: [], rows: []};
    const pops = populations(gens);
    const per = (column, dash, label) => pops.map((p, i) => ({label: (p || '') + ' ' + label, color: popColor(p, i), dash, pts: genSeries(gens, column, p)}));
    const charts = h('div', {class: 'charts'});
    charts.append(lineChart('best fitness per generation', per('best_fitness', false, 'best')));
    charts.append(lineChart('species per generation', per('species', false, 'species')));
    charts.append(lineChart('connections (mean solid, best dashed)', per('mean_connections', false, 'mean').concat(per('best_connections', true, 'best'))));
    charts.append(lineChart('hidden nodes (mean solid, best dashed)', per('mean_hidden', false, 'mean').concat(per('best_hidden', true, 'best'))));
    const st = d.strength;
    if (st && Array.isArray(st.columns) && Array.isArray(st.rows)) {
      // total_wins when the file has it, else the sum of the per-builtin *_wins columns.
      const gi = col(st, 'generation');
      const total = (suffix) => st.rows.filter((r) => typeof r[gi] === 'number').map((r) => {
        const ti = col(st, 'total' + suffix);
        return [r[gi], ti >= 0 ? +r[ti] : st.columns.reduce((s, c, j) => s + (String(c).endsWith(suffix) && typeof r[j] === 'number' ? r[j] : 0), 0)];
      }).sort((a, b) => a[0] - b[0]);
      charts.append(lineChart('strength: games against the builtins', [
        {label: 'total wins', color: PALETTE[2], pts: total('_wins')}, {label: 'total losses', color: PALETTE[3], dash: true, pts: total('_losses')}]));
    }
    app.append(h('h2', {text: 'evolution'}), charts);
    app.append(h('h2', {text: 'dominance ladder'}), ladderTable(d.levels, d.ladder_against, d));
    pageHook('run', d);
  }

  function experimentPage(app, d) {
    const method = typeof d.method === 'string' ? clean(d.method) : null;
    app.append(h('h1', {text: clean(d.title) || 'experiment'}),
      h('div', {class: 'muted', text: 'experiment ' + clean(d.experiment) + (method ? ' \u00b7 method ' + method : '') + ' \u00b7 ' + clean(d.generator)}));
    if (Array.isArray(d.pages) && d.pages.length) {
      app.append(h('nav', {class: 'pages'}, [h('span', {class: 'muted', text: 'methods: '})].concat(d.pages.map((p) =>
        (p && safeHref(p.href) ? h('a', {href: p.href, text: clean(p.label)}) : h('span', {text: clean(p && p.label)}))))));
    }
    if (d.table1) app.append(h('h2', {text: 'Table 1'}), table(d.table1.columns, d.table1.rows));
    const figs = (Array.isArray(d.figures) ? d.figures : []).filter((f) => f && typeof f.svg === 'string' && /^data:image\/svg\+xml;base64,[A-Za-z0-9+\/]*={0,2}$/.test(f.svg));
    if (figs.length) {
      app.append(h('h2', {text: 'figures'}), h('div', {class: 'figures'}, figs.map((f) =>
        h('figure', {}, [h('img', {src: f.svg, alt: clean(f.caption)}), h('figcaption', {text: clean(f.caption)})]))));
    }
    const runs = Array.isArray(d.runs) ? d.runs.filter((r) => r && typeof r === 'object') : [];
    if (runs.length) {
      // Per run and generation: the population with the higher best fitness, and its best connections.
      const better = runs.map((r) => {
        const g = r.generations || {}, gi = col(g, 'generation'), fi = col(g, 'best_fitness'), ci = col(g, 'best_connections'), by = new Map();
        for (const row of Array.isArray(g.rows) ? g.rows : []) {
          if (typeof row[gi] !== 'number' || typeof row[fi] !== 'number') continue;
          const cur = by.get(row[gi]);
          if (!cur || row[fi] > cur[0]) by.set(row[gi], [row[fi], row[ci]]);
        }
        return [...by.entries()].sort((a, b) => a[0] - b[0]);
      });
      const color = (i) => (runs.length <= PALETTE.length ? PALETTE[i] : 'hsl(' + Math.round(i * 360 / runs.length) + ',65%,62%)');
      const over = (k) => runs.map((r, i) => ({label: clean(r.name), color: color(i),
        pts: better[i].filter((e) => typeof e[1][k] === 'number').map((e) => [e[0], e[1][k]])}));
      app.append(h('h2', {text: 'runs'}), h('div', {class: 'charts'}, [
        lineChart('best fitness (the better population) per generation', over(0)), lineChart('best connections (the better population)', over(1))]));
      for (const r of runs) {
        const n = Array.isArray(r.levels) ? r.levels.length : 0;
        app.append(h('details', {class: 'run'}, [h('summary', {text: clean(r.name) + ': dominance ladder, ' + n + ' levels'}), ladderTable(r.levels, r.ladder_against, d)]));
      }
    }
    pageHook('experiment', d);
  }

  function fail(app, text) {
    app.append(h('p', {class: 'msg', text}));
    Object.assign(hook, {kind: 'error', message: text, ready: true});
  }

  function boot() {
    const app = document.getElementById('app') || document.body;
    let d;
    try {
      d = JSON.parse(document.getElementById('duel-data').textContent);
    } catch (e) {
      return fail(app, 'This page\u2019s data cannot be read (' + e.message + ').');
    }
    if (!d || d.format !== 'neat-duel-page' || d.version !== 1) return fail(app, 'This page\u2019s data is not neat-duel page data of version 1.');
    document.title = (typeof d.title === 'string' && d.title ? clean(d.title) + ' - ' : '') + 'neat-duel';
    try {
      if (d.kind === 'duel') duelPage(app, d);
      else if (d.kind === 'run') runPage(app, d);
      else if (d.kind === 'experiment') experimentPage(app, d);
      else fail(app, 'Unknown page kind \u201c' + clean(d.kind) + '\u201d: this viewer draws duel, run and experiment pages.');
    } catch (e) {
      hook.errors.push(String(e && e.message));
      fail(app, 'This page cannot be drawn: ' + (e && e.message));
    }
  }
  boot();
})();
