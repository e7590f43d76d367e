// The page of `ngc view`: the toolpath in 3D (three.js), the program text beside it, the planner's
// trajectory on a time slider, a summary panel and a measuring tool.  Everything it shows comes
// from the page itself: a JSON block (#ngc-meta), the program text (#ngc-text) and the toolpath's
// arrays in one base64 block (#ngc-data); nothing is fetched from the network.
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";

const KINDS = ["rapid", "feed", "arc", "probe", "sync", "tap", "nurbs", "curve"];
const KIND_COLOURS = [0x8a8f98, 0x2e7dd7, 0x1aa37a, 0xd9822b, 0x8e44ad, 0xc0392b, 0x16a3b8, 0x2e7dd7];
const TOOL_COLOURS = [0x2e7dd7, 0xd9822b, 0x1aa37a, 0xc0392b, 0x8e44ad, 0x16a3b8, 0xb8a019, 0x6d4c41];
const FADED = 0.18; // how much of its colour a segment after the slider keeps
const PICK_PIXELS = 8;

function el(tag, attrs, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === "class") node.className = v;
    else if (k.startsWith("on")) node.addEventListener(k.slice(2), v);
    else node.setAttribute(k, v);
  }
  for (const c of children) node.append(c);
  return node;
}

async function decode(b64) { // base64 of gzip, as the page holds its arrays and text
  const response = await fetch("data:application/octet-stream;base64," + b64);
  const stream = response.body.pipeThrough(new DecompressionStream("gzip"));
  return new Response(stream).arrayBuffer();
}

function clock(seconds) {
  const ms = Math.round(seconds * 1000);
  const h = Math.floor(ms / 3600000), m = Math.floor(ms / 60000) % 60, s = Math.floor(ms / 1000) % 60;
  return `${h}:${String(m).padStart(2, "0")}:${String(s).padStart(2, "0")}.${String(ms % 1000).padStart(3, "0")}`;
}

function rampColour(t) { // blue (slow) .. red (fast)
  const c = new THREE.Color();
  c.setHSL((1 - Math.min(Math.max(t, 0), 1)) * 0.66, 0.85, 0.45);
  return c;
}

class Viewer {
  constructor(meta, text, buffer) {
    this.meta = meta;
    this.lines = text.split("\n");
    if (this.lines.length && this.lines[this.lines.length - 1] === "") this.lines.pop();
    const a = meta.arrays;
    const view = (Type, key) => new Type(buffer, a[key][0], a[key][1]);
    this.points = view(Float32Array, "points");
    this.starts = view(Uint32Array, "starts");
    this.segLine = view(Uint32Array, "line");
    this.segFeed = view(Float32Array, "feed");
    this.segTool = view(Uint16Array, "tool");
    this.segKind = view(Uint8Array, "kind");
    this.lineT0 = view(Float32Array, "line_t0");
    this.lineSpeed = view(Float32Array, "line_speed");
    this.traj = view(Float32Array, "trajectory"); // t, x, y, z, line per sample
    this.count = this.segLine.length;
    this.segStart = new Uint32Array(this.count); // the point each segment starts at
    let s = 0;
    for (let p = 0; p < this.starts.length; p++) {
      const first = this.starts[p], last = p + 1 < this.starts.length ? this.starts[p + 1] : this.points.length / 3;
      for (let i = first; i + 1 < last; i++) this.segStart[s++] = i;
    }
    this.selected = 0;
    this.time = meta.time ? meta.time.total : 0;
    this.playing = false;
    this.rate = 1;
    this.colourBy = "kind";
    this.measuring = false;
    this.measured = [];
  }

