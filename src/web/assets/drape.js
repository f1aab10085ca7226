// The configurator's drape view: the current design draped on the body by the
// server (POST /api/drape starts it, GET /api/drape/JOB is polled for its frames),
// drawn with three.js (vendored, served by the server: the page stays offline).
// app.js drives it through window.drapeView: show(request), hide(), restart(request).
import * as THREE from "three";
import { OrbitControls } from "/vendor/OrbitControls.js";

const BACKGROUND = 0xfaf9f7;
const GARMENT_COLOR = 0x2f6fd0;
const BODY_COLOR = 0xcdb9a6;
const POLL_MS = 150;
const RESTART_MS = 300;

const $ = (id) => document.getElementById(id);

class DrapeView {
  constructor(canvas) {
    this.canvas = canvas;
    // Throws without WebGL 2: the caller shows a message instead.
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(BACKGROUND);
    this.camera = new THREE.PerspectiveCamera(35, 1, 1, 5000);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8070, 1.6));
    const key = new THREE.DirectionalLight(0xffffff, 1.8);
    key.position.set(0.4, 0.6, 1);
    this.camera.add(key); // the light follows the eye
    this.scene.add(this.camera);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    this.controls.addEventListener("change", () => this.redraw());
    canvas.addEventListener("dblclick", () => this.fit());
    this.body = null;     // THREE.Mesh of the body
    this.bodyKey = null;  // what the body mesh was made from (name and size), to reuse it
    this.garment = null;  // THREE.Mesh of the garment
    this.frame = 0;
    new ResizeObserver(() => this.redraw()).observe(canvas);
  }

  // The body and the garment of a POST /api/drape answer.
  setScene(res) {
    const b = res.body_mesh;
    const key = `${b.name}:${b.positions.length}:${b.positions[0]}:${b.positions[b.positions.length - 1]}`;
    if (key !== this.bodyKey) {
      if (this.body) { this.scene.remove(this.body); this.body.geometry.dispose(); }
      const g = new THREE.BufferGeometry();
      g.setAttribute("position", new THREE.Float32BufferAttribute(b.positions, 3));
      g.setIndex(b.triangles);
      g.computeVertexNormals();
      this.body = new THREE.Mesh(g, new THREE.MeshStandardMaterial({ color: BODY_COLOR, roughness: 0.9 }));
      this.scene.add(this.body);
      this.bodyKey = key;
      g.computeBoundingBox();
      this.bounds = g.boundingBox;
      this.fit();
    }
    if (this.garment) { this.scene.remove(this.garment); this.garment.geometry.dispose(); }
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(res.mesh.positions, 3));
    g.setIndex(res.mesh.triangles);
    g.computeVertexNormals();
    const material = new THREE.MeshStandardMaterial({ color: GARMENT_COLOR, roughness: 0.8, side: THREE.DoubleSide });
    this.garment = new THREE.Mesh(g, material);
    this.scene.add(this.garment);
    this.redraw();
  }

  // The garment's vertices after a frame.
  setPositions(positions) {
    if (!this.garment) return;
    const a = this.garment.geometry.getAttribute("position");
    if (a.array.length !== positions.length) return;
    a.array.set(positions);
    a.needsUpdate = true;
    this.garment.geometry.computeVertexNormals();
    this.garment.geometry.computeBoundingSphere();
    this.redraw();
  }

  // The whole body in sight, from the front.
  fit() {
    if (!this.bounds) return;
    const center = this.bounds.getCenter(new THREE.Vector3());
    const size = this.bounds.getSize(new THREE.Vector3());
    const aspect = this.aspect();
    const half = Math.max(size.y / 2, size.x / 2 / aspect) * 1.1;
    const distance = half / Math.tan(THREE.MathUtils.degToRad(this.camera.fov / 2));
    this.camera.position.set(center.x, center.y, center.z + distance);
    this.camera.near = Math.max(1, distance / 20);
    this.camera.far = distance * 10;
    this.controls.target.copy(center);
    this.controls.update();
    this.redraw();
  }

  zoom(factor) {
    const offset = this.camera.position.clone().sub(this.controls.target).multiplyScalar(factor);
    this.camera.position.copy(this.controls.target).add(offset);
    this.controls.update();
    this.redraw();
  }

  aspect() {
    return Math.max(1, this.canvas.clientWidth) / Math.max(1, this.canvas.clientHeight);
  }

  redraw() {
    if (!this.frame) this.frame = requestAnimationFrame(() => { this.frame = 0; this.draw(); });
  }

  draw() {
    const c = this.canvas;
    const w = Math.max(1, c.clientWidth), h = Math.max(1, c.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.renderer.render(this.scene, this.camera);
    c.dataset.drawn = String(Number(c.dataset.drawn || 0) + 1);
  }
}

// ---------------------------------------------------------------------------
// The drape job of the view: started when the view is shown or the design changes,
// polled until it ends, cancelled when the view is left.

