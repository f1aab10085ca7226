//! The box mesh's files, laid out as the reference writes them, and readers for our own OBJ
//! and segmentation files.

use std::fmt::Write as _;
use std::io;
use std::path::{Path, PathBuf};

use super::{BoxMesh, VertexLabel};
use crate::parity::float_repr::write_python_float;
use crate::{Vec2, Vec3};

/// Padding between texture islands (cm), as the reference lays them out.
const UV_PADDING: f64 = 3.0;

/// Width and height of `<name>_texture_fabric.png`, pixels.
pub const TEXTURE_SIZE: usize = 512;

impl BoxMesh {
    /// File name prefix: the pattern name without a `_specification` suffix.
    pub fn file_prefix(&self) -> &str {
        self.name.strip_suffix("_specification").unwrap_or(&self.name)
    }

    /// `<name>_boxmesh.obj`: `mtllib`, `v` (cm, Python float repr), `vt` (one per panel-local
    /// vertex), `s 1`, `usemtl panels_texture`, `f v/vt v/vt v/vt`.
    pub fn obj(&self) -> String {
        self.obj_with(&Coordinates::new(&self.vertices), &self.texture_coordinates())
    }

    fn obj_with(&self, xyz: &Coordinates, uvs: &[Vec2]) -> String {
        let mut out = String::with_capacity(xyz.text.len() + 3 * self.vertices.len() + 48 * uvs.len() + 48 * self.faces.len() + 100);
        let _ = writeln!(out, "mtllib {}_material.mtl", self.file_prefix());
        for v in 0..self.vertices.len() {
            out.push_str("v ");
            out.push_str(xyz.get(v));
            out.push('\n');
        }
        for uv in uvs {
            out.push_str("vt ");
            write_python_float(&mut out, uv.x);
            out.push(' ');
            write_python_float(&mut out, uv.y);
            out.push('\n');
        }
        out.push_str("s 1\nusemtl panels_texture\n");
        for f in &self.faces {
            out.push('f');
            for k in 0..3 {
                out.push(' ');
                push_int(&mut out, f.vertices[k] + 1);
                out.push('/');
                push_int(&mut out, f.uvs[k] + 1);
            }
            out.push('\n');
        }
        out
    }

    /// Texture coordinates of every panel-local vertex (texture id order): each panel's 2D
    /// points minus its minimum, islands laid out as the reference lays them (columns of
    /// ⌊√panels⌋ islands, 3 cm padding), scaled into `[0, 1]`.
    pub fn texture_coordinates(&self) -> Vec<Vec2> {
        let per_column = (self.panels.len() as f64).sqrt().floor().max(1.0) as usize;
        let mut uvs = Vec::with_capacity(self.panels.iter().map(|p| p.points.len()).sum());
        let (mut x, mut y, mut column_width) = (UV_PADDING, UV_PADDING, 0.0f64);
        for (i, p) in self.panels.iter().enumerate() {
            if i > 0 && i % per_column == 0 {
                x += column_width + UV_PADDING;
                (y, column_width) = (UV_PADDING, 0.0);
            }
            let local = p.uv();
            let size = local.iter().fold(Vec2::ZERO, |m, q| m.max(*q));
            uvs.extend(local.iter().map(|q| *q + Vec2::new(x, y)));
            y += size.y + UV_PADDING;
            column_width = column_width.max(size.x);
        }
        let scale = uvs.iter().fold(0.0f64, |m, q| m.max(q.x).max(q.y)) + UV_PADDING;
        uvs.iter().map(|q| *q / scale).collect()
    }

    /// `<name>_texture_fabric.png`, the texture the material names (the reference's renderer
    /// needs the file): the texture islands, each panel's faces at their texture coordinates,
    /// in a fabric colour on white, [`TEXTURE_SIZE`] pixels square. The reference draws
    /// its islands at 1,500 dpi (about 10 MB a garment); this one is a few kilobytes.
    pub fn texture_png(&self) -> Vec<u8> {
        self.texture_png_with(&self.texture_coordinates())
    }