  segmentsOf(line) { // (built once, by counting: the segments of each line, in order)
    if (this.lineFirst === undefined) {
      const n = this.count, lines = this.segLine;
      let top = 0;
      for (let i = 0; i < n; i++) if (lines[i] > top) top = lines[i];
      const first = new Uint32Array(top + 2);
      for (let i = 0; i < n; i++) first[lines[i] + 1]++;
      for (let l = 1; l < first.length; l++) first[l] += first[l - 1];
      const fill = first.slice(0, top + 1), order = new Uint32Array(n);
      for (let i = 0; i < n; i++) order[fill[lines[i]]++] = i;
      this.lineFirst = first;
      this.lineOrder = order;
    }
    if (line < 0 || line + 1 >= this.lineFirst.length) return [];
    return Array.from(this.lineOrder.subarray(this.lineFirst[line], this.lineFirst[line + 1]));
  }

  // -- the 3D scene ----------------------------------------------------------------------------
  build(canvasBox) {
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0xfbfbfd);
    canvasBox.append(renderer.domElement);
    this.renderer = renderer;
    this.scene = new THREE.Scene();
    const m = this.meta;
    const size = Math.max(m.size[0], m.size[1], m.size[2], 1e-3);
    this.size = size;
    this.camera = new THREE.PerspectiveCamera(35, 1, size / 1000, size * 1000);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.addEventListener("change", () => this.draw());

    // Two draw calls: the rapids faint (transparent, drawn after the cuts, not hiding them) and
    // the cuts; every segment keeps its place in one array for picking and measuring.
    const n = this.count;
    const positions = new Float32Array(n * 6);
    const P = this.points;
    for (let i = 0; i < n; i++) {
      const a = this.segStart[i] * 3;
      positions.set(P.subarray(a, a + 6), i * 6);
    }
    this.positions = positions;
    let rapids = 0;
    for (let i = 0; i < n; i++) if (this.segKind[i] === 0) rapids++;
    this.slot = new Uint32Array(n);
    const groups = [new Float32Array(rapids * 6), new Float32Array((n - rapids) * 6)];
    const fill = [0, 0];
    for (let i = 0; i < n; i++) {
      const g = this.segKind[i] === 0 ? 0 : 1;
      this.slot[i] = fill[g];
      groups[g].set(positions.subarray(i * 6, i * 6 + 6), fill[g] * 6);
      fill[g]++;
    }
    this.colourSets = [new Float32Array(rapids * 6), new Float32Array((n - rapids) * 6)];
    this.timeUniform = { value: Infinity };
    this.baseColours = new Float32Array(n * 3);
    this.paths = groups.map((pos, g) => {
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute("position", new THREE.BufferAttribute(pos, 3));
      geometry.setAttribute("color", new THREE.BufferAttribute(this.colourSets[g], 3));
      geometry.computeBoundingSphere();
      const times = new Float32Array(pos.length / 3);
      geometry.setAttribute("t0", new THREE.BufferAttribute(times, 1));
      this.timeSets = this.timeSets || [];
      this.timeSets[g] = times;
      const material = g === 0
        ? new THREE.LineBasicMaterial({ vertexColors: true, transparent: true, opacity: 0.35, depthWrite: false })
        : new THREE.LineBasicMaterial({ vertexColors: true });
      this.fadeWithTime(material);
      const lines = new THREE.LineSegments(geometry, material);
      lines.renderOrder = g === 0 ? 1 : 0;
      this.scene.add(lines);
      return lines;
    });

