//! The box mesh's files, laid out as the reference writes them, and readers for our own OBJ
//! and segmentation files.

use std::borrow::Cow;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

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
        self.text_file(OBJ)
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
        self.file(PNG)
    }

    /// `<name>_material.mtl`.
    pub fn material(&self) -> String {
        self.text_file(MTL)
    }

    /// `<name>_sim_segmentation.txt`: one line per vertex.
    pub fn segmentation(&self) -> String {
        self.text_file(SEGMENTATION)
    }

    /// `<name>_orig_lens.pickle`: the rest lengths as a pickled `{(i, j): length}` dict
    /// (protocol 2, written by hand: `}` then `(`, per item `J i J j \x86 G <f64 BE>`, `u`, `.`).
    pub fn rest_lengths_pickle(&self) -> Vec<u8> {
        self.file(PICKLE)
    }

    /// `<name>_vertex_labels.yaml`: `label:` then `- id` lines (block style), `{}` when empty.
    pub fn vertex_labels_yaml(&self) -> String {
        self.text_file(LABELS)
    }

    /// `<name>_sim_mesh.obj`: the welded mesh in metres, plain `v` and `f` lines.
    pub fn welded_obj_metres(&self) -> String {
        self.text_file(WELDED)
    }

    /// `<name>_boxmesh.ply` (ASCII, cm): per vertex `x y z segment stitch`, where `segment`
    /// is the panel index (panels named in `comment panel <i> <name>` lines) or -1 for a
    /// stitch vertex and `stitch` the first stitch of a stitch vertex (-1 otherwise).
    pub fn ply(&self) -> String {
        self.text_file(PLY)
    }

    /// The files, named `<name><suffix>` (suffixes in [`FILE_SUFFIXES`]): the reference's
    /// (OBJ, material, segmentation, rest lengths, vertex labels), the welded metre OBJ, the
    /// PLY and the texture the material names. [`MeshFiles`] writes the same bytes into
    /// any writer without holding them.
    pub fn files(&self) -> Vec<(String, Vec<u8>)> {
        let files = MeshFiles::new(Cow::Borrowed(self));
        files.names().into_iter().enumerate().map(|(i, name)| (name, files.bytes(i))).collect()
    }

    /// Writes the files of [`BoxMesh::files`] into `dir`, each streamed straight into its
    /// file; returns the paths written.
    pub fn write_files(&self, dir: &Path) -> io::Result<Vec<PathBuf>> {
        std::fs::create_dir_all(dir)?;
        let files = MeshFiles::new(Cow::Borrowed(self));
        let mut written = Vec::new();
        for (i, name) in files.names().into_iter().enumerate() {
            let path = dir.join(name);
            files.write(i, &mut std::fs::File::create(&path)?)?;
            written.push(path);
        }
        Ok(written)
    }

    /// File `index` (of [`FILE_SUFFIXES`]) in memory.
    fn file(&self, index: usize) -> Vec<u8> {
        MeshFiles::new(Cow::Borrowed(self)).bytes(index)
    }

    /// A text file (`index` of [`FILE_SUFFIXES`]) in memory.
    fn text_file(&self, index: usize) -> String {
        // Every text file is laid out from `str` pieces.
        String::from_utf8(self.file(index)).expect("mesh text files are UTF-8")
    }
}

/// Indices of the files in [`FILE_SUFFIXES`].
const OBJ: usize = 0;
const MTL: usize = 1;
const SEGMENTATION: usize = 2;
const PICKLE: usize = 3;
const LABELS: usize = 4;
const WELDED: usize = 5;
const PLY: usize = 6;
const PNG: usize = 7;

/// How many bytes of a file are laid out in memory before they are handed to its writer.
const CHUNK: usize = 256 * 1024;

/// The files of a box mesh (the mesh borrowed or owned), written one at a time into any
/// writer ([`MeshFiles::write`]) through one buffer of a few hundred kilobytes, so that
/// no file's whole text is held in memory. What two files share (the vertices' `x y z`
/// text of the OBJ and the PLY, the texture coordinates of the OBJ and the texture, the
/// decimal text of indices) is made once, when first needed.
pub struct MeshFiles<'a> {
    mesh: Cow<'a, BoxMesh>,
    xyz: OnceLock<Coordinates>,
    uvs: OnceLock<Vec<Vec2>>,
    decimals: OnceLock<Decimals>,
}

