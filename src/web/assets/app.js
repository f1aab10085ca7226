// GarmentCode configurator: controls generated from the design space served at
// /api/schema, the pattern re-evaluated by POST /api/pattern as they move (and its
// box mesh by POST /api/mesh while the 3D view is shown, drawn by view3d.js; the
// drape view is drape.js's, on three.js).
// Plain JS; three.js is vendored: the page works offline from the binary alone.
"use strict";

const DEBOUNCE_MS = 60;

const state = {
  schema: null,          // GET /api/schema
  specs: new Map(),      // path -> parameter spec
  values: {},            // path -> current value
  origin: null,          // the design started from: {label, preset (built-in name or null), values};
                         // changed values are marked against it, Reset returns to it
  name: "garment",       // pattern name (file names)
  layout: "placed",      // drawing: "placed" (as on the body) or "flat" (to cut)
  bodyBase: null,        // built-in body the measurements started from
  bodyLabel: null,       // what the body select shows ("custom" after edits)
  measurements: {},      // name -> number (or null for an absent optional one)
  seq: 0,                // id of the latest evaluation request
  timer: null,           // pending first request of a burst of changes
  dirty: false,          // changes not yet sent
  inflight: false,       // a request is on its way
  lastGood: false,       // a drawing is on screen
  view: null,            // current view box [x, y, w, h] (null: fit)
  fitBox: null,          // view box of the whole pattern
  mode: "2d",            // view shown: "2d" (the drawing) or "3d" (the box mesh)
  mesh3d: undefined,     // the 3D view (MeshView; null without WebGL; undefined until first shown)
  meshSeq: 0,            // id of the latest mesh request
  meshStale: true,       // the 3D view does not show the latest pattern
};

const $ = (id) => document.getElementById(id);

// ---------------------------------------------------------------------------
// Server calls

async function api(method, path, body) {
  const opts = { method, headers: {} };
  if (body !== undefined) {
    opts.headers["Content-Type"] = "application/json";
    opts.body = JSON.stringify(body);
  }
  let res;
  try {
    res = await fetch(path, opts);
  } catch (e) {
    throw new ApiError(["the server cannot be reached (is `garmentcode serve` still running?)"], 0);
  }
  const type = res.headers.get("Content-Type") || "";
  if (!type.startsWith("application/json")) {
    if (!res.ok) throw new ApiError([`${res.status} ${res.statusText}`], res.status);
    return res.blob();
  }
  const data = await res.json();
  if (!res.ok) throw new ApiError(data.problems && data.problems.length ? data.problems : [data.error || res.statusText], res.status);
  return data;
}

class ApiError extends Error {
  constructor(problems, status) {
    super(problems.join("; "));
    this.problems = problems;
    this.status = status;
  }
}

function requestBody() {
  return {
    design: state.values,
    body: { base: state.bodyBase, name: state.bodyLabel, measurements: state.measurements },
    name: state.name,
    layout: state.layout,
  };
}

// ---------------------------------------------------------------------------
// Formatting

function optionLabel(v) {
  return v === null ? "none" : String(v);
}

function fmt(x) {
  if (typeof x !== "number") return String(x);
  return String(Number(x.toFixed(4)));
}

function niceStep(lo, hi, isInt) {
  if (isInt) return 1;
  const raw = (hi - lo) / 100;
  return Math.pow(10, Math.floor(Math.log10(raw)));
}

function sameValue(a, b) {
  if (typeof a === "number" && typeof b === "number") return Math.abs(a - b) < 1e-12;
  return a === b;
}

function safeName(text) {
  const s = text.replace(/\.[^.]*$/, "").replace(/[^A-Za-z0-9_.-]+/g, "_").replace(/^[._]+/, "").slice(0, 64);
  return s || "garment";
}

// ---------------------------------------------------------------------------
// Design controls, generated from the schema