    fn texture_png_with(&self, uvs: &[Vec2]) -> Vec<u8> {
        const FABRIC: [u8; 3] = [0xd8, 0xc8, 0xb0];
        let n = TEXTURE_SIZE;
        let mut rgb = vec![0xffu8; 3 * n * n];
        let scale = n as f64;
        for f in &self.faces {
            // Image rows run down, texture v up.
            let [a, b, c] = f.uvs.map(|t| Vec2::new(uvs[t].x * scale, (1.0 - uvs[t].y) * scale));
            let area = (b - a).perp_dot(c - a);
            if area == 0.0 || !area.is_finite() {
                continue;
            }
            let (lo, hi) = (a.min(b).min(c), a.max(b).max(c));
            let (x0, x1) = ((lo.x.floor().max(0.0)) as usize, (hi.x.ceil().min(scale)) as usize);
            let (y0, y1) = ((lo.y.floor().max(0.0)) as usize, (hi.y.ceil().min(scale)) as usize);
            for y in y0..y1 {
                for x in x0..x1 {
                    // Pixels whose centre is inside (or on) the triangle.
                    let p = Vec2::new(x as f64 + 0.5, y as f64 + 0.5);
                    let w = [(b - a).perp_dot(p - a), (c - b).perp_dot(p - b), (a - c).perp_dot(p - c)];
                    if w.iter().all(|w| w * area >= 0.0) {
                        rgb[3 * (y * n + x)..3 * (y * n + x) + 3].copy_from_slice(&FABRIC);
                    }
                }
            }
        }
        let mut out = Vec::new();
        let mut enc = png::Encoder::new(&mut out, n as u32, n as u32);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_compression(png::Compression::Fast);
        // Writing into memory cannot fail for an image of the size declared.
        let mut writer = enc.write_header().expect("PNG header in memory");
        writer.write_image_data(&rgb).expect("PNG data in memory");
        writer.finish().expect("PNG end in memory");
        out
    }

    /// `<name>_material.mtl`.
    pub fn material(&self) -> String {
        format!(
            "newmtl panels_texture\nNs 0.000000\nKa 1.000000 1.000000 1.000000\nKs 0.000000 0.000000 0.000000\n\
             Ke 0.000000 0.000000 0.000000\nNi 1.000000\nd 1.000000\nillum 1\nmap_Kd {}_texture_fabric.png\n",
            self.file_prefix()
        )
    }

    /// `<name>_sim_segmentation.txt`: one line per vertex.
    pub fn segmentation(&self) -> String {
        let mut out = String::with_capacity(24 * self.vertices.len());
        for label in &self.labels {
            match label {
                VertexLabel::Stitch(ks) => {
                    for (i, k) in ks.iter().enumerate() {
                        out.push_str(if i == 0 { "stitch_" } else { ",stitch_" });
                        push_int(&mut out, *k);
                    }
                }
                VertexLabel::Panel(p) => out.push_str(&self.panels[*p].name),
            }
            out.push('\n');
        }
        out
    }

    /// `<name>_orig_lens.pickle`: the rest lengths as a pickled `{(i, j): length}` dict
    /// (protocol 2, written by hand: `}` then `(`, per item `J i J j \x86 G <f64 BE>`, `u`, `.`).
    pub fn rest_lengths_pickle(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(16 + 20 * self.rest_lengths.len());
        out.extend_from_slice(&[0x80, 2, b'}']);
        for chunk in self.rest_lengths.chunks(1000) {
            out.push(b'(');
            for ([i, j], len) in chunk {
                for id in [i, j] {
                    out.push(b'J');
                    out.extend_from_slice(&(*id as i32).to_le_bytes());
                }
                out.push(0x86);
                out.push(b'G');
                out.extend_from_slice(&len.to_be_bytes());
            }
            out.push(b'u');
        }
        out.push(b'.');
        out
    }

