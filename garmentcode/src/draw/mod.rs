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
//! stitch gets a colour and a numbered marker (its index in `pattern.stitches`) at the
//! arc-length midpoint of both of its edges, just inside the panel, with the edges
//! themselves traced in that colour, so one sees what sews to what. Vertex and edge
//! indices (the reference's `view_ids`) can be switched on.
//!
//! Both outputs are built from one layout of the sheet, so the PNG shows exactly
//! what the SVG describes, and both are deterministic: the same pattern and options
//! give the same bytes. Text in the PNG uses a small built-in stroke font, so no
//! system fonts are needed.

mod font;
mod layout;
mod raster;
mod svg;

#[cfg(test)]
mod tests;

use crate::error::Result;
use crate::pattern::Pattern;

/// How panels are arranged on the sheet.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Layout {
    /// As the reference draws them: each panel at its flattened 3D position, front
    /// panels on the left and back panels on the right (panels may overlap, as on
    /// the body).
    #[default]
    Placed,
    /// Side by side without overlap, in rows at most [`FLAT_ROW_WIDTH`] cm wide
    /// (or as wide as the widest panel), in the pattern's panel order: a sheet to
    /// print and cut from. Panels keep their orientation.
    Flat,
}

/// Row width of [`Layout::Flat`], in cm (a 150 cm bolt of fabric).
pub const FLAT_ROW_WIDTH: f64 = 150.0;

impl std::str::FromStr for Layout {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<Layout, String> {
        match s {
            "placed" => Ok(Layout::Placed),
            "flat" => Ok(Layout::Flat),
            other => Err(format!("unknown layout '{other}' (expected placed or flat)")),
        }
    }
}

/// What to draw and at which resolution.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawOptions {
    /// Arrangement of the panels.
    pub layout: Layout,
    /// Panel names at the centre of each panel (the reference's `with_text`).
    pub with_text: bool,
    /// Vertex indices at vertices and edge indices at edge midpoints (the
    /// reference's `view_ids`).
    pub view_ids: bool,
    /// Numbered, coloured markers on both edges of every stitch.
    pub stitch_markers: bool,
    /// Free space around the panels, in cm (the reference uses 2).
    pub margin: f64,
    /// PNG resolution in pixels per cm (the reference rasterises at 3).
    pub px_per_cm: f64,
    /// PNG background; `None` keeps it transparent, as the reference's PNG.
    pub background: Option<[u8; 3]>,
}

impl Default for DrawOptions {
    fn default() -> Self {
        DrawOptions {
            layout: Layout::Placed,
            with_text: true,
            view_ids: false,
            stitch_markers: true,
            margin: 2.0,
            px_per_cm: 3.0,
            background: None,
        }
    }
}

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
pub fn to_png(p: &Pattern, opts: &DrawOptions) -> Result<Vec<u8>> {
    let sheet = layout::layout(p, opts)?;
    raster::render(&sheet, opts)
}
