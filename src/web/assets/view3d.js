// The configurator's 3D view: the simulation box mesh of POST /api/mesh drawn with
// plain WebGL 1 (no library): flat Lambert shading, one colour per panel, the
// seams of the stitches as lines; drag to orbit, wheel to zoom.
"use strict";

const VERTEX_SHADER = `
attribute vec3 a_position;
attribute vec3 a_normal;
attribute vec3 a_color;
uniform mat4 u_matrix;
varying vec3 v_normal;
varying vec3 v_color;
void main() {
  gl_Position = u_matrix * vec4(a_position, 1.0);
  v_normal = a_normal;
  v_color = a_color;
}`;

// Two-sided Lambert lighting from a light near the eye; the inside of the
// garment (back faces) a little darker. u_lit = 0 draws the plain colour (lines).
const FRAGMENT_SHADER = `
precision mediump float;
uniform vec3 u_light;
uniform float u_lit;
varying vec3 v_normal;
varying vec3 v_color;
void main() {
  vec3 n = normalize(v_normal);
  float side = 1.0;
  if (!gl_FrontFacing) { n = -n; side = 0.8; }
  float shade = mix(1.0, side * (0.35 + 0.65 * max(dot(n, u_light), 0.0)), u_lit);
  gl_FragColor = vec4(v_color * shade, 1.0);
}`;

const BACKGROUND = [0.98, 0.976, 0.969];
const SEAM_COLOR = [0.54, 0.18, 0.32];
const FOV = (35 * Math.PI) / 180;
const START_YAW = -0.45;
const START_PITCH = 0.2;

// Column-major 4x4 matrices, as WebGL reads them.
const mat4 = {
  multiply(a, b) {
    const out = new Float32Array(16);
    for (let c = 0; c < 4; c++) {
      for (let r = 0; r < 4; r++) {
        let s = 0;
        for (let k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
        out[c * 4 + r] = s;
      }
    }
    return out;
  },
  identity() {
    const m = new Float32Array(16);
    m[0] = m[5] = m[10] = m[15] = 1;
    return m;
  },
  translation(x, y, z) {
    const m = mat4.identity();
    m[12] = x; m[13] = y; m[14] = z;
    return m;
  },
  rotationX(a) {
    const m = mat4.identity(), c = Math.cos(a), s = Math.sin(a);
    m[5] = c; m[6] = s; m[9] = -s; m[10] = c;
    return m;
  },
  rotationY(a) {
    const m = mat4.identity(), c = Math.cos(a), s = Math.sin(a);
    m[0] = c; m[2] = -s; m[8] = s; m[10] = c;
    return m;
  },
  perspective(fovy, aspect, near, far) {
    const m = new Float32Array(16), f = 1 / Math.tan(fovy / 2);
    m[0] = f / aspect; m[5] = f;
    m[10] = (far + near) / (near - far); m[11] = -1;
    m[14] = (2 * far * near) / (near - far);
    return m;
  },
  // The direction vector (x, y, z) turned by the rotation part of m.
  turn(m, v) {
    return [0, 1, 2].map((r) => m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2]);
  },
};

// A colour per panel from its name: the same name keeps its colour as the
// pattern changes; left and right panels share a hue, the right one lighter.
function panelColor(name) {
  const base = name.replace(/^(left|right)_/, "");
  let h = 2166136261;
  for (let i = 0; i < base.length; i++) h = Math.imul(h ^ base.charCodeAt(i), 16777619) >>> 0;
  const hue = (h % 360) / 360;
  const light = name.startsWith("right_") ? 0.72 : 0.64;
  return hsl(hue, 0.5, light);
}

function hsl(h, s, l) {
  const q = l < 0.5 ? l * (1 + s) : l + s - l * s, p = 2 * l - q;
  const channel = (t) => {
    t = (t + 1) % 1;
    if (t < 1 / 6) return p + (q - p) * 6 * t;
    if (t < 1 / 2) return q;
    if (t < 2 / 3) return p + (q - p) * (2 / 3 - t) * 6;
    return p;
  };
  return [channel(h + 1 / 3), channel(h), channel(h - 1 / 3)];
}

class MeshView {
  // The view on `canvas`, or null when the browser has no WebGL.
  static create(canvas) {
    let gl = null;
    try {
      gl = canvas.getContext("webgl", { antialias: true, preserveDrawingBuffer: true, alpha: false });
    } catch (e) {
      gl = null;
    }
    return gl ? new MeshView(canvas, gl) : null;
  }

