//! What to draw: the arrangement of panels and the drawing options.

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
            other => Err(format!("unknown layout {} (expected placed or flat)", crate::message::quote(other))),
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