impl<'a> MeshFiles<'a> {
    /// The files of `mesh` (`Cow::Borrowed(&mesh)`, or `Cow::Owned(mesh)` for files that
    /// outlive the caller's mesh).
    pub fn new(mesh: Cow<'a, BoxMesh>) -> MeshFiles<'a> {
        MeshFiles { mesh, xyz: OnceLock::new(), uvs: OnceLock::new(), decimals: OnceLock::new() }
    }

    /// The mesh.
    pub fn mesh(&self) -> &BoxMesh {
        &self.mesh
    }

    /// The file names, `<name><suffix>` for each of [`FILE_SUFFIXES`], in that order.
    pub fn names(&self) -> Vec<String> {
        let prefix = self.mesh.file_prefix();
        FILE_SUFFIXES.iter().map(|suffix| format!("{prefix}{suffix}")).collect()
    }

    /// Writes file `index` (of [`FILE_SUFFIXES`]) into `out`, a chunk at a time.
    ///
    /// # Panics
    /// If `index` is not below `FILE_SUFFIXES.len()`.
    pub fn write(&self, index: usize, out: &mut dyn Write) -> io::Result<()> {
        let mut text = Chunked { buf: Vec::with_capacity(CHUNK + 4096), out };
        match index {
            OBJ => self.obj(&mut text)?,
            MTL => self.material(&mut text),
            SEGMENTATION => self.segmentation(&mut text)?,
            PICKLE => return self.rest_lengths_pickle(text.out),
            LABELS => self.vertex_labels_yaml(&mut text)?,
            WELDED => self.welded_obj_metres(&mut text)?,
            PLY => self.ply(&mut text)?,
            PNG => return text.out.write_all(&self.texture_png()),
            _ => panic!("a box mesh has {} files, not {}", FILE_SUFFIXES.len(), index + 1),
        }
        text.finish()
    }

    /// File `index` in memory.
    fn bytes(&self, index: usize) -> Vec<u8> {
        let mut out = Vec::new();
        // Writing into memory cannot fail.
        self.write(index, &mut out).expect("mesh files in memory");
        out
    }

    fn xyz(&self) -> &Coordinates {
        self.xyz.get_or_init(|| Coordinates::new(&self.mesh.vertices))
    }

    fn uvs(&self) -> &[Vec2] {
        self.uvs.get_or_init(|| self.mesh.texture_coordinates())
    }

    /// The decimal text of every index the files write: vertex and texture ids, counted
    /// from 0 and from 1.
    fn decimals(&self) -> &Decimals {
        self.decimals.get_or_init(|| {
            let m = &*self.mesh;
            let texture_ids = m.panels.iter().map(|p| p.points.len()).sum::<usize>();
            Decimals::new(m.vertices.len().max(texture_ids) + 1)
        })
    }

    fn obj(&self, text: &mut Chunked) -> io::Result<()> {
        let (m, xyz, decimals) = (&*self.mesh, self.xyz(), self.decimals());
        let _ = writeln!(text.buf, "mtllib {}_material.mtl", m.file_prefix());
        for v in 0..m.vertices.len() {
            text.buf.extend_from_slice(b"v ");
            text.buf.extend_from_slice(xyz.get(v));
            text.buf.push(b'\n');
            text.line_end()?;
        }
        for uv in self.uvs() {
            text.buf.extend_from_slice(b"vt ");
            write_python_float(&mut text.buf, uv.x);
            text.buf.push(b' ');
            write_python_float(&mut text.buf, uv.y);
            text.buf.push(b'\n');
            text.line_end()?;
        }
        text.buf.extend_from_slice(b"s 1\nusemtl panels_texture\n");
        let mut line = Line::new();
        for f in &m.faces {
            line.clear();
            line.byte(b'f');
            for k in 0..3 {
                line.byte(b' ');
                line.int(decimals, f.vertices[k] + 1);
                line.byte(b'/');
                line.int(decimals, f.uvs[k] + 1);
            }
            line.byte(b'\n');
            text.push_line(&line);
            text.line_end()?;
        }
        Ok(())
    }

    fn texture_png(&self) -> Vec<u8> {
        const FABRIC: [u8; 3] = [0xd8, 0xc8, 0xb0];
        let uvs = self.uvs();
        let n = TEXTURE_SIZE;
        let mut rgb = blank_image(n);
        let scale = n as f64;
        for f in &self.mesh.faces {
            // Image rows run down, texture v up.
            let corners = f.uvs.map(|t| Vec2::new(uvs[t].x * scale, (1.0 - uvs[t].y) * scale));
            fill_triangle(&mut rgb, n, corners, FABRIC);
        }
        encode_texture(&rgb, n)
    }

    fn material(&self, text: &mut Chunked) {
        let _ = write!(
            text.buf,
            "newmtl panels_texture\nNs 0.000000\nKa 1.000000 1.000000 1.000000\nKs 0.000000 0.000000 0.000000\n\
             Ke 0.000000 0.000000 0.000000\nNi 1.000000\nd 1.000000\nillum 1\nmap_Kd {}_texture_fabric.png\n",
            self.mesh.file_prefix()
        );
    }

    fn segmentation(&self, text: &mut Chunked) -> io::Result<()> {
        let (m, decimals) = (&*self.mesh, self.decimals());
        let mut line = Line::new();
        for label in &m.labels {
            match label {
                VertexLabel::Stitch(ks) => {
                    for (i, k) in ks.iter().enumerate() {
                        text.buf.extend_from_slice(if i == 0 { b"stitch_" } else { b",stitch_" });
                        line.clear();
                        line.int(decimals, *k);
                        text.push_line(&line);
                    }
                }
                VertexLabel::Panel(p) => text.buf.extend_from_slice(m.panels[*p].name.as_bytes()),
            }
            text.buf.push(b'\n');
            text.line_end()?;
        }
        Ok(())
    }

    fn rest_lengths_pickle(&self, out: &mut dyn Write) -> io::Result<()> {
        let lengths = &self.mesh.rest_lengths;
        let mut buf = Vec::with_capacity((16 + 20 * lengths.len()).min(CHUNK + 4096));
        buf.extend_from_slice(&[0x80, 2, b'}']);
        for chunk in lengths.chunks(1000) {
            buf.push(b'(');
            for ([i, j], len) in chunk {
                for id in [i, j] {
                    buf.push(b'J');
                    buf.extend_from_slice(&(*id as i32).to_le_bytes());
                }
                buf.push(0x86);
                buf.push(b'G');
                buf.extend_from_slice(&len.to_be_bytes());
            }
            buf.push(b'u');
            if buf.len() >= CHUNK {
                out.write_all(&buf)?;
                buf.clear();
            }
        }
        buf.push(b'.');
        out.write_all(&buf)
    }

    fn vertex_labels_yaml(&self, text: &mut Chunked) -> io::Result<()> {
        let (labels, decimals) = (&self.mesh.vertex_labels, self.decimals());
        if labels.is_empty() {
            text.buf.extend_from_slice(b"{}\n");
        }
        let mut line = Line::new();
        for (label, ids) in labels {
            let _ = writeln!(text.buf, "{}:", yaml_key(label));
            if ids.is_empty() {
                text.buf.pop();
                text.buf.extend_from_slice(b" []\n");
            }
            for id in ids {
                line.clear();
                line.byte(b'-');
                line.byte(b' ');
                line.int(decimals, *id);
                line.byte(b'\n');
                text.push_line(&line);
                text.line_end()?;
            }
        }
        Ok(())
    }

    fn welded_obj_metres(&self, text: &mut Chunked) -> io::Result<()> {
        let (m, decimals) = (&*self.mesh, self.decimals());
        for v in &m.vertices {
            text.buf.extend_from_slice(b"v ");
            push_xyz_line(&mut text.buf, *v / 100.0);
            text.buf.push(b'\n');
            text.line_end()?;
        }
        let mut line = Line::new();
        for f in &m.faces {
            line.clear();
            line.byte(b'f');
            for v in f.vertices {
                line.byte(b' ');
                line.int(decimals, v + 1);
            }
            line.byte(b'\n');
            text.push_line(&line);
            text.line_end()?;
        }
        Ok(())
    }

    fn ply(&self, text: &mut Chunked) -> io::Result<()> {
        let (m, xyz, decimals) = (&*self.mesh, self.xyz(), self.decimals());
        text.buf.extend_from_slice(b"ply\nformat ascii 1.0\ncomment garmentcode box mesh, cm\n");
        for (i, p) in m.panels.iter().enumerate() {
            let _ = writeln!(text.buf, "comment panel {i} {}", p.name);
            text.line_end()?;
        }
        let _ = write!(
            text.buf,
            "element vertex {}\nproperty double x\nproperty double y\nproperty double z\nproperty int segment\nproperty int stitch\n\
             element face {}\nproperty list uchar int vertex_indices\nend_header\n",
            m.vertices.len(),
            m.faces.len()
        );
        let mut line = Line::new();
        for (v, label) in m.labels.iter().enumerate() {
            text.buf.extend_from_slice(xyz.get(v));
            // ` segment stitch`: the panel and -1, or -1 and the first stitch (-1 if none).
            line.clear();
            line.byte(b' ');
            match label {
                VertexLabel::Stitch(ks) => {
                    line.byte(b'-');
                    line.byte(b'1');
                    line.byte(b' ');
                    match ks.first() {
                        Some(&k) => line.int(decimals, k),
                        None => {
                            line.byte(b'-');
                            line.byte(b'1');
                        }
                    }
                }
                VertexLabel::Panel(p) => {
                    line.int(decimals, *p);
                    line.byte(b' ');
                    line.byte(b'-');
                    line.byte(b'1');
                }
            }
            line.byte(b'\n');
            text.push_line(&line);
            text.line_end()?;
        }
        for f in &m.faces {
            line.clear();
            line.byte(b'3');
            for v in f.vertices {
                line.byte(b' ');
                line.int(decimals, v);
            }
            line.byte(b'\n');
            text.push_line(&line);
            text.line_end()?;
        }
        Ok(())
    }
}

/// The PNG of the `n`×`n` RGB image `rgb` (from [`blank_image`]).
fn encode_texture(rgb: &[u8], n: usize) -> Vec<u8> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, n as u32, n as u32);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    // fdeflate's fast compressor after the "up" filter on every row: the texture's rows
    // mostly repeat the row above, so each filters to zeros in one pass (the adaptive
    // filter tried all five on every row).
    enc.set_compression(png::Compression::Fastest);
    // Writing into memory cannot fail for an image of the size declared.
    let mut writer = enc.write_header().expect("PNG header in memory");
    writer.write_image_data(&rgb[..3 * n * n]).expect("PNG data in memory");
    writer.finish().expect("PNG end in memory");
    out
}