    /// `<name>_vertex_labels.yaml`: `label:` then `- id` lines (block style), `{}` when empty.
    pub fn vertex_labels_yaml(&self) -> String {
        if self.vertex_labels.is_empty() {
            return "{}\n".into();
        }
        let mut out = String::new();
        for (label, ids) in &self.vertex_labels {
            let _ = writeln!(out, "{}:", yaml_key(label));
            if ids.is_empty() {
                out.pop();
                out.push_str(" []\n");
            }
            for id in ids {
                out.push_str("- ");
                push_int(&mut out, *id);
                out.push('\n');
            }
        }
        out
    }

    /// `<name>_sim_mesh.obj`: the welded mesh in metres, plain `v` and `f` lines.
    pub fn welded_obj_metres(&self) -> String {
        let mut out = String::with_capacity(72 * self.vertices.len() + 24 * self.faces.len());
        for v in &self.vertices {
            out.push_str("v ");
            push_xyz(&mut out, *v / 100.0);
        }
        for f in &self.faces {
            out.push('f');
            for v in f.vertices {
                out.push(' ');
                push_int(&mut out, v + 1);
            }
            out.push('\n');
        }
        out
    }

    /// `<name>_boxmesh.ply` (ASCII, cm): per vertex `x y z segment stitch`, where `segment`
    /// is the panel index (panels named in `comment panel <i> <name>` lines) or -1 for a
    /// stitch vertex and `stitch` the first stitch of a stitch vertex (-1 otherwise).
    pub fn ply(&self) -> String {
        self.ply_with(&Coordinates::new(&self.vertices))
    }

    fn ply_with(&self, xyz: &Coordinates) -> String {
        let mut out = String::with_capacity(xyz.text.len() + 16 * self.vertices.len() + 24 * self.faces.len() + 1000);
        out.push_str("ply\nformat ascii 1.0\ncomment garmentcode box mesh, cm\n");
        for (i, p) in self.panels.iter().enumerate() {
            let _ = writeln!(out, "comment panel {i} {}", p.name);
        }
        let _ = write!(
            out,
            "element vertex {}\nproperty double x\nproperty double y\nproperty double z\nproperty int segment\nproperty int stitch\n\
             element face {}\nproperty list uchar int vertex_indices\nend_header\n",
            self.vertices.len(),
            self.faces.len()
        );
        for (v, label) in self.labels.iter().enumerate() {
            let (segment, stitch) = match label {
                VertexLabel::Stitch(ks) => (-1, ks.first().map_or(-1, |&k| k as i64)),
                VertexLabel::Panel(p) => (*p as i64, -1),
            };
            out.push_str(xyz.get(v));
            out.push(' ');
            out.push_str(itoa::Buffer::new().format(segment));
            out.push(' ');
            out.push_str(itoa::Buffer::new().format(stitch));
            out.push('\n');
        }
        for f in &self.faces {
            out.push('3');
            for v in f.vertices {
                out.push(' ');
                push_int(&mut out, v);
            }
            out.push('\n');
        }
        out
    }

    /// The files, named `<name><suffix>` (suffixes in [`FILE_SUFFIXES`]): the reference's
    /// (OBJ, material, segmentation, rest lengths, vertex labels), the welded metre OBJ, the
    /// PLY and the texture the material names.
    pub fn files(&self) -> Vec<(String, Vec<u8>)> {
        let name = self.file_prefix();
        // Shared by the OBJ and the PLY, and by the OBJ and the texture.
        let (xyz, uvs) = (Coordinates::new(&self.vertices), self.texture_coordinates());
        let bytes = [
            self.obj_with(&xyz, &uvs).into_bytes(),
            self.material().into_bytes(),
            self.segmentation().into_bytes(),
            self.rest_lengths_pickle(),
            self.vertex_labels_yaml().into_bytes(),
            self.welded_obj_metres().into_bytes(),
            self.ply_with(&xyz).into_bytes(),
            self.texture_png_with(&uvs),
        ];
        FILE_SUFFIXES.iter().zip(bytes).map(|(suffix, b)| (format!("{name}{suffix}"), b)).collect()
    }

    /// Writes [`BoxMesh::files`] into `dir`; returns the paths written.
    pub fn write_files(&self, dir: &Path) -> io::Result<Vec<PathBuf>> {
        std::fs::create_dir_all(dir)?;
        let mut written = Vec::new();
        for (name, bytes) in self.files() {
            let path = dir.join(name);
            std::fs::write(&path, bytes)?;
            written.push(path);
        }
        Ok(written)
    }
}