    // (the marks are "transparent" so that they are drawn after the faint rapids, which are)
    this.highlight = new THREE.LineSegments(new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: 0xff1f5a, depthTest: false, transparent: true }));
    this.highlight.renderOrder = 2;
    this.scene.add(this.highlight);

    this.scene.add(this.axes(size));
    this.scene.add(this.extentsBox());
    this.dimensions(canvasBox);
    const marker = new THREE.Mesh(new THREE.SphereGeometry(size / 120, 16, 12),
      new THREE.MeshBasicMaterial({ color: 0xffa000, depthTest: false, transparent: true }));
    marker.renderOrder = 3;
    this.tool = marker;
    this.scene.add(marker);
    if (m.error && m.error.at) {
      const stop = new THREE.Mesh(new THREE.SphereGeometry(size / 90, 16, 12),
        new THREE.MeshBasicMaterial({ color: 0xe01b24, depthTest: false, transparent: true }));
      stop.position.set(...m.error.at);
      stop.renderOrder = 3;
      this.scene.add(stop);
    }
    this.measureLine = new THREE.Line(new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: 0x111111, depthTest: false, transparent: true }));
    this.measureLine.renderOrder = 4;
    this.scene.add(this.measureLine);
    this.recolour();
    this.setView(this.meta.view || "iso");
    new ResizeObserver(() => this.resize()).observe(canvasBox);
    this.resize();
    renderer.domElement.addEventListener("pointerdown", (e) => { this.down = [e.clientX, e.clientY]; });
    renderer.domElement.addEventListener("pointerup", (e) => {
      if (this.down && Math.hypot(e.clientX - this.down[0], e.clientY - this.down[1]) < 4) this.click(e);
    });
  }

  fadeWithTime(material) { // a segment that starts after the slider's time is drawn faded
    material.onBeforeCompile = (shader) => {
      shader.uniforms.uTime = this.timeUniform;
      shader.vertexShader = "attribute float t0;\nuniform float uTime;\n" + shader.vertexShader.replace(
        "#include <color_vertex>",
        `#include <color_vertex>\n#ifdef USE_COLOR\nif (t0 > uTime) vColor.rgb = 1.0 - (1.0 - vColor.rgb) * ${FADED.toFixed(2)};\n#endif`);
    };
  }

  axes(size) {
    const g = new THREE.Group();
    const o = this.meta.origin;
    const len = size * 0.15;
    const at = new THREE.Vector3(-o[0], -o[1], -o[2]); // the machine's origin, in the page's frame
    [[0xd7263d, [1, 0, 0]], [0x1b998b, [0, 1, 0]], [0x2e86de, [0, 0, 1]]].forEach(([c, d]) => {
      const geo = new THREE.BufferGeometry().setFromPoints([at, at.clone().add(new THREE.Vector3(...d).multiplyScalar(len))]);
      g.add(new THREE.Line(geo, new THREE.LineBasicMaterial({ color: c })));
    });
    return g;
  }

  extentsBox() {
    const lo = this.meta.low, hi = this.meta.high, o = this.meta.origin;
    const box = new THREE.Box3(new THREE.Vector3(lo[0] - o[0], lo[1] - o[1], lo[2] - o[2]),
      new THREE.Vector3(hi[0] - o[0], hi[1] - o[1], hi[2] - o[2]));
    const helper = new THREE.Box3Helper(box, 0xc8ccd4);
    return helper;
  }

  resize() {
    const box = this.renderer.domElement.parentElement;
    const w = Math.max(box.clientWidth, 1), h = Math.max(box.clientHeight, 1);
    this.renderer.setSize(w, h, false);
    this.renderer.domElement.style.width = "100%";
    this.renderer.domElement.style.height = "100%";
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.draw();
  }

  setView(name) {
    const dirs = { top: [0, 0, 1], front: [0, -1, 0], side: [1, 0, 0], iso: [1, -1, 0.8], lathe: [0, 1, 0] };
    const d = new THREE.Vector3(...(dirs[name] || dirs.iso)).normalize();
    this.camera.up.set(0, 0, 1);
    if (name === "top") this.camera.up.set(0, 1, 0);
    if (name === "lathe") this.camera.up.set(1, 0, 0);
    const dist = this.size * 0.62 / Math.tan((this.camera.fov * Math.PI) / 360) + this.size / 2;
    this.controls.target.set(0, 0, 0);
    this.camera.position.copy(d.multiplyScalar(dist));
    this.camera.lookAt(0, 0, 0);
    this.controls.update();
    this.draw();
  }

  recolour() {
    const n = this.count, base = this.baseColours, by = this.colourBy;
    const c = new THREE.Color();
    let top = 0;
    if (by === "feed") for (let i = 0; i < n; i++) top = Math.max(top, this.segKind[i] === 0 ? 0 : this.segFeed[i]);
    if (by === "speed") for (let i = 0; i < this.lineSpeed.length; i++) top = Math.max(top, this.lineSpeed[i]);
    for (let i = 0; i < n; i++) {
      const k = this.segKind[i];
      if (k === 0) c.setHex(KIND_COLOURS[0]);
      else if (by === "tool") c.setHex(TOOL_COLOURS[this.segTool[i] % TOOL_COLOURS.length]);
      else if (by === "feed") c.copy(rampColour(top ? this.segFeed[i] / top : 0));
      else if (by === "speed") c.copy(rampColour(top ? (this.lineSpeed[this.segLine[i]] || 0) / top : 0));
      else c.setHex(KIND_COLOURS[k] || KIND_COLOURS[1]);
      base[i * 3] = c.r; base[i * 3 + 1] = c.g; base[i * 3 + 2] = c.b;
    }
    this.legend(by, top);
    this.shade();
  }

  shade() { // the colours, and each segment's start time (the shader fades the later ones)
    const n = this.count, base = this.baseColours;
    const sets = this.colourSets, times = this.timeSets, slot = this.slot, kind = this.segKind;
    const timed = !!this.meta.time;
    for (let i = 0; i < n; i++) {
      const g = kind[i] === 0 ? 0 : 1, out = sets[g], k = slot[i] * 6;
      out[k] = out[k + 3] = base[i * 3];
      out[k + 1] = out[k + 4] = base[i * 3 + 1];
      out[k + 2] = out[k + 5] = base[i * 3 + 2];
      const t0 = timed ? this.lineT0[this.segLine[i]] : 0;
      times[g][slot[i] * 2] = times[g][slot[i] * 2 + 1] = t0 === t0 ? t0 : 0;
    }
    for (const lines of this.paths) {
      lines.geometry.attributes.color.needsUpdate = true;
      lines.geometry.attributes.t0.needsUpdate = true;
    }
    this.draw();
  }

  legend(by, top) {
    const box = document.getElementById("legend");
    box.replaceChildren();
    const swatch = (hex, label) => box.append(el("span", { class: "swatch", style: `background:#${new THREE.Color(hex).getHexString()}` }), el("span", {}, label));
    swatch(KIND_COLOURS[0], "rapid");
    if (by === "kind") {
      const seen = new Set(this.segKind);
      KINDS.forEach((name, k) => { if (k > 0 && seen.has(k)) swatch(KIND_COLOURS[k], name); });
    } else if (by === "tool") {
      [...new Set(this.segTool)].sort((x, y) => x - y).forEach((t) => swatch(TOOL_COLOURS[t % TOOL_COLOURS.length], t ? `T${t}` : "no tool"));
    } else {
      const unit = by === "feed" ? `${this.meta.units}/min` : `${this.meta.units}/s`;
      swatch(rampColour(0).getHex(), "0");
      swatch(rampColour(1).getHex(), `${+top.toFixed(3)} ${unit}`);
    }
  }

  draw() {
    if (!this.renderer || this.pending) return;
    this.pending = true;
    requestAnimationFrame(() => {
      this.pending = false;
      this.drawNow();
    });
  }

  drawNow() {
    this.renderer.render(this.scene, this.camera);
    this.placeDimensions();
  }

  dimensions(box) { // the extents' sizes, as labels on the box's edges
    const m = this.meta;
    this.dimensionLabels = ["X", "Y", "Z"].map((axis, i) => {
      const label = el("div", { class: "dimension" }, `${axis} ${(m.high[i] - m.low[i]).toFixed(3)} ${m.units}`);
      box.append(label);
      return label;
    });
  }

  placeDimensions() {
    if (!this.dimensionLabels) return;
    const m = this.meta, o = m.origin, lo = m.low, hi = m.high;
    const mid = [(lo[0] + hi[0]) / 2 - o[0], (lo[1] + hi[1]) / 2 - o[1], (lo[2] + hi[2]) / 2 - o[2]];
    const at = [[mid[0], lo[1] - o[1], lo[2] - o[2]], [hi[0] - o[0], mid[1], lo[2] - o[2]], [lo[0] - o[0], lo[1] - o[1], mid[2]]];
    const r = this.renderer.domElement.getBoundingClientRect();
    this.dimensionLabels.forEach((label, i) => {
      const [x, y, z] = this.screenOf(...at[i]);
      const visible = z < 1 && hi[i] > lo[i];
      label.hidden = !visible;
      label.style.left = `${x - r.left}px`;
      label.style.top = `${y - r.top}px`;
    });
  }

  // -- picking -----------------------------------------------------------------------------------
  screenOf(x, y, z) {
    const v = new THREE.Vector3(x, y, z).project(this.camera);
    const r = this.renderer.domElement.getBoundingClientRect();
    return [r.left + (v.x + 1) / 2 * r.width, r.top + (1 - v.y) / 2 * r.height, v.z];
  }

  screenOfSegment(i) {
    const p = this.positions;
    return this.screenOf((p[i * 6] + p[i * 6 + 3]) / 2, (p[i * 6 + 1] + p[i * 6 + 4]) / 2, (p[i * 6 + 2] + p[i * 6 + 5]) / 2);
  }

  nearest(cx, cy) { // the segment nearest to a point of the screen, within PICK_PIXELS
    const r = this.renderer.domElement.getBoundingClientRect();
    const m = new THREE.Matrix4().multiplyMatrices(this.camera.projectionMatrix, this.camera.matrixWorldInverse).elements;
    const p = this.positions, n = this.count;
    const px = (cx - r.left) / r.width * 2 - 1, py = 1 - (cy - r.top) / r.height * 2;
    const sx = r.width / 2, sy = r.height / 2;
    let best = -1, bestD = PICK_PIXELS;
    for (let i = 0; i < n; i++) {
      const o = i * 6;
      const w0 = m[3] * p[o] + m[7] * p[o + 1] + m[11] * p[o + 2] + m[15];
      const w1 = m[3] * p[o + 3] + m[7] * p[o + 4] + m[11] * p[o + 5] + m[15];
      if (w0 <= 0 || w1 <= 0) continue;
      const x0 = ((m[0] * p[o] + m[4] * p[o + 1] + m[8] * p[o + 2] + m[12]) / w0 - px) * sx;
      const y0 = ((m[1] * p[o] + m[5] * p[o + 1] + m[9] * p[o + 2] + m[13]) / w0 - py) * sy;
      const x1 = ((m[0] * p[o + 3] + m[4] * p[o + 4] + m[8] * p[o + 5] + m[12]) / w1 - px) * sx;
      const y1 = ((m[1] * p[o + 3] + m[5] * p[o + 4] + m[9] * p[o + 5] + m[13]) / w1 - py) * sy;
      const dx = x1 - x0, dy = y1 - y0, l2 = dx * dx + dy * dy;
      let t = l2 > 0 ? -(x0 * dx + y0 * dy) / l2 : 0;
      t = t < 0 ? 0 : t > 1 ? 1 : t;
      const d = Math.hypot(x0 + t * dx, y0 + t * dy);
      if (d < bestD) { bestD = d; best = i; }
    }
    return best;
  }

  click(e) {
    const i = this.nearest(e.clientX, e.clientY);
    if (this.measuring) {
      if (i >= 0) this.measurePoint(i, e.clientX, e.clientY);
      return;
    }
    if (i >= 0) this.select(this.segLine[i]);
  }

  select(line, scroll = true) {
    this.selected = line;
    const segs = this.segmentsOf(line);
    const pts = new Float32Array(segs.length * 6);
    segs.forEach((s, k) => pts.set(this.positions.subarray(s * 6, s * 6 + 6), k * 6));
    this.highlight.geometry.dispose();
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.BufferAttribute(pts, 3));
    this.highlight.geometry = g;
    this.text.select(line, scroll);
    this.draw();
    return segs.length;
  }

  // -- measure ---------------------------------------------------------------------------------
  measurePoint(i, cx, cy) {
    const p = this.positions, o = i * 6;
    const a = this.screenOf(p[o], p[o + 1], p[o + 2]), b = this.screenOf(p[o + 3], p[o + 4], p[o + 5]);
    const end = Math.hypot(a[0] - cx, a[1] - cy) <= Math.hypot(b[0] - cx, b[1] - cy) ? 0 : 3;
    this.addMeasure([p[o + end], p[o + end + 1], p[o + end + 2]]);
  }

  addMeasure(point) { // a point in the page's frame; two make a measure
    if (this.measured.length === 2) this.measured = [];
    this.measured.push(point);
    const box = document.getElementById("measure-out");
    const o = this.meta.origin, u = this.meta.units;
    if (this.measured.length === 2) {
      const [a, b] = this.measured;
      const d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
      this.measurement = { distance: Math.hypot(...d), dx: d[0], dy: d[1], dz: d[2] };
      box.textContent = `distance ${this.measurement.distance.toFixed(4)} ${u}  ΔX ${d[0].toFixed(4)}  ΔY ${d[1].toFixed(4)}  ΔZ ${d[2].toFixed(4)}`;
      this.measureLine.geometry.dispose();
      this.measureLine.geometry = new THREE.BufferGeometry().setFromPoints(this.measured.map((q) => new THREE.Vector3(...q)));
    } else {
      const q = point;
      box.textContent = `from X${(q[0] + o[0]).toFixed(4)} Y${(q[1] + o[1]).toFixed(4)} Z${(q[2] + o[2]).toFixed(4)}: click a second point`;
      this.measureLine.geometry.dispose();
      this.measureLine.geometry = new THREE.BufferGeometry();
    }
    this.draw();
  }

  // -- time --------------------------------------------------------------------------------------
  sampleAt(t) { // position (page frame) and line of the trajectory at time t
    const T = this.traj, n = T.length / 5;
    if (n === 0) return null;
    let lo = 0, hi = n - 1;
    if (t <= T[0]) hi = 0;
    else if (t >= T[(n - 1) * 5]) lo = hi = n - 1;
    else {
      while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (T[mid * 5] <= t) lo = mid; else hi = mid; }
    }
    const a = lo * 5, b = hi * 5;
    const span = T[b] - T[a], f = span > 0 ? (t - T[a]) / span : 0;
    const o = this.meta.origin;
    return {
      position: [T[a + 1] + (T[b + 1] - T[a + 1]) * f - o[0], T[a + 2] + (T[b + 2] - T[a + 2]) * f - o[1], T[a + 3] + (T[b + 3] - T[a + 3]) * f - o[2]],
      line: T[a + 4],
    };
  }

  setTime(t, follow = true) { // the slider's time: the tool there, its line selected (follow)
    const total = this.meta.time ? this.meta.time.total : 0;
    this.time = Math.min(Math.max(t, 0), total);
    const s = this.sampleAt(this.time);
    if (s) {
      this.tool.position.set(...s.position);
      if (follow && s.line && s.line !== this.selected) this.select(s.line);
    }
    const slider = document.getElementById("slider");
    if (slider && total > 0) slider.value = String(Math.round(this.time / total * 10000));
    const clockBox = document.getElementById("clock");
    if (clockBox) clockBox.textContent = `${clock(this.time)} / ${clock(total)}, ${clock(total - this.time)} left`;
    this.timeUniform.value = this.meta.time && this.time < total ? this.time : Infinity;
    this.draw();
    return s;
  }

  play() {
    if (!this.meta.time) return;
    this.playing = !this.playing;
    document.getElementById("play").textContent = this.playing ? "❚❚" : "▶";
    if (this.time >= this.meta.time.total) this.time = 0;
    let last = performance.now();
    const step = (now) => {
      if (!this.playing) return;
      this.setTime(this.time + (now - last) / 1000 * this.rate);
      last = now;
      if (this.time >= this.meta.time.total) { this.play(); return; }
      requestAnimationFrame(step);
    };
    requestAnimationFrame(step);
  }
}