function buildControls() {
  const root = $("groups");
  root.textContent = "";
  const tops = new Map(); // top-level group -> {details, body, subs: Map}
  for (const spec of state.schema.params) {
    state.specs.set(spec.path, spec);
    const parts = spec.group ? spec.group.split(".") : ["(design)"];
    const top = parts[0];
    if (!tops.has(top)) {
      const details = document.createElement("details");
      details.className = "group";
      details.dataset.group = top;
      if (top === "meta") details.open = true;
      const summary = document.createElement("summary");
      summary.innerHTML = `<span class="gname"></span> <span class="changed-count"></span>`;
      summary.querySelector(".gname").textContent = top;
      details.append(summary);
      const body = document.createElement("div");
      body.className = "group-body";
      details.append(body);
      root.append(details);
      tops.set(top, { details, body, subs: new Map() });
    }
    const g = tops.get(top);
    let container = g.body;
    if (parts.length > 1) {
      const sub = parts.slice(1).join(".");
      if (!g.subs.has(sub)) {
        const fs = document.createElement("fieldset");
        fs.className = "subgroup";
        fs.dataset.group = spec.group;
        const legend = document.createElement("legend");
        legend.textContent = sub;
        fs.append(legend);
        g.body.append(fs);
        g.subs.set(sub, fs);
      }
      container = g.subs.get(sub);
    }
    container.append(makeControl(spec));
  }
}

function makeControl(spec) {
  const row = document.createElement("div");
  row.className = "param";
  row.dataset.path = spec.path;
  row.dataset.type = spec.type;
  const id = "p-" + spec.path;
  const range = spec.range ? `[${spec.range[0]}, ${spec.range[1]}]` : "one of " + spec.options.map(optionLabel).join(", ");
  const prob = spec.default_prob === null ? "" : `; kept at its default by ${Math.round(spec.default_prob * 100)}% of random designs`;
  row.title = `${spec.path} (${spec.type}, ${range}; design-space default ${optionLabel(spec.default)}${prob})\n${spec.description}\nDouble-click the name to return to the value of the design you started from.`;

  const head = document.createElement("div");
  head.className = "phead";
  const label = document.createElement("label");
  label.htmlFor = id;
  label.textContent = spec.name;
  label.addEventListener("dblclick", () => setValue(spec.path, originValue(spec.path), true));
  head.append(label);
  row.append(head);

  const ctl = document.createElement("div");
  ctl.className = "pctl";
  if (spec.type === "float" || spec.type === "int") {
    const [lo, hi] = spec.range;
    const step = niceStep(lo, hi, spec.type === "int");
    const slider = document.createElement("input");
    slider.type = "range";
    slider.id = id;
    slider.min = lo;
    slider.max = hi;
    slider.step = step;
    const num = document.createElement("input");
    num.type = "number";
    num.className = "num";
    num.min = lo;
    num.max = hi;
    num.step = spec.type === "int" ? 1 : "any";
    num.setAttribute("aria-label", spec.path);
    slider.addEventListener("input", () => setValue(spec.path, Number(slider.value), false));
    num.addEventListener("change", () => {
      const x = Number(num.value);
      if (num.value === "" || !Number.isFinite(x)) { refresh(spec.path); return; }
      setValue(spec.path, x, true);
    });
    ctl.append(slider, num);
  } else if (spec.type === "bool") {
    const sw = document.createElement("input");
    sw.type = "checkbox";
    sw.id = id;
    sw.className = "switch";
    sw.setAttribute("role", "switch");
    sw.addEventListener("change", () => setValue(spec.path, sw.checked, false));
    ctl.append(sw);
  } else {
    const sel = document.createElement("select");
    sel.id = id;
    spec.options.forEach((o, i) => {
      const opt = document.createElement("option");
      opt.value = String(i);
      opt.textContent = optionLabel(o);
      sel.append(opt);
    });
    sel.addEventListener("change", () => setValue(spec.path, spec.options[Number(sel.value)], false));
    ctl.append(sel);
  }
  row.append(ctl);

  const desc = document.createElement("div");
  desc.className = "desc";
  desc.textContent = spec.description;
  row.append(desc);
  return row;
}