/// Pixels of a row [`fill_triangle`] tests together.
const GROUP: usize = 4;

/// A white `n`×`n` RGB image for [`fill_triangle`], with the room it needs past the end
/// (the image is `image[..3 * n * n]`).
fn blank_image(n: usize) -> Vec<u8> {
    vec![0xff; 3 * (n * n + GROUP)]
}

/// Paints `colour` over the pixels of the `n`×`n` RGB image `rgb` (white or `colour`,
/// from [`blank_image`]) whose centres lie inside or on the triangle `[a, b, c]` (pixel
/// units): where each edge function `(end − start).perp_dot(p − start)` has the sign of
/// the triangle's doubled area, or is 0. A degenerate triangle paints nothing.
///
/// The mesh's triangles are a few pixels wide, so a row of the triangle's bounding box is
/// tested [`GROUP`] pixels at a time without a branch ([`paint_group`]): pixels past the
/// box (past the image's end, its padding) are left as they are, inside ones are painted
/// by `&` (white is all ones). Each edge function's term in the row's height is computed
/// once per row, by the same operations as `perp_dot` (so the same bits).
fn fill_triangle(rgb: &mut [u8], n: usize, [a, b, c]: [Vec2; 3], colour: [u8; 3]) {
    let area = (b - a).perp_dot(c - a);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let scale = n as f64;
    // The pixels whose centres the triangle's bounding box holds, within the image.
    let (lo, hi) = (a.min(b).min(c), a.max(b).max(c));
    let (x0, x1) = (floor_within(lo.x, scale), ceil_within(hi.x, scale));
    let (y0, y1) = (floor_within(lo.y, scale), ceil_within(hi.y, scale));
    let starts = [a, b, c];
    let edges = [b - a, c - b, a - c];
    for y in y0..y1 {
        let py = y as f64 + 0.5;
        let row = Row { terms: [0, 1, 2].map(|k| edges[k].x * (py - starts[k].y)), edges, starts, area, end: x1 };
        let mut x = x0;
        while x < x1 {
            let at = 3 * (y * n + x);
            let pixels = (&mut rgb[at..at + 3 * GROUP]).try_into().expect("a group of pixels");
            // Pixel indices are below `n`, a few hundred: exact as `u32`, whose conversion
            // to `f64` is one instruction (that of `usize` is a dozen).
            paint_group(pixels, x as u32, &row, colour);
            x += GROUP;
        }
    }
}