// -- the program text: only the lines in sight are in the page, so a long program stays light --
class TextPane {
  constructor(box, lines, onPick, errorLine) {
    this.box = box;
    this.lines = lines;
    this.onPick = onPick;
    this.errorLine = errorLine;
    this.height = 18;
    this.selected = 0;
    this.spacer = el("div", { class: "spacer" });
    this.spacer.style.height = `${lines.length * this.height}px`;
    this.rows = el("div", { class: "rows", role: "list" });
    this.spacer.append(this.rows);
    box.append(this.spacer);
    box.addEventListener("scroll", () => this.render());
    new ResizeObserver(() => this.render()).observe(box);
  }

  render() {
    const first = Math.max(0, Math.floor(this.box.scrollTop / this.height) - 5);
    const count = Math.ceil(this.box.clientHeight / this.height) + 10;
    const last = Math.min(this.lines.length, first + count);
    this.rows.style.transform = `translateY(${first * this.height}px)`;
    const nodes = [];
    for (let i = first; i < last; i++) {
      const n = i + 1;
      const row = el("div", { class: "row", role: "listitem", "data-line": String(n) },
        el("span", { class: "num" }, String(n)), el("span", { class: "src" }, this.lines[i]));
      if (n === this.selected) row.setAttribute("aria-current", "true");
      if (n === this.errorLine) row.classList.add("error");
      row.addEventListener("click", () => this.onPick(n));
      nodes.push(row);
    }
    this.rows.replaceChildren(...nodes);
  }