// Show the current value of `path` in its control.
function refresh(path) {
  const spec = state.specs.get(path);
  const row = document.querySelector(`.param[data-path="${CSS.escape(path)}"]`);
  if (!spec || !row) return;
  const v = state.values[path];
  if (spec.type === "float" || spec.type === "int") {
    row.querySelector("input[type=range]").value = v;
    row.querySelector("input.num").value = fmt(v);
  } else if (spec.type === "bool") {
    row.querySelector("input").checked = v === true;
  } else {
    const i = spec.options.findIndex((o) => sameValue(o, v));
    row.querySelector("select").value = String(Math.max(i, 0));
  }
  row.classList.toggle("changed", !sameValue(v, originValue(path)));
}

// The value of `path` in the design started from (the design space's default
// before one is loaded).
function originValue(path) {
  const o = state.origin;
  return o && path in o.values ? o.values[path] : state.specs.get(path).default;
}

// Start from `values` (a built-in design, a random one, a file): the controls
// show them, nothing is marked changed, Reset comes back here.
function startFrom(label, preset, values) {
  state.origin = { label, preset, values: { ...values } };
  state.values = { ...values };
  state.view = null; // another garment: fit it
  refreshAll();
  schedule();
}

function refreshAll() {
  for (const path of state.specs.keys()) refresh(path);
  updateChangedCounts();
}

function updateChangedCounts() {
  for (const details of document.querySelectorAll("details.group")) {
    const n = details.querySelectorAll(".param.changed").length;
    details.querySelector(".changed-count").textContent = n ? `${n} changed` : "";
  }
  showOrigin();
}

// "Start from" shows the built-in design the current one is, or what it came
// from and whether it was edited since.
function showOrigin() {
  const o = state.origin;
  const ds = $("design-select");
  if (!o || !ds.options.length) return;
  const edited = document.querySelector(".param.changed") !== null;
  ds.dataset.edited = String(edited);
  ds.options[0].textContent = o.preset && !edited ? "(custom)" : edited ? `${o.label} (edited)` : o.label;
  ds.value = o.preset && !edited ? o.preset : "";
  $("reset").disabled = !edited;
}

function setValue(path, v, redraw) {
  state.values[path] = v;
  if (redraw) refresh(path);
  else {
    const spec = state.specs.get(path);
    const row = document.querySelector(`.param[data-path="${CSS.escape(path)}"]`);
    if (spec.type === "float" || spec.type === "int") row.querySelector("input.num").value = fmt(v);
    row.classList.toggle("changed", !sameValue(v, originValue(path)));
  }
  updateChangedCounts();
  schedule();
}

function applyFilter() {
  const q = $("filter").value.trim().toLowerCase();
  for (const row of document.querySelectorAll(".param")) {
    const spec = state.specs.get(row.dataset.path);
    const hit = !q || spec.path.toLowerCase().includes(q) || spec.description.toLowerCase().includes(q);
    row.hidden = !hit;
  }
  for (const fs of document.querySelectorAll("fieldset.subgroup")) {
    fs.hidden = !fs.querySelector(".param:not([hidden])");
  }
  for (const details of document.querySelectorAll("details.group")) {
    const any = details.querySelector(".param:not([hidden])");
    details.hidden = !any;
    if (q && any) details.open = true;
  }
}

// ---------------------------------------------------------------------------
// Body tab

