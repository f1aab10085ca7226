//! Drawings of a flat sewing pattern: an SVG document and its PNG rendering.
//!
//! The picture follows the reference's placed drawing (`VisPattern.get_svg`,
//! pattern-format.md §11) so that users of the reference recognise it: each panel is
//! flipped to y-down, rotated by the in-plane angle of its 3D rotation and moved to its
//! flattened 3D position; front panels (translation z ≥ 0) are drawn on the left, back
//! panels shifted to the right of them; sizes are centimetres, filled in the
//! reference's pink with its outline and panel names.
//!
//! On top of that the drawing marks the stitches (the reference draws none): every
//! stitch gets a colour and a numbered marker (its index in `pattern.stitches`; the
//! format extension's inner stitches are numbered on after them, as the box mesh's
//! `stitch_K` labels count them) on both of its edges (on a hole or inner line for an
//! inner stitch), with the edges themselves traced in that colour, so one sees what
//! sews to what. Vertex and edge indices (the reference's `view_ids`) can be
//! switched on.
//!
//! Markers never overlap each other or a panel name. Where many short stitched
//! edges come together (darts, collars, cuffs, waistbands) they cannot all sit at
//! their edges' midpoints, so each marker is placed in turn, in stitch order, at
//! the first free spot of a fixed search: just inside the panel at the arc-length
//! midpoint of its edge, then at points further along the edge, then a row or two
//! deeper into the panel, then all of that again with a smaller disc (down to 70%);
//! a marker with no room inside goes outside the panel, to the nearest free spot
//! around its edge's midpoint, with a leader line to the edge. The boxes compared
//! are the discs' and the names' (names estimated as the PNG's font sets them, or
//! at 0.6 em per character when that is wider). The sheet grows to hold markers
//! outside the panels.
//!
//! Holes and inner lines of the format extension (`docs/pattern-extension.md`) are
//! drawn inside their panels: a cut-out as an opening (the outline path's even-odd
//! fill), a dart as a dashed loop, a fold line dash-dot with the word "fold", a
//! placement line dashed, a pleat's fold in long dashes and its placement dotted.
//!
//! Both outputs are built from one layout of the sheet, so the PNG shows exactly
//! what the SVG describes, and both are deterministic: the same pattern and options
//! give the same bytes. Text in the PNG uses a small built-in stroke font, so no
//! system fonts are needed. The PNG output (and its dependencies, `tiny-skia` and
//! `png`) is behind the `png` cargo feature, on by default.

mod font;
mod layout;
mod options;
#[cfg(feature = "png")]
mod raster;
mod svg;

#[cfg(all(test, feature = "png"))]
mod tests;

pub use options::{DrawOptions, FLAT_ROW_WIDTH, Layout};
#[cfg(feature = "png")]
pub use raster::MAX_PNG_PIXELS;

use crate::error::Result;
use crate::pattern::Pattern;

/// The placed drawing of `p` as an SVG document (sizes in cm, y down).
///
/// Fails on an empty pattern ([`Error::Design`](crate::Error::Design), as the
/// reference refuses to draw one) and, with [`Error::Input`](crate::Error::Input), on
/// edges or stitches that refer to missing vertices, panels or edges and on
/// non-finite numbers.
///
/// ```
/// use garmentcode::draw::{DrawOptions, to_svg};
/// use garmentcode::{Arena, EdgeSeq, PartExt, Pattern, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 30.0), Vec2::new(20.0, 30.0), Vec2::new(20.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("front", edges);
/// let pattern = PartExt::assemble(&panel, &mut a, "demo")?;
/// let svg = to_svg(&pattern, &DrawOptions::default())?;
/// assert!(svg.contains("<svg") && svg.contains(">front<"));
/// assert!(to_svg(&Pattern::new("empty"), &DrawOptions::default()).is_err());
/// # Ok::<(), garmentcode::Error>(())
/// ```
pub fn to_svg(p: &Pattern, opts: &DrawOptions) -> Result<String> {
    let sheet = layout::layout(p, opts)?;
    Ok(svg::write(&sheet, &p.name))
}

/// The same drawing as [`to_svg`], rasterised with anti-aliasing at
/// `opts.px_per_cm` and encoded as PNG.
///
/// The image is `ceil(view box size × px_per_cm)` pixels wide and high (the
/// reference's rasteriser rounds instead, so its PNG can be one pixel smaller), RGBA,
/// transparent outside the panels unless `opts.background` is set.
///
/// An image of more than [`MAX_PNG_PIXELS`] pixels is drawn at the highest
/// resolution within it instead (see [`render_png`] to learn which).
///
/// Needs the `png` feature (on by default).
#[cfg(feature = "png")]
pub fn to_png(p: &Pattern, opts: &DrawOptions) -> Result<Vec<u8>> {
    render_png(p, opts).map(|png| png.bytes)
}

/// A PNG drawing and the resolution it was drawn at.
#[cfg(feature = "png")]
#[derive(Clone, Debug)]
pub struct Png {
    /// The PNG file.
    pub bytes: Vec<u8>,
    /// Pixels per cm: `opts.px_per_cm`, or less when the image would have had
    /// more than [`MAX_PNG_PIXELS`] pixels (the PNG's `Comment` chunk says so).
    pub px_per_cm: f64,
}

/// [`to_png`], with the resolution it was drawn at.
///
/// ```
/// use garmentcode::draw::{DrawOptions, MAX_PNG_PIXELS, render_png};
/// use garmentcode::{Arena, EdgeSeq, PartExt, Vec2};
///
/// let mut a = Arena::new();
/// let corners = [Vec2::ZERO, Vec2::new(0.0, 300.0), Vec2::new(200.0, 300.0), Vec2::new(200.0, 0.0)];
/// let edges = EdgeSeq::from_points(&mut a, &corners, true)?;
/// let panel = a.panel_with_edges("front", edges);
/// let pattern = PartExt::assemble(&panel, &mut a, "demo")?;
/// // 400 px per cm would be 100,000 × 150,000 px: drawn smaller instead.
/// let png = render_png(&pattern, &DrawOptions { px_per_cm: 400.0, ..Default::default() })?;
/// assert!(png.px_per_cm < 400.0);
/// let (w, h) = (u32::from_be_bytes(png.bytes[16..20].try_into().unwrap()), u32::from_be_bytes(png.bytes[20..24].try_into().unwrap()));
/// assert!(u64::from(w) * u64::from(h) <= MAX_PNG_PIXELS);
/// # Ok::<(), garmentcode::Error>(())
/// ```
#[cfg(feature = "png")]
pub fn render_png(p: &Pattern, opts: &DrawOptions) -> Result<Png> {
    let sheet = layout::layout(p, opts)?;
    let (bytes, px_per_cm) = raster::render(&sheet, opts)?;
    Ok(Png { bytes, px_per_cm })
}