/// One row of a triangle for [`paint_group`].
struct Row {
    /// Each edge function's term in the row's height, `edge.x · (py − start.y)`.
    terms: [f64; 3],
    edges: [Vec2; 3],
    starts: [Vec2; 3],
    /// The triangle's doubled area.
    area: f64,
    /// The first pixel past the triangle's bounding box.
    end: usize,
}

/// Paints the pixels `x..x + GROUP` of a row of [`fill_triangle`] (`pixels`, RGB) whose
/// centres pass the row's three edge tests, without a branch. Not inlined: inlined, the
/// compiler vectorises the loop over groups, which for the usual one group a row costs more
/// than it saves.
#[inline(never)]
fn paint_group(pixels: &mut [u8; 3 * GROUP], x: u32, row: &Row, colour: [u8; 3]) {
    let first = f64::from(x) + 0.5;
    // 0xff for a pixel to paint, 0 for one to leave.
    let paint: [u8; GROUP] = std::array::from_fn(|lane| {
        // Exact: a whole number and a half below 2^32.
        let px = first + lane as f64;
        let inside = (0..3).fold(x as usize + lane < row.end, |inside, k| {
            inside & ((row.terms[k] - row.edges[k].y * (px - row.starts[k].x)) * row.area >= 0.0)
        });
        0u8.wrapping_sub(u8::from(inside))
    });
    for (i, channel) in pixels.iter_mut().enumerate() {
        *channel &= !paint[i / 3] | colour[i % 3];
    }
}