  select(line, scroll) {
    this.selected = line;
    if (scroll) {
      const top = (line - 1) * this.height;
      if (top < this.box.scrollTop || top > this.box.scrollTop + this.box.clientHeight - this.height) {
        this.box.scrollTop = Math.max(0, top - this.box.clientHeight / 3);
      }
    }
    this.render();
  }

  find(query, from) {
    if (!query) return 0;
    const q = query.toLowerCase();
    for (let k = 0; k < this.lines.length; k++) {
      const i = (from + k) % this.lines.length;
      if (this.lines[i].toLowerCase().includes(q)) return i + 1;
    }
    return 0;
  }
}

function summaryPanel(meta) {
  const box = document.getElementById("summary");
  const rows = [];
  const u = meta.units;
  if (meta.time) {
    rows.push(["time", `${clock(meta.time.total)} on ${meta.time.machine}`]);
    for (const [tool, s] of Object.entries(meta.time.by_tool)) rows.push([`  ${tool}`, clock(s)]);
  }
  rows.push(["segments", String(meta.segments)]);
  rows.push(["rapid length", `${meta.lengths.rapid.toFixed(3)} ${u}`]);
  rows.push(["cut length", `${meta.lengths.cut.toFixed(3)} ${u}`]);
  rows.push(["extents (machine)", ["X", "Y", "Z"].map((a, i) => `${a} ${meta.low[i].toFixed(3)} .. ${meta.high[i].toFixed(3)}`).join("  ") + ` ${u}`]);
  for (const t of meta.tools) rows.push([t.name, t.text]);
  for (const w of meta.warnings) rows.push(["warning", w]);
  const table = el("table", {});
  for (const [k, v] of rows) table.append(el("tr", {}, el("th", {}, k), el("td", {}, v)));
  box.append(table);
  if (meta.error) box.append(el("div", { class: "error-box", role: "alert" }, `${meta.error.where}: ${meta.error.message}`));
}

