//! Pictures of a drape: the garment on the body, shaded, seen from the front or the back
//! (`NAME_render_front.png`, `NAME_render_back.png`, as GarmentCodeData has them).
//!
//! A small software z-buffer rasteriser: orthographic view along the z axis, smooth
//! (per-pixel interpolated) normals, one directional light and an ambient term, 2×2
//! supersampling, PNG via the `png` crate the workspace already uses. Why not a crate: the
//! 3D renderers for Rust (wgpu-, OpenGL- or Vulkan-based) need a GPU or a display and pull
//! in hundreds of dependencies, and the CPU path tracers are far slower than this for a
//! picture that only has to show how a garment sits; the whole job is a hundred lines.
//! The output is deterministic: the same meshes give the same bytes.

use garmentcode::Vec3;
use garmentcode::mesh::BoxMesh;

use crate::BodyMesh;

/// Which side the drape is seen from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// From +z looking towards −z (the reference bodies face +z).
    Front,
    /// From −z.
    Back,
}

/// Width and height of the pictures (px): the reference's render resolution.
pub const SIZE: u32 = 800;

/// Garment colour (linear RGB, 0–1): the reference's ochre render colour.
pub(crate) const GARMENT: [f64; 3] = [0.636, 0.435, 0.048];
/// Body colour.
pub(crate) const BODY: [f64; 3] = [0.78, 0.78, 0.8];
/// Share of the frame left empty around the meshes, each side.
const MARGIN: f64 = 0.04;

/// A mesh to draw: vertices, triangles, colour.
type Layer<'a> = (&'a [Vec3], &'a [[u32; 3]], [f64; 3]);

/// Area-weighted vertex normals of a triangle mesh (unit; +y for a vertex of no area).
pub(crate) fn vertex_normals(positions: &[Vec3], faces: &[[u32; 3]]) -> Vec<Vec3> {
    let mut n = vec![Vec3::ZERO; positions.len()];
    for f in faces {
        let [a, b, c] = f.map(|i| positions[i as usize]);
        let face = (b - a).cross(c - a);
        for &i in f {
            n[i as usize] += face;
        }
    }
    n.into_iter().map(|v| v.try_normalize().unwrap_or(Vec3::Y)).collect()
}

/// The garment's triangles as index triples.
pub(crate) fn garment_faces(mesh: &BoxMesh) -> Vec<[u32; 3]> {
    mesh.faces.iter().map(|f| f.vertices.map(|i| i as u32)).collect()
}