/// `x.floor()` limited to `0..=max` (a whole number), as a pixel index, without a call to
/// the maths library (`x` is finite).
fn floor_within(x: f64, max: f64) -> usize {
    // For x ≥ 0 the conversion truncates, which is the floor; below 0 it gives 0, as
    // `x.floor().max(0.0)` does.
    x.min(max) as usize
}

/// `x.ceil()` limited to `0..=max` (a whole number), as a pixel index (`x` is finite).
fn ceil_within(x: f64, max: f64) -> usize {
    let x = x.min(max);
    let t = x as usize;
    // The conversion truncates (to 0 below 0); a fraction left over rounds up.
    if (t as f64) < x { t + 1 } else { t }
}

/// A text file being written: laid out in `buf`, handed to `out` a chunk at a time.
struct Chunked<'w> {
    buf: Vec<u8>,
    out: &'w mut dyn Write,
}

impl Chunked<'_> {
    /// After a line: hands the text on once a chunk's worth is laid out.
    fn line_end(&mut self) -> io::Result<()> {
        if self.buf.len() >= CHUNK {
            self.out.write_all(&self.buf)?;
            self.buf.clear();
        }
        Ok(())
    }

    /// Appends a line laid out on the stack. A short line (every line but one of huge
    /// indices) goes in by a copy of fixed length, which the compiler lays out inline
    /// instead of calling `memcpy` for each line; the bytes past the line's end are cut off.
    fn push_line(&mut self, line: &Line) {
        if line.len <= SHORT_LINE {
            let at = self.buf.len();
            self.buf.extend_from_slice(&line.bytes[..SHORT_LINE]);
            self.buf.truncate(at + line.len);
        } else {
            self.buf.extend_from_slice(line.bytes());
        }
    }

    /// Hands the rest on.
    fn finish(self) -> io::Result<()> {
        self.out.write_all(&self.buf)
    }
}