function buildBodyControls() {
  const root = $("measurements");
  root.textContent = "";
  for (const m of state.schema.measurements) {
    const row = document.createElement("div");
    row.className = "measure";
    row.dataset.name = m.name;
    row.title = `${m.name} (${m.unit}, plausible ${m.min} to ${m.max}${m.optional ? ", optional" : ""})\n${m.description}`;
    const label = document.createElement("label");
    label.htmlFor = "m-" + m.name;
    label.textContent = m.name;
    const input = document.createElement("input");
    input.type = "number";
    input.id = "m-" + m.name;
    input.step = "any";
    const unit = document.createElement("span");
    unit.className = "unit";
    const problem = document.createElement("div");
    problem.className = "problem";
    problem.setAttribute("role", "status");
    // Range check as you type; the value is taken when it is plausible.
    input.addEventListener("input", () => checkMeasure(m, input, problem));
    input.addEventListener("change", () => {
      if (input.value === "" && m.optional) state.measurements[m.name] = null;
      else if (!checkMeasure(m, input, problem)) return;
      else state.measurements[m.name] = toCm(m, Number(input.value));
      state.bodyLabel = "custom";
      $("body-select").value = "";
      schedule();
    });
    const desc = document.createElement("div");
    desc.className = "desc";
    desc.textContent = m.description;
    // How to take it: the guide's sentence and figure, loaded when opened.
    const how = document.createElement("details");
    how.className = "how";
    how.innerHTML = `<summary>how to measure</summary><p></p>`;
    how.querySelector("p").textContent = m.how || "";
    how.addEventListener("toggle", () => {
      if (how.open && !how.querySelector("img")) {
        const img = document.createElement("img");
        img.alt = `Where the tape goes for ${m.name}`;
        img.src = "/api/guide/" + encodeURIComponent(m.name) + ".svg";
        how.append(img);
      }
    });
    row.append(label, input, unit, problem, desc, how);
    root.append(row);
  }
  showUnits();
  const droot = $("derived");
  droot.textContent = "";
  for (const d of state.schema.derived) {
    const row = document.createElement("div");
    row.className = "measure derived";
    row.dataset.name = d.name;
    row.title = d.description;
    row.innerHTML = `<span class="dname"></span><output></output><div class="desc"></div>`;
    row.querySelector(".dname").textContent = d.name;
    row.querySelector(".desc").textContent = d.description;
    droot.append(row);
  }
}

// Lengths are shown in the chosen unit; the state, files and API stay in cm.
function inches(m) { return m.unit === "cm" && $("body-units").value === "in"; }
function toCm(m, v) { return inches(m) ? v * 2.54 : v; }
function fromCm(m, v) { return inches(m) ? v / 2.54 : v; }

// Marks a measurement outside its plausible range while it is typed; true when it may be taken.
function checkMeasure(m, input, problem) {
  const shown = inches(m) ? "in" : m.unit === "deg" ? "°" : m.unit;
  const [lo, hi] = [fromCm(m, m.min), fromCm(m, m.max)].map((x) => Number(x.toFixed(2)));
  let msg = "";
  if (input.value === "") msg = m.optional ? "" : "required";
  else if (!Number.isFinite(Number(input.value))) msg = "not a number";
  else if (toCm(m, Number(input.value)) < m.min || toCm(m, Number(input.value)) > m.max) msg = `outside the plausible ${lo} to ${hi} ${shown}`;
  problem.textContent = msg;
  input.setAttribute("aria-invalid", msg ? "true" : "false");
  input.closest(".measure").classList.toggle("invalid", msg !== "");
  return msg === "" && input.value !== "";
}

function showUnits() {
  for (const m of state.schema.measurements) {
    const input = $("m-" + m.name);
    input.min = Number(fromCm(m, m.min).toFixed(2));
    input.max = Number(fromCm(m, m.max).toFixed(2));
    input.closest(".measure").querySelector(".unit").textContent = inches(m) ? "in" : m.unit === "deg" ? "°" : m.unit;
  }
  showBody();
}

function showBody(derived) {
  for (const [name, v] of Object.entries(state.measurements)) {
    const input = $("m-" + name);
    const m = state.schema.measurements.find((x) => x.name === name);
    if (input && m) {
      input.value = v === null ? "" : fmt(Number(fromCm(m, v).toFixed(3)));
      checkMeasure(m, input, input.closest(".measure").querySelector(".problem"));
    }
  }
  if (derived) {
    for (const [name, v] of Object.entries(derived)) {
      const out = document.querySelector(`.derived[data-name="${CSS.escape(name)}"] output`);
      if (out) out.textContent = fmt(v);
    }
  }
}

async function loadBody(name) {
  const b = await api("GET", "/api/body/" + encodeURIComponent(name));
  state.bodyBase = name;
  state.bodyLabel = name;
  state.measurements = b.measurements;
  $("body-select").value = name;
  showBody(b.derived);
}

// ---------------------------------------------------------------------------
// Evaluation and drawing