  constructor(canvas, gl) {
    this.canvas = canvas;
    this.gl = gl;
    this.program = this.link();
    this.loc = {
      position: gl.getAttribLocation(this.program, "a_position"),
      normal: gl.getAttribLocation(this.program, "a_normal"),
      color: gl.getAttribLocation(this.program, "a_color"),
      matrix: gl.getUniformLocation(this.program, "u_matrix"),
      light: gl.getUniformLocation(this.program, "u_light"),
      lit: gl.getUniformLocation(this.program, "u_lit"),
    };
    this.buffers = { position: gl.createBuffer(), normal: gl.createBuffer(), color: gl.createBuffer(), seams: gl.createBuffer() };
    this.triangleVertices = 0;
    this.seamVertices = 0;
    this.showSeams = true;
    this.center = [0, 0, 0];
    this.radius = 0;
    this.yaw = START_YAW;
    this.pitch = START_PITCH;
    this.zoomFactor = 1;
    this.frame = 0;
    this.listen();
    new ResizeObserver(() => this.redraw()).observe(canvas);
  }

  link() {
    const gl = this.gl;
    const shader = (type, text) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, text);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
      return s;
    };
    const p = gl.createProgram();
    gl.attachShader(p, shader(gl.VERTEX_SHADER, VERTEX_SHADER));
    gl.attachShader(p, shader(gl.FRAGMENT_SHADER, FRAGMENT_SHADER));
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    return p;
  }

  // A mesh of POST /api/mesh: flat triangles (each with its face normal and its
  // panel's colour) and seam segments. Keeps the rotation and zoom; refits the
  // camera to the new bounds.
  setMesh(mesh) {
    const gl = this.gl;
    const P = mesh.positions, T = mesh.triangles;
    const positions = new Float32Array(T.length * 3);
    const normals = new Float32Array(T.length * 3);
    const colors = new Float32Array(T.length * 3);
    this.legend = [];
    for (const panel of mesh.panels) {
      const color = panelColor(panel.name);
      this.legend.push({ name: panel.name, color });
      for (let f = panel.first_face; f < panel.first_face + panel.faces; f++) {
        const a = T[3 * f] * 3, b = T[3 * f + 1] * 3, c = T[3 * f + 2] * 3;
        const ux = P[b] - P[a], uy = P[b + 1] - P[a + 1], uz = P[b + 2] - P[a + 2];
        const vx = P[c] - P[a], vy = P[c + 1] - P[a + 1], vz = P[c + 2] - P[a + 2];
        let nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        const len = Math.hypot(nx, ny, nz) || 1;
        nx /= len; ny /= len; nz /= len;
        [a, b, c].forEach((v, k) => {
          const o = 9 * f + 3 * k;
          positions[o] = P[v]; positions[o + 1] = P[v + 1]; positions[o + 2] = P[v + 2];
          normals[o] = nx; normals[o + 1] = ny; normals[o + 2] = nz;
          colors[o] = color[0]; colors[o + 1] = color[1]; colors[o + 2] = color[2];
        });
      }
    }
    const seams = [];
    for (const seam of mesh.stitches) {
      for (let i = 0; i + 1 < seam.length; i++) {
        const a = seam[i] * 3, b = seam[i + 1] * 3;
        seams.push(P[a], P[a + 1], P[a + 2], P[b], P[b + 1], P[b + 2]);
      }
    }
    const upload = (buffer, data) => {
      gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
      gl.bufferData(gl.ARRAY_BUFFER, data, gl.STATIC_DRAW);
    };
    upload(this.buffers.position, positions);
    upload(this.buffers.normal, normals);
    upload(this.buffers.color, colors);
    upload(this.buffers.seams, new Float32Array(seams));
    this.triangleVertices = T.length;
    this.seamVertices = seams.length / 3;
    const lo = mesh.bounds.min, hi = mesh.bounds.max;
    this.center = [0, 1, 2].map((k) => (lo[k] + hi[k]) / 2);
    this.radius = Math.max(1, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2);
    this.redraw();
  }

  setSeams(show) {
    this.showSeams = show;
    this.redraw();
  }

  zoom(factor) {
    this.zoomFactor = Math.min(20, Math.max(0.05, this.zoomFactor * factor));
    this.redraw();
  }

  // Back to the first view: from the front-left, the whole mesh in sight.
  fit() {
    this.yaw = START_YAW;
    this.pitch = START_PITCH;
    this.zoomFactor = 1;
    this.redraw();
  }

  rotate(dx, dy) {
    this.yaw += dx * 0.01;
    this.pitch = Math.min(1.5, Math.max(-1.5, this.pitch + dy * 0.01));
    this.redraw();
  }

  listen() {
    const c = this.canvas;
    let drag = null;
    c.addEventListener("pointerdown", (ev) => {
      drag = { x: ev.clientX, y: ev.clientY };
      c.setPointerCapture(ev.pointerId);
      c.classList.add("dragging");
    });
    c.addEventListener("pointermove", (ev) => {
      if (!drag) return;
      this.rotate(ev.clientX - drag.x, ev.clientY - drag.y);
      drag = { x: ev.clientX, y: ev.clientY };
    });
    const end = () => { drag = null; c.classList.remove("dragging"); };
    c.addEventListener("pointerup", end);
    c.addEventListener("pointercancel", end);
    c.addEventListener("wheel", (ev) => {
      ev.preventDefault();
      this.zoom(ev.deltaY > 0 ? 1.15 : 1 / 1.15);
    }, { passive: false });
    c.addEventListener("dblclick", () => this.fit());
  }

  redraw() {
    if (!this.frame) this.frame = requestAnimationFrame(() => { this.frame = 0; this.draw(); });
  }

  draw() {
    const gl = this.gl, c = this.canvas;
    const dpr = window.devicePixelRatio || 1;
    const w = Math.max(1, Math.round(c.clientWidth * dpr)), h = Math.max(1, Math.round(c.clientHeight * dpr));
    if (c.width !== w || c.height !== h) { c.width = w; c.height = h; }
    gl.viewport(0, 0, w, h);
    gl.clearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    if (!this.triangleVertices) return;

    // Fit the bounding sphere in the narrower field of view (FOV is the vertical one), then zoom.
    const aspect = w / h;
    const fov = aspect >= 1 ? FOV : 2 * Math.atan(Math.tan(FOV / 2) * aspect);
    const distance = (this.radius / Math.sin(fov / 2)) * 1.05 * this.zoomFactor;
    const rotation = mat4.multiply(mat4.rotationX(this.pitch), mat4.rotationY(this.yaw));
    const view = mat4.multiply(
      mat4.translation(0, 0, -distance),
      mat4.multiply(rotation, mat4.translation(-this.center[0], -this.center[1], -this.center[2])),
    );
    const near = Math.max(0.5, distance - this.radius * 1.5), far = distance + this.radius * 1.5;
    const matrix = mat4.multiply(mat4.perspective(FOV, aspect, near, far), view);
    // A light above-right of the eye, in the mesh's frame (the inverse rotation).
    const inverse = mat4.multiply(mat4.rotationY(-this.yaw), mat4.rotationX(-this.pitch));
    const l = mat4.turn(inverse, [0.3, 0.45, 1]);
    const ln = Math.hypot(l[0], l[1], l[2]);

    gl.useProgram(this.program);
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LEQUAL);
    gl.uniformMatrix4fv(this.loc.matrix, false, matrix);
    gl.uniform3f(this.loc.light, l[0] / ln, l[1] / ln, l[2] / ln);
    const attribute = (loc, buffer) => {
      gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
      gl.enableVertexAttribArray(loc);
      gl.vertexAttribPointer(loc, 3, gl.FLOAT, false, 0, 0);
    };

    // Triangles, pushed back a little so that the seams on them stay visible.
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    gl.uniform1f(this.loc.lit, 1);
    attribute(this.loc.position, this.buffers.position);
    attribute(this.loc.normal, this.buffers.normal);
    attribute(this.loc.color, this.buffers.color);
    gl.drawArrays(gl.TRIANGLES, 0, this.triangleVertices);
    gl.disable(gl.POLYGON_OFFSET_FILL);

    if (this.showSeams && this.seamVertices) {
      gl.uniform1f(this.loc.lit, 0);
      attribute(this.loc.position, this.buffers.seams);
      gl.disableVertexAttribArray(this.loc.normal);
      gl.disableVertexAttribArray(this.loc.color);
      gl.vertexAttrib3f(this.loc.normal, 0, 0, 1);
      gl.vertexAttrib3f(this.loc.color, SEAM_COLOR[0], SEAM_COLOR[1], SEAM_COLOR[2]);
      gl.drawArrays(gl.LINES, 0, this.seamVertices);
    }
  }
}