/// Longest line [`Line`] lays out: "f" and three pairs of 20-digit indices, with room for
/// the last 8-byte copy.
const LINE: usize = 160;

/// Length of the fixed copy of [`Chunked::push_line`]: a face line of the box OBJ with
/// indices below 10^8 (the decimals' table) and room to spare.
const SHORT_LINE: usize = 64;

/// One line of a file laid out on the stack, then appended to the file in one copy.
struct Line {
    bytes: [u8; LINE],
    len: usize,
}

impl Line {
    fn new() -> Line {
        Line { bytes: [0; LINE], len: 0 }
    }

    fn clear(&mut self) {
        self.len = 0;
    }

    fn byte(&mut self, b: u8) {
        self.bytes[self.len] = b;
        self.len += 1;
    }

    /// Appends the decimal text of `n`: an 8-byte copy from `decimals`, whose bytes
    /// past the number's are overwritten by what follows (or left out of the line).
    fn int(&mut self, decimals: &Decimals, n: usize) {
        match decimals.slots.get(n) {
            Some(&(slot, len)) => {
                self.bytes[self.len..self.len + 8].copy_from_slice(&slot);
                self.len += usize::from(len);
            }
            None => {
                let mut buf = itoa::Buffer::new();
                let text = buf.format(n).as_bytes();
                self.bytes[self.len..self.len + text.len()].copy_from_slice(text);
                self.len += text.len();
            }
        }
    }