// A change marks the design dirty; one request is in flight at a time, and when
// it returns while more changes came in, the latest state is sent at once. So a
// dragged slider redraws continuously, at the server's pace, and the last
// answer shown is always for the last state.
function schedule() {
  state.dirty = true;
  setBusy(true);
  setStatus("busy", "Updating…");
  if (state.inflight) return;
  clearTimeout(state.timer);
  state.timer = setTimeout(evaluate, DEBOUNCE_MS);
}

function setBusy(busy) {
  $("status").dataset.idle = busy ? "false" : "true";
}

async function evaluate() {
  state.dirty = false;
  state.inflight = true;
  const seq = ++state.seq;
  const t0 = performance.now();
  try {
    let res;
    try {
      res = await api("POST", "/api/pattern", requestBody());
    } catch (e) {
      if (seq === state.seq) showProblems("The server refused these values", e.problems, "error");
      return;
    }
    if (seq !== state.seq) return;
    if (res.body && res.body.derived) showBody(res.body.derived);
    if (!res.ok) {
      showProblems("This design cannot be built", [res.error], "rejected");
      return;
    }
    showDrawing(res.svg);
    $("overlay").hidden = true;
    state.meshStale = true;
    if (state.mode === "3d") await loadMesh();
    if (state.mode === "drape") window.drapeView.restart(drapeRequest());
    const ms = Math.round(performance.now() - t0);
    const summary = `${res.panels.length} panels · ${res.stitches} stitches · ${ms} ms`;
    setStatus(res.warnings.length ? "warning" : "ok", res.warnings.length ? `${summary} · ${res.warnings.length} warning(s)` : summary);
    $("status").title = "Panels: " + res.panels.join(", ");
    showWarnings(res.warnings);
  } finally {
    state.inflight = false;
    if (state.dirty) evaluate();
    else setBusy(false);
  }
}

function setStatus(kind, text) {
  const s = $("status");
  s.dataset.state = kind;
  s.textContent = text;
}

function showWarnings(list) {
  const ul = $("warnings");
  ul.textContent = "";
  for (const w of list) {
    const li = document.createElement("li");
    li.textContent = w;
    ul.append(li);
  }
  ul.hidden = list.length === 0;
}

function showProblems(title, problems, kind) {
  $("overlay-title").textContent = title;
  const ul = $("overlay-problems");
  ul.textContent = "";
  for (const p of problems) {
    const li = document.createElement("li");
    li.textContent = p;
    ul.append(li);
  }
  $("overlay-note").textContent = state.lastGood
    ? "The drawing shows the last design that could be built."
    : "Change a value, pick a built-in design or press Random to get a pattern.";
  $("overlay").hidden = false;
  $("stage").classList.toggle("stale", state.lastGood);
  setStatus(kind, kind === "rejected" ? "Rejected: " + problems[0] : "Refused: " + problems.join("; "));
  showWarnings([]);
}

function showDrawing(svgText) {
  const doc = new DOMParser().parseFromString(svgText, "image/svg+xml");
  const svg = doc.documentElement;
  if (svg.nodeName !== "svg") return;
  const box = (svg.getAttribute("viewBox") || "0 0 100 100").split(/[\s,]+/).map(Number);
  svg.removeAttribute("width");
  svg.removeAttribute("height");
  svg.setAttribute("preserveAspectRatio", "xMidYMid meet");
  const host = $("drawing");
  host.replaceChildren(document.importNode(svg, true));
  state.fitBox = box;
  applyView();
  state.lastGood = true;
  $("stage").classList.remove("stale");
  host.dataset.version = String(Number(host.dataset.version) + 1);
}

// Zoom and pan act on the SVG's view box (centimetres), so they survive redraws.
function applyView() {
  const svg = $("drawing").querySelector("svg");
  if (!svg || !state.fitBox) return;
  const b = state.view || state.fitBox;
  svg.setAttribute("viewBox", b.map((x) => x.toFixed(3)).join(" "));
}