/// Suffixes of the files [`BoxMesh::files`] writes, after the pattern's name.
pub const FILE_SUFFIXES: [&str; 8] = [
    "_boxmesh.obj",
    "_material.mtl",
    "_sim_segmentation.txt",
    "_orig_lens.pickle",
    "_vertex_labels.yaml",
    "_sim_mesh.obj",
    "_boxmesh.ply",
    "_texture_fabric.png",
];

/// Every vertex's `x y z` in Python's float repr, laid out once for the OBJ and the PLY.
struct Coordinates {
    text: String,
    /// Vertex `i`'s text ends at `ends[i]` (and starts at `ends[i - 1]`).
    ends: Vec<usize>,
}

impl Coordinates {
    fn new(vertices: &[Vec3]) -> Coordinates {
        let mut text = String::with_capacity(72 * vertices.len());
        let ends = vertices
            .iter()
            .map(|v| {
                push_xyz_line(&mut text, *v);
                text.len()
            })
            .collect();
        Coordinates { text, ends }
    }

    fn get(&self, i: usize) -> &str {
        &self.text[if i == 0 { 0 } else { self.ends[i - 1] }..self.ends[i]]
    }
}

fn push_int(out: &mut String, i: usize) {
    out.push_str(itoa::Buffer::new().format(i));
}

/// `x y z` in Python's float repr (shortest round trip), without a line end.
fn push_xyz_line(out: &mut String, v: Vec3) {
    write_python_float(out, v.x);
    out.push(' ');
    write_python_float(out, v.y);
    out.push(' ');
    write_python_float(out, v.z);
}

fn push_xyz(out: &mut String, v: Vec3) {
    push_xyz_line(out, v);
    out.push('\n');
}

/// A YAML mapping key as PyYAML dumps a string: plain when unambiguous, else single-quoted.
fn yaml_key(s: &str) -> String {
    let plain = !s.is_empty()
        && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
        && !s.starts_with('-')
        && s.parse::<f64>().is_err()
        && !matches!(s.to_ascii_lowercase().as_str(), "true" | "false" | "yes" | "no" | "on" | "off" | "null" | "y" | "n" | "~");
    if plain { s.to_string() } else { format!("'{}'", s.replace('\'', "''")) }
}

/// Vertices (`v x y z`) and triangles (`f a/.. b/.. c/..`, 0-based) of an OBJ text.
pub fn read_obj(text: &str) -> Result<(Vec<Vec3>, Vec<[usize; 3]>), String> {
    let mut vertices = Vec::new();
    let mut faces = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut it = line.split_whitespace();
        match it.next() {
            Some("v") => {
                let c: Vec<f64> =
                    it.take(3).map(|x| x.parse::<f64>().map_err(|e| format!("line {}: {e}", n + 1))).collect::<Result<_, _>>()?;
                if c.len() != 3 {
                    return Err(format!("line {}: a vertex needs three coordinates", n + 1));
                }
                vertices.push(Vec3::new(c[0], c[1], c[2]));
            }
            Some("f") => {
                let ids: Vec<usize> = it
                    .map(|t| t.split('/').next().unwrap_or("").parse::<usize>().map_err(|e| format!("line {}: {e}", n + 1)))
                    .collect::<Result<_, _>>()?;
                if ids.len() != 3 || ids.iter().any(|&i| i == 0 || i > vertices.len()) {
                    return Err(format!("line {}: not a triangle of existing vertices", n + 1));
                }
                faces.push([ids[0] - 1, ids[1] - 1, ids[2] - 1]);
            }
            _ => {}
        }
    }
    Ok((vertices, faces))
}

/// The labels of a segmentation file, one per vertex (each a list of comma-separated entries).
pub fn read_segmentation(text: &str) -> Vec<Vec<String>> {
    text.lines().map(|l| l.split(',').map(str::to_string).collect()).collect()
}