async function main() {
  const meta = JSON.parse(document.getElementById("ngc-meta").textContent);
  const [textBytes, buffer] = await Promise.all([
    decode(document.getElementById("ngc-text").textContent.trim()),
    decode(document.getElementById("ngc-data").textContent.trim())]);
  const text = new TextDecoder("utf-8").decode(textBytes);
  const viewer = new Viewer(meta, text, buffer);
  const textBox = document.getElementById("text");
  viewer.text = new TextPane(textBox, viewer.lines, (line) => viewer.select(line, false), meta.error ? meta.error.line : 0);
  viewer.build(document.getElementById("canvas"));
  summaryPanel(meta);
  viewer.text.render();

  document.getElementById("colour").addEventListener("change", (e) => { viewer.colourBy = e.target.value; viewer.recolour(); });
  for (const name of ["top", "front", "side", "iso"]) document.getElementById(`view-${name}`).addEventListener("click", () => viewer.setView(name));
  document.getElementById("fit").addEventListener("click", () => viewer.setView(meta.view || "iso"));
  const measureButton = document.getElementById("measure");
  const toggleMeasure = () => {
    viewer.measuring = !viewer.measuring;
    measureButton.setAttribute("aria-pressed", String(viewer.measuring));
    document.getElementById("measure-out").textContent = viewer.measuring ? "click a first point" : "";
    viewer.measured = [];
  };
  measureButton.addEventListener("click", toggleMeasure);
  const search = document.getElementById("search");
  search.addEventListener("keydown", (e) => {
    if (e.key === "Enter") {
      const line = viewer.text.find(search.value, viewer.selected);
      if (line) viewer.select(line);
    }
  });
  const slider = document.getElementById("slider");
  if (meta.time) {
    slider.addEventListener("input", () => viewer.setTime(Number(slider.value) / 10000 * meta.time.total));
    document.getElementById("play").addEventListener("click", () => viewer.play());
    document.getElementById("rate").addEventListener("change", (e) => { viewer.rate = Number(e.target.value); });
  } else {
    document.getElementById("player").hidden = true;
  }
  const help = document.getElementById("help");
  document.getElementById("help-button").addEventListener("click", () => { help.hidden = !help.hidden; });
  document.addEventListener("keydown", (e) => {
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
    const keys = { 1: "top", 2: "front", 3: "side", 4: "iso" };
    if (keys[e.key]) viewer.setView(keys[e.key]);
    else if (e.key === "f") viewer.setView(meta.view || "iso");
    else if (e.key === " ") { e.preventDefault(); viewer.play(); }
    else if (e.key === "m") toggleMeasure();
    else if (e.key === "/") { e.preventDefault(); search.focus(); }
    else if (e.key === "?") help.hidden = !help.hidden;
    else if (e.key === "Escape") help.hidden = true;
    else if (e.key === "ArrowDown" || e.key === "ArrowUp") {
      e.preventDefault();
      const next = Math.min(Math.max(1, viewer.selected + (e.key === "ArrowDown" ? 1 : -1)), viewer.lines.length);
      viewer.select(next);
    }
  });
  viewer.setTime(meta.time ? meta.time.total : 0, false);
  if (meta.error) viewer.select(meta.error.line);
  viewer.drawNow();
  return viewer;
}

