//! Drawings of a pattern (PROVISIONAL: replaced by the full SVG/PNG module).

use crate::error::{Error, Result};
use crate::pattern::Pattern;

/// Drawing options.
#[derive(Clone, Debug, Default)]
pub struct DrawOptions {}

/// SVG drawing.
pub fn to_svg(p: &Pattern, _opts: &DrawOptions) -> Result<String> {
    if p.panels.is_empty() {
        return Err(Error::Design("cannot draw an empty pattern".into()));
    }
    Ok(String::from("<svg xmlns=\"http://www.w3.org/2000/svg\"/>\n"))
}

/// PNG drawing.
pub fn to_png(_p: &Pattern, _opts: &DrawOptions) -> Result<Vec<u8>> {
    Err(Error::Design("PNG drawing is not available yet".into()))
}