    fn bytes(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

/// The decimal text of the whole numbers below some bound (at most 10^8), each in an
/// 8-byte slot with its length: the indices of a mesh's lines, laid out once.
struct Decimals {
    slots: Vec<([u8; 8], u8)>,
}

impl Decimals {
    /// The numbers `0..=max` (at most `10^8 − 1`; [`Line::int`] lays out larger ones itself).
    fn new(max: usize) -> Decimals {
        let slots = (0..=max.min(99_999_999))
            .map(|i| {
                let mut buf = itoa::Buffer::new();
                let text = buf.format(i).as_bytes();
                let mut slot = [0u8; 8];
                slot[..text.len()].copy_from_slice(text);
                (slot, text.len() as u8)
            })
            .collect();
        Decimals { slots }
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
    text: Vec<u8>,
    /// Vertex `i`'s text ends at `ends[i]` (and starts at `ends[i - 1]`).
    ends: Vec<usize>,
}

impl Coordinates {
    fn new(vertices: &[Vec3]) -> Coordinates {
        let mut text = Vec::with_capacity(72 * vertices.len());
        let ends = vertices
            .iter()
            .map(|v| {
                push_xyz_line(&mut text, *v);
                text.len()
            })
            .collect();
        Coordinates { text, ends }
    }

    fn get(&self, i: usize) -> &[u8] {
        &self.text[if i == 0 { 0 } else { self.ends[i - 1] }..self.ends[i]]
    }
}

/// `x y z` in Python's float repr (shortest round trip), without a line end.
fn push_xyz_line(out: &mut Vec<u8>, v: Vec3) {
    write_python_float(out, v.x);
    out.push(b' ');
    write_python_float(out, v.y);
    out.push(b' ');
    write_python_float(out, v.z);
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

/// The labels of a segmentation file, one per vertex (each a list of comma-separated entries).
pub fn read_segmentation(text: &str) -> Vec<Vec<String>> {
    text.lines().map(|l| l.split(',').map(str::to_string).collect()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Indices are written as their decimal text, from the table and past its end alike,
    /// whatever follows them on the line.
    #[test]
    fn lines_of_indices_read_as_the_numbers() {
        let decimals = Decimals::new(120);
        let mut line = Line::new();
        for n in (0..=250).chain([999, 1_000_000, 99_999_999, 100_000_000, usize::MAX]) {
            line.clear();
            line.byte(b'f');
            for k in 0..3 {
                line.byte(b' ');
                line.int(&decimals, n.saturating_add(k));
                line.byte(b'/');
                line.int(&decimals, n);
            }
            line.byte(b'\n');
            let expected = format!("f {n}/{n} {}/{n} {}/{n}\n", n.saturating_add(1), n.saturating_add(2));
            assert_eq!(std::str::from_utf8(line.bytes()).unwrap(), expected);
        }
    }

    /// `fill_triangle` paints exactly the pixels whose centres pass the three edge tests
    /// written out in full (`perp_dot` of the whole vectors, per pixel), for triangles of
    /// both windings, with corners on pixel centres and corners (edges through centres),
    /// thin and degenerate ones, and ones reaching past the image.
    #[test]
    fn triangles_paint_the_pixels_whose_centres_they_hold() {
        const N: usize = 24;
        const COLOUR: [u8; 3] = [0xd8, 0xc8, 0xb0];
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for i in 0..3000 {
            let mut coordinate = || match next() % 4 {
                // On a pixel centre or corner, so that edges run through centres.
                0 => (next() % 52) as f64 * 0.5 - 1.0,
                _ => (next() % 1_000_000) as f64 * (N as f64 + 4.0) / 1e6 - 2.0,
            };
            let mut corners = [0; 3].map(|_| Vec2::new(coordinate(), coordinate()));
            if i % 7 == 0 {
                corners[2] = corners[0] + (corners[1] - corners[0]) * 0.5; // degenerate
            }
            let mut painted = blank_image(N);
            fill_triangle(&mut painted, N, corners, COLOUR);
            let [a, b, c] = corners;
            let area = (b - a).perp_dot(c - a);
            for y in 0..N {
                for x in 0..N {
                    let p = Vec2::new(x as f64 + 0.5, y as f64 + 0.5);
                    let w = [(b - a).perp_dot(p - a), (c - b).perp_dot(p - b), (a - c).perp_dot(p - c)];
                    let inside = area != 0.0 && w.iter().all(|w| w * area >= 0.0);
                    let expected = if inside { COLOUR } else { [0xff; 3] };
                    assert_eq!(painted[3 * (y * N + x)..3 * (y * N + x) + 3], expected, "triangle {corners:?}, pixel ({x}, {y})");
                }
            }
            assert!(painted[3 * N * N..].iter().all(|&b| b == 0xff), "the padding is left white");
            // Painting over fabric keeps it.
            let before = painted.clone();
            fill_triangle(&mut painted, N, corners, COLOUR);
            assert_eq!(painted, before);
        }
    }

    /// The texture's PNG decodes to the image painted, pixel for pixel.
    #[test]
    fn the_texture_decodes_to_the_painted_pixels() {
        const N: usize = 64;
        let mut rgb = blank_image(N);
        let triangles =
            [[(3.2, 4.1), (40.5, 9.0), (20.0, 50.7)], [(50.0, 50.0), (63.9, 60.2), (45.1, 63.5)], [(0.0, 0.0), (2.0, 0.5), (1.0, 3.0)]];
        for (i, corners) in triangles.into_iter().enumerate() {
            let colour = [0xd8, 0xc8 - i as u8, 0xb0];
            fill_triangle(&mut rgb, N, corners.map(|(x, y)| Vec2::new(x, y)), colour);
        }
        let png = encode_texture(&rgb, N);
        let mut reader = png::Decoder::new(std::io::Cursor::new(&png)).read_info().expect("a PNG");
        let mut pixels = vec![0; reader.output_buffer_size().expect("a small image")];
        let info = reader.next_frame(&mut pixels).expect("one frame");
        assert_eq!(
            (info.width, info.height, info.color_type, info.bit_depth),
            (N as u32, N as u32, png::ColorType::Rgb, png::BitDepth::Eight)
        );
        assert_eq!(pixels[..info.buffer_size()], rgb[..3 * N * N]);
    }

    /// The texture's pixel bounds are the floor and ceiling of the triangle's bounds,
    /// limited to the image, as `f64::floor` and `f64::ceil` give them.
    #[test]
    fn pixel_bounds_are_floor_and_ceiling() {
        let max = 512.0;
        for i in -2000..=2000 {
            for x in [i as f64 * 0.37, i as f64, i as f64 + 0.5, i as f64 - 1e-12, -0.0] {
                assert_eq!(floor_within(x, max), x.floor().clamp(0.0, max) as usize, "{x}");
                assert_eq!(ceil_within(x, max), x.ceil().clamp(0.0, max) as usize, "{x}");
            }
        }
    }
}