function zoom(factor, cx, cy) {
  const svg = $("drawing").querySelector("svg");
  if (!svg || !state.fitBox) return;
  const b = (state.view || fittedBox(svg)).slice();
  const px = cx === undefined ? b[0] + b[2] / 2 : cx;
  const py = cy === undefined ? b[1] + b[3] / 2 : cy;
  const w = b[2] * factor, h = b[3] * factor;
  state.view = [px - (px - b[0]) * factor, py - (py - b[1]) * factor, w, h];
  applyView();
}

// The view box as displayed (the element's aspect ratio, centred), in cm.
function fittedBox(svg) {
  const [x, y, w, h] = state.fitBox;
  const r = svg.getBoundingClientRect();
  if (!r.width || !r.height) return state.fitBox.slice();
  const s = Math.max(w / r.width, h / r.height);
  const W = r.width * s, H = r.height * s;
  return [x - (W - w) / 2, y - (H - h) / 2, W, H];
}

function toSheet(svg, clientX, clientY) {
  const r = svg.getBoundingClientRect();
  const b = state.view || fittedBox(svg);
  const s = Math.max(b[2] / r.width, b[3] / r.height);
  const ox = b[0] + b[2] / 2 - (r.width * s) / 2, oy = b[1] + b[3] / 2 - (r.height * s) / 2;
  return [ox + (clientX - r.left) * s, oy + (clientY - r.top) * s, s];
}

function setupZoom() {
  const host = $("drawing");
  host.addEventListener("wheel", (ev) => {
    const svg = host.querySelector("svg");
    if (!svg) return;
    ev.preventDefault();
    const [x, y] = toSheet(svg, ev.clientX, ev.clientY);
    zoom(ev.deltaY > 0 ? 1.15 : 1 / 1.15, x, y);
  }, { passive: false });
  let drag = null;
  host.addEventListener("pointerdown", (ev) => {
    const svg = host.querySelector("svg");
    if (!svg) return;
    drag = { x: ev.clientX, y: ev.clientY, box: (state.view || fittedBox(svg)).slice(), scale: toSheet(svg, ev.clientX, ev.clientY)[2] };
    host.setPointerCapture(ev.pointerId);
    host.classList.add("dragging");
  });
  host.addEventListener("pointermove", (ev) => {
    if (drag) {
      const dx = (ev.clientX - drag.x) * drag.scale, dy = (ev.clientY - drag.y) * drag.scale;
      state.view = [drag.box[0] - dx, drag.box[1] - dy, drag.box[2], drag.box[3]];
      applyView();
      return;
    }
    const g = ev.target.closest && ev.target.closest("g[id]");
    const tip = $("panel-tip");
    if (g && g.parentNode && g.parentNode.classList && g.parentNode.classList.contains("panels")) {
      tip.textContent = g.id;
      const r = $("stage").getBoundingClientRect();
      tip.style.left = ev.clientX - r.left + 12 + "px";
      tip.style.top = ev.clientY - r.top + 12 + "px";
      tip.hidden = false;
    } else tip.hidden = true;
  });
  const end = () => { drag = null; host.classList.remove("dragging"); };
  host.addEventListener("pointerup", end);
  host.addEventListener("pointercancel", end);
  host.addEventListener("pointerleave", () => { $("panel-tip").hidden = true; });
  host.addEventListener("dblclick", () => { state.view = null; applyView(); });
  // The view shown: the drawing, the box mesh, or the drape.
  const shown = () => (state.mode === "3d" && state.mesh3d ? state.mesh3d : state.mode === "drape" ? window.drapeView : null);
  $("zoom-in").addEventListener("click", () => (shown() ? shown().zoom(1 / 1.3) : zoom(1 / 1.3)));
  $("zoom-out").addEventListener("click", () => (shown() ? shown().zoom(1.3) : zoom(1.3)));
  $("zoom-fit").addEventListener("click", () => {
    if (shown()) shown().fit();
    else { state.view = null; applyView(); }
  });
}

// ---------------------------------------------------------------------------
// 3D view