const run = {
  view: undefined, // DrapeView; null without WebGL; undefined until first shown
  job: null,       // id of the latest drape job
  seq: 0,          // id of the latest start request (older answers are ignored)
  timer: null,     // pending restart
  shown: false,
  request: null,   // the design and body of the latest drape
};

for (const id of ["drape-frames", "drape-resolution"]) {
  $(id).addEventListener("change", () => { if (run.shown && run.view && run.request) start(run.request); });
}

function message(text) {
  const p = $("drape-message");
  p.textContent = text || "";
  p.hidden = !text;
}

function progress(frame, max, text, state) {
  const bar = $("drape-progress");
  bar.max = max || 1;
  bar.value = frame;
  $("drape-info").textContent = text;
  const c = $("drape3d");
  c.dataset.state = state;
  c.dataset.frame = String(frame);
}

async function call(method, path, body) {
  const opts = { method, headers: {} };
  if (body !== undefined) {
    opts.headers["Content-Type"] = "application/json";
    opts.body = JSON.stringify(body);
  }
  const res = await fetch(path, opts);
  const data = await res.json();
  if (!res.ok) throw new Error((data.problems && data.problems.join("; ")) || data.error || res.statusText);
  return data;
}

// The request with the view's settings (frames, mesh resolution).
function withSettings(request) {
  const frames = Math.round(Number($("drape-frames").value));
  return { ...request, max_frames: frames >= 1 && frames <= 2400 ? frames : 600, resolution: Number($("drape-resolution").value) };
}

async function start(request) {
  run.request = request;
  request = withSettings(request);
  const seq = ++run.seq;
  cancel();
  progress(0, 1, "Starting the drape…", "starting");
  let res;
  try {
    res = await call("POST", "/api/drape", request);
  } catch (e) {
    if (seq === run.seq) { message("The drape cannot be started: " + e.message); progress(0, 1, "", "error"); }
    return;
  }
  if (seq !== run.seq || !run.shown) {
    // Left meanwhile: stop it (a newer start stops it anyway).
    if (!run.shown && res.ok) call("POST", "/api/drape/cancel", { job: res.job }).catch(() => {});
    return;
  }
  if (!res.ok) {
    message("No drape of this design: " + res.error);
    progress(0, 1, "", "error");
    return;
  }
  message("");
  run.job = res.job;
  run.view.setScene(res);
  const c = $("drape3d");
  c.dataset.vertices = String(res.mesh.vertices);
  c.dataset.job = String(res.job);
  poll(res.job, res.max_frames);
}

async function poll(job, maxFrames) {
  while (run.job === job && run.shown) {
    let s;
    try {
      s = await call("GET", "/api/drape/" + job);
    } catch (e) {
      if (run.job === job) { message("The drape stopped: " + e.message); progress(0, 1, "", "error"); run.job = null; }
      return;
    }
    if (run.job !== job) return;
    run.view.setPositions(s.positions);
    const head = `Frame ${s.frame} / ${maxFrames} · ${s.seconds.toFixed(1)} s`;
    if (s.state === "running") {
      progress(s.frame, maxFrames, `Draping… ${head} · ${s.non_static_vertices} vertices moving`, "running");
      await new Promise((r) => setTimeout(r, POLL_MS));
      continue;
    }
    run.job = null;
    const st = s.stats;
    if (s.state === "failed") {
      message("The drape failed: " + s.error);
      progress(s.frame, maxFrames, head, "failed");
    } else if (s.state === "stopped") {
      progress(s.frame, maxFrames, `Stopped (${s.error}) · ${head}`, "stopped");
    } else {
      const settled = st.converged ? "settled" : "not settled within the frame limit";
      progress(s.frame, maxFrames,
        `Draped: ${st.frames} frames in ${st.seconds.toFixed(1)} s, ${settled} · ${st.body_penetrations} body penetrations, ${st.self_intersections} self-intersections · drag to rotate, wheel to zoom, double-click to reset`,
        "done");
    }
    return;
  }
}

function cancel() {
  const job = run.job;
  run.job = null;
  if (job !== null) call("POST", "/api/drape/cancel", { job }).catch(() => {});
}

window.drapeView = {
  // The view is shown: make it (once) and drape `request` (POST /api/drape's body).
  show(request) {
    run.shown = true;
    if (run.view === undefined) {
      try {
        run.view = new DrapeView($("drape3d"));
      } catch (e) {
        run.view = null;
      }
      $("drape3d").dataset.webgl = run.view ? "yes" : "no";
    }
    if (!run.view) {
      message("The drape view needs WebGL 2, which this browser does not provide or has turned off. The 2D view works without it.");
      return;
    }
    run.view.redraw();
    start(request);
  },
  // The design or body changed: drape again after a short pause (a slider moving
  // restarts it once it rests).
  restart(request) {
    if (!run.shown || !run.view) return;
    clearTimeout(run.timer);
    run.timer = setTimeout(() => start(request), RESTART_MS);
  },
  hide() {
    run.shown = false;
    clearTimeout(run.timer);
    run.seq++;
    cancel();
  },
  zoom(factor) { if (run.view) run.view.zoom(factor); },
  fit() { if (run.view) run.view.fit(); },
};