/// A PNG of the draped garment (`positions`, one per box-mesh vertex, cm) on `body`, from
/// `side`, [`SIZE`] × [`SIZE`] px on white, framed to fit both.
///
/// # Panics
/// If `positions` does not have one entry per box-mesh vertex.
pub fn render_png(mesh: &BoxMesh, positions: &[Vec3], body: Option<&BodyMesh>, side: Side) -> Vec<u8> {
    assert_eq!(positions.len(), mesh.vertices.len(), "one position per box-mesh vertex");
    let garment_faces = garment_faces(mesh);
    let mut layers: Vec<Layer> = vec![(positions, &garment_faces, GARMENT)];
    if let Some(b) = body {
        layers.push((&b.vertices, &b.faces, BODY));
    }
    // View space: x right, y up, z towards the viewer.
    let view = |p: Vec3| match side {
        Side::Front => p,
        Side::Back => Vec3::new(-p.x, p.y, -p.z),
    };
    let (mut lo, mut hi) = (Vec3::splat(f64::INFINITY), Vec3::splat(f64::NEG_INFINITY));
    for (v, _, _) in &layers {
        for p in v.iter().filter(|p| p.is_finite()) {
            lo = lo.min(view(*p));
            hi = hi.max(view(*p));
        }
    }
    let px = 2 * SIZE as usize; // supersampled
    let extent = (hi - lo).x.max((hi - lo).y).max(1e-6);
    let scale = px as f64 * (1.0 - 2.0 * MARGIN) / extent;
    let centre = (lo + hi) * 0.5;
    let to_screen = |p: Vec3| {
        let q = view(p) - centre;
        Vec3::new(px as f64 * 0.5 + q.x * scale, px as f64 * 0.5 - q.y * scale, q.z)
    };
    let light = Vec3::new(-0.35, 0.5, 1.0).normalize();
    let mut depth = vec![f64::NEG_INFINITY; px * px];
    let mut color = vec![[1.0f64; 3]; px * px];
    for (vertices, faces, base) in layers {
        let screen: Vec<Vec3> = vertices.iter().map(|&p| to_screen(p)).collect();
        let normals: Vec<Vec3> = vertex_normals(vertices, faces).into_iter().map(view).collect();
        for f in faces {
            let [a, b, c] = f.map(|i| screen[i as usize]);
            if !(a.is_finite() && b.is_finite() && c.is_finite()) {
                continue;
            }
            let area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
            if area.abs() < 1e-12 {
                continue;
            }
            let x0 = a.x.min(b.x).min(c.x).floor().max(0.0) as usize;
            let x1 = (a.x.max(b.x).max(c.x).ceil().min(px as f64 - 1.0)).max(0.0) as usize;
            let y0 = a.y.min(b.y).min(c.y).floor().max(0.0) as usize;
            let y1 = (a.y.max(b.y).max(c.y).ceil().min(px as f64 - 1.0)).max(0.0) as usize;
            let [na, nb, nc] = f.map(|i| normals[i as usize]);
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let (sx, sy) = (x as f64 + 0.5, y as f64 + 0.5);
                    let wa = ((b.x - sx) * (c.y - sy) - (b.y - sy) * (c.x - sx)) / area;
                    let wb = ((c.x - sx) * (a.y - sy) - (c.y - sy) * (a.x - sx)) / area;
                    let wc = 1.0 - wa - wb;
                    if wa < 0.0 || wb < 0.0 || wc < 0.0 {
                        continue;
                    }
                    let z = wa * a.z + wb * b.z + wc * c.z;
                    let k = y * px + x;
                    if z <= depth[k] {
                        continue;
                    }
                    depth[k] = z;
                    let mut n = (na * wa + nb * wb + nc * wc).normalize_or_zero();
                    // Cloth has two sides: light the one facing the viewer.
                    if n.z < 0.0 {
                        n = -n;
                    }
                    let shade = 0.3 + 0.7 * n.dot(light).max(0.0);
                    color[k] = base.map(|c| c * shade);
                }
            }
        }
    }
    // 2×2 box filter, then sRGB-ish gamma.
    let size = SIZE as usize;
    let mut rgb = Vec::with_capacity(size * size * 3);
    for y in 0..size {
        for x in 0..size {
            let mut sum = [0.0; 3];
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let c = color[(2 * y + dy) * px + 2 * x + dx];
                (0..3).for_each(|i| sum[i] += c[i] / 4.0);
            }
            rgb.extend(sum.map(|c| (c.clamp(0.0, 1.0).powf(1.0 / 2.2) * 255.0).round() as u8));
        }
    }
    encode_rgb(&rgb, SIZE, SIZE)
}

/// PNG bytes of an 8-bit RGB image.
fn encode_rgb(rgb: &[u8], width: u32, height: u32) -> Vec<u8> {
    let mut out = Vec::new();
    let mut enc = png::Encoder::new(&mut out, width, height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    // Writing into memory cannot fail, and the header matches the data.
    let mut writer = enc.write_header().expect("PNG header into memory");
    writer.write_image_data(rgb).expect("PNG data of the declared size");
    writer.finish().expect("PNG into memory");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Decoded RGB pixels of a PNG.
    fn pixels(png_bytes: &[u8]) -> (u32, u32, Vec<u8>) {
        let mut reader = png::Decoder::new(std::io::Cursor::new(png_bytes)).read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size().unwrap()];
        let info = reader.next_frame(&mut buf).unwrap();
        (info.width, info.height, buf[..info.buffer_size()].to_vec())
    }

    #[test]
    fn the_garment_is_drawn_shaded_on_white_and_deterministically() {
        let spec = include_str!("../tests/data/waistband_specification.json");
        let mesh = BoxMesh::new(&garmentcode::Pattern::from_json(spec).unwrap(), 1.0).unwrap();
        let png = render_png(&mesh, &mesh.vertices, None, Side::Front);
        assert_eq!(png, render_png(&mesh, &mesh.vertices, None, Side::Front));
        let (w, h, rgb) = pixels(&png);
        assert_eq!((w, h), (SIZE, SIZE));
        let at = |x: u32, y: u32| &rgb[3 * (y * w + x) as usize..3 * (y * w + x) as usize + 3];
        assert_eq!(at(0, 0), [255, 255, 255], "background");
        // The band fills the frame's width: its middle row crosses cloth (ochre: red > blue).
        let row = h / 2;
        let cloth = (0..w).filter(|&x| i32::from(at(x, row)[0]) > i32::from(at(x, row)[2]) + 40).count();
        assert!(cloth > w as usize / 2, "{cloth} cloth pixels in the middle row");
    }
}