function selectView(mode) {
  const was = state.mode;
  state.mode = mode;
  for (const m of ["2d", "3d", "drape"]) $("show-" + m).setAttribute("aria-selected", String(m === mode));
  $("drawing").hidden = mode !== "2d";
  $("view3d").hidden = mode !== "3d";
  $("drape-view").hidden = mode !== "drape";
  $("layout").hidden = mode !== "2d";
  $("show-stitches").parentElement.hidden = mode === "drape";
  $("panel-tip").hidden = true;
  // The drape view (drape.js, a module: loaded by the time a user clicks).
  if (was === "drape" && mode !== "drape") window.drapeView.hide();
  if (mode === "drape" && was !== "drape") window.drapeView.show(drapeRequest());
  if (mode !== "3d") return;
  if (state.mesh3d === undefined) {
    try {
      state.mesh3d = MeshView.create($("mesh3d"));
    } catch (e) {
      state.mesh3d = null;
    }
    $("mesh3d").dataset.webgl = state.mesh3d ? "yes" : "no";
    if (!state.mesh3d) {
      showMeshMessage("The 3D view needs WebGL, which this browser does not provide or has turned off. The 2D view works without it.");
      return;
    }
    state.mesh3d.setSeams($("show-stitches").checked);
  }
  if (state.meshStale && state.lastGood) loadMesh();
}

// POST /api/drape's body: the current design and body.
function drapeRequest() {
  const { layout, ...request } = requestBody();
  return request;
}

function showMeshMessage(text) {
  const p = $("mesh3d-message");
  p.textContent = text || "";
  p.hidden = !text;
}

// The box mesh of the current state; only the latest request's answer is shown.
async function loadMesh() {
  if (!state.mesh3d) return;
  const seq = ++state.meshSeq;
  const { layout, ...request } = requestBody();
  let res;
  try {
    res = await api("POST", "/api/mesh", request);
  } catch (e) {
    if (seq === state.meshSeq) showMeshMessage("The 3D view cannot be updated: " + e.problems.join("; "));
    return;
  }
  if (seq !== state.meshSeq) return;
  state.meshStale = false;
  if (!res.ok) {
    showMeshMessage("No 3D view of this pattern: " + res.error);
    return;
  }
  showMeshMessage("");
  state.mesh3d.setMesh(res);
  const legend = $("mesh3d-legend");
  legend.textContent = "";
  for (const { name, color } of state.mesh3d.legend) {
    const li = document.createElement("li");
    const swatch = document.createElement("span");
    swatch.className = "swatch";
    swatch.style.background = `rgb(${color.map((x) => Math.round(x * 255)).join(",")})`;
    li.append(swatch, name);
    legend.append(li);
  }
  $("mesh3d-info").textContent =
    `Box mesh at ${res.resolution} cm: ${res.vertices} vertices, ${res.faces} triangles, stitched edges joined · drag to rotate, wheel to zoom, double-click to reset`;
  const c = $("mesh3d");
  c.dataset.vertices = String(res.vertices);
  c.dataset.faces = String(res.faces);
  c.dataset.version = String(Number(c.dataset.version) + 1);
}

// ---------------------------------------------------------------------------
// Buttons

async function loadDesign(name) {
  const d = await api("GET", "/api/design/" + encodeURIComponent(name));
  state.name = safeName(name);
  startFrom(name, name, d.design);
}

function reset() {
  const o = state.origin;
  if (o) startFrom(o.label, o.preset, o.values);
}

async function randomDesign() {
  const seedInput = $("seed");
  const seed = Math.max(0, Math.floor(Number(seedInput.value) || 0));
  setStatus("busy", `Drawing a random design (seed ${seed})…`);
  try {
    const r = await api("POST", "/api/random", { seed, body: requestBody().body });
    if (!r.ok) { showProblems("No random design", [r.error], "rejected"); return; }
    state.name = "random_" + seed;
    startFrom(`random (seed ${seed})`, null, r.design);
  } catch (e) {
    showProblems("The server refused the request", e.problems, "error");
  }
  seedInput.value = String(seed + 1);
}

function download(name, blob) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