function watch() { // served by `ngc view --watch`: reload when the program changes
  if (location.protocol !== "http:") return;
  let seen = null;
  setInterval(async () => {
    try {
      const r = await fetch("version", { cache: "no-store" });
      const v = await r.text();
      if (seen !== null && v !== seen) location.reload();
      seen = v;
    } catch (err) { /* the server stopped: keep the page */ }
  }, 500);
}

const ready = main().then((viewer) => {
  Object.assign(window.ngcView, {
    viewer,
    segments: viewer.count,
    lineOfSegment: (i) => viewer.segLine[i],
    segmentsOfLine: (line) => viewer.segmentsOf(line).slice(),
    select: (line) => viewer.select(line),
    selected: () => viewer.selected,
    screenOfSegment: (i) => viewer.screenOfSegment(i).slice(0, 2),
    screenOfPoint: (x, y, z) => viewer.screenOf(x - viewer.meta.origin[0], y - viewer.meta.origin[1], z - viewer.meta.origin[2]).slice(0, 2),
    setView: (name) => viewer.setView(name),
    setTime: (t) => { const s = viewer.setTime(t); viewer.drawNow(); return s && { position: s.position.map((v, k) => v + viewer.meta.origin[k]), line: s.line }; },
    toolPosition: () => viewer.tool.position.toArray().map((v, k) => v + viewer.meta.origin[k]),
    measure: () => viewer.measurement || null,
    colourBy: (name) => { viewer.colourBy = name; document.getElementById("colour").value = name; viewer.recolour(); },
  });
  watch();
  return viewer;
});
window.ngcView = { ready };