async function downloadFile(file, type) {
  try {
    const r = await api("POST", "/api/files", requestBody());
    const text = r.files[file];
    if (text === undefined) {
      showProblems(`No ${file}: the design cannot be built`, [r.error], "rejected");
      return;
    }
    download(file, new Blob([text], { type }));
  } catch (e) {
    showProblems("The server refused these values", e.problems, "error");
  }
}

async function downloadZip() {
  try {
    const blob = await api("POST", "/api/zip", requestBody());
    download(state.name + ".zip", blob);
  } catch (e) {
    showProblems("The server refused these values", e.problems, "error");
  }
}

async function upload(file) {
  const text = await file.text();
  try {
    if (/^body\s*:/m.test(text)) {
      const b = await api("POST", "/api/body", { body: { yaml: text, name: safeName(file.name) } });
      state.measurements = b.measurements;
      state.bodyLabel = b.name;
      $("body-select").value = "";
      showBody(b.derived);
      selectTab("body");
      schedule();
    } else {
      const d = await api("POST", "/api/design", { design: text });
      state.name = safeName(file.name);
      startFrom(file.name, null, d.design);
    }
  } catch (e) {
    showProblems(`${file.name} cannot be used`, e.problems, "error");
  }
}

function selectTab(which) {
  for (const t of ["design", "body"]) {
    $("tab-" + t).setAttribute("aria-selected", String(t === which));
    $(t + "-panel").hidden = t !== which;
  }
}

// ---------------------------------------------------------------------------
// Start

async function main() {
  setupZoom();
  try {
    state.schema = await api("GET", "/api/schema");
  } catch (e) {
    showProblems("The design space cannot be loaded", e.problems, "error");
    return;
  }
  buildControls();
  buildBodyControls();
  const ds = $("design-select");
  ds.append(new Option("(custom)", ""));
  for (const d of state.schema.designs) {
    const o = new Option(d.name, d.name);
    o.title = d.description;
    ds.append(o);
  }
  const bs = $("body-select");
  bs.append(new Option("(custom)", ""));
  for (const b of state.schema.bodies) bs.append(new Option(b, b));

  ds.addEventListener("change", () => { if (ds.value) loadDesign(ds.value).catch((e) => showProblems("Cannot load the design", e.problems, "error")); });
  bs.addEventListener("change", () => { if (bs.value) loadBody(bs.value).then(schedule, (e) => showProblems("Cannot load the body", e.problems, "error")); });
  $("reset").addEventListener("click", reset);
  $("random").addEventListener("click", randomDesign);
  $("upload-button").addEventListener("click", () => $("upload").click());
  $("upload").addEventListener("change", (ev) => {
    const f = ev.target.files[0];
    if (f) upload(f).finally(() => { ev.target.value = ""; });
  });
  $("download-design").addEventListener("click", () => downloadFile("design_params.yaml", "application/x-yaml"));
  $("download-body").addEventListener("click", () => downloadFile("body_measurements.yaml", "application/x-yaml"));
  $("download-spec").addEventListener("click", () => downloadFile("specification.json", "application/json"));
  $("download-svg").addEventListener("click", () => downloadFile("pattern.svg", "image/svg+xml"));
  $("download-zip").addEventListener("click", downloadZip);
  $("filter").addEventListener("input", applyFilter);
  $("show-stitches").addEventListener("change", (ev) => {
    $("drawing").classList.toggle("hide-stitches", !ev.target.checked);
    if (state.mesh3d) state.mesh3d.setSeams(ev.target.checked);
  });
  $("show-2d").addEventListener("click", () => selectView("2d"));
  $("show-3d").addEventListener("click", () => selectView("3d"));
  $("show-drape").addEventListener("click", () => selectView("drape"));
  $("layout").addEventListener("change", (ev) => { state.layout = ev.target.value; state.view = null; schedule(); });
  $("tab-design").addEventListener("click", () => selectTab("design"));
  $("tab-body").addEventListener("click", () => selectTab("body"));
  $("body-units").addEventListener("change", showUnits);

  try {
    await loadBody(state.schema.default_body);
    await loadDesign(state.schema.default_design);
  } catch (e) {
    showProblems("The defaults cannot be loaded", e.problems, "error");
  }
}

main();
