//! A small stroke font for the PNG, so that rendering needs no system fonts and
//! gives the same pixels everywhere. The layout also measures names with it.
//!
//! Glyphs are polylines on a grid: x from 0 to the glyph width, y up from the
//! baseline (0), with the x-height at 8, capitals and ascenders at 12 and
//! descenders down to −4. The capital height is 0.7 em, close to common sans fonts,
//! so a text takes about the room the SVG's `font-size` gives it. Covered: `a–z`,
//! `A–Z`, `0–9`, `_ - . :` and space; anything else is drawn as a box.

use crate::math::Vec2;

/// Grid units of the capital height.
const CAP_UNITS: f64 = 12.0;
/// Capital height as a fraction of the font size.
pub const CAP_HEIGHT: f64 = 0.7;
/// x-height as a fraction of the font size.
#[cfg(feature = "png")]
pub const X_HEIGHT: f64 = CAP_HEIGHT * 8.0 / CAP_UNITS;
/// Space between glyphs, grid units.
const SPACING: f64 = 2.5;
/// Stroke width as a fraction of the font size.
#[cfg(feature = "png")]
pub const STROKE: f64 = 0.085;

/// Glyphs: character, width in grid units, strokes (`;`-separated polylines of
/// `,`-separated `x y` points).
const GLYPHS: &[(char, u8, &str)] = &[
    (' ', 4, ""),
    ('_', 6, "0 -2,6 -2"),
    ('-', 6, "1 5,5 5"),
    ('.', 2, "1 0,1 1"),
    (':', 2, "1 0,1 1;1 6,1 7"),
    ('0', 8, "3 0,1 2,0 5,0 7,1 10,3 12,5 12,7 10,8 7,8 5,7 2,5 0,3 0"),
    ('1', 8, "1 9,4 12,4 0;1 0,7 0"),
    ('2', 8, "0 10,2 12,6 12,8 10,8 8,0 0,8 0"),
    ('3', 8, "0 10,2 12,6 12,8 10,8 8,6 6,3 6;6 6,8 4,8 2,6 0,2 0,0 2"),
    ('4', 8, "6 0,6 12,0 4,8 4"),
    ('5', 8, "8 12,1 12,0 7,6 7,8 5,8 2,6 0,2 0,0 2"),
    ('6', 8, "7 11,5 12,3 12,1 10,0 7,0 2,2 0,6 0,8 2,8 5,6 7,2 7,0 5"),
    ('7', 8, "0 12,8 12,3 0"),
    ('8', 8, "2 6,0 8,0 10,2 12,6 12,8 10,8 8,6 6,2 6,0 4,0 2,2 0,6 0,8 2,8 4,6 6"),
    ('9', 8, "8 7,6 5,2 5,0 7,0 10,2 12,6 12,8 10,8 5,7 2,5 0,3 0,1 1"),
    ('A', 8, "0 0,4 12,8 0;1 3,7 3"),
    ('B', 8, "0 0,0 12,6 12,8 10,8 8,6 6,0 6;6 6,8 4,8 2,6 0,0 0"),
    ('C', 8, "8 10,6 12,2 12,0 10,0 2,2 0,6 0,8 2"),
    ('D', 8, "0 0,0 12,5 12,8 9,8 3,5 0,0 0"),
    ('E', 8, "8 12,0 12,0 0,8 0;0 6,6 6"),
    ('F', 8, "8 12,0 12,0 0;0 6,6 6"),
    ('G', 8, "8 10,6 12,2 12,0 10,0 2,2 0,6 0,8 2,8 6,5 6"),
    ('H', 8, "0 0,0 12;8 0,8 12;0 6,8 6"),
    ('I', 4, "2 0,2 12;0 12,4 12;0 0,4 0"),
    ('J', 8, "8 12,8 2,6 0,2 0,0 2"),
    ('K', 8, "0 0,0 12;8 12,0 4;3 7,8 0"),
    ('L', 8, "0 12,0 0,8 0"),
    ('M', 10, "0 0,0 12,5 5,10 12,10 0"),
    ('N', 8, "0 0,0 12,8 0,8 12"),
    ('O', 8, "2 0,0 2,0 10,2 12,6 12,8 10,8 2,6 0,2 0"),
    ('P', 8, "0 0,0 12,6 12,8 10,8 8,6 6,0 6"),
    ('Q', 8, "2 0,0 2,0 10,2 12,6 12,8 10,8 2,6 0,2 0;5 3,8 0"),
    ('R', 8, "0 0,0 12,6 12,8 10,8 8,6 6,0 6;4 6,8 0"),
    ('S', 8, "8 10,6 12,2 12,0 10,0 8,2 6,6 6,8 4,8 2,6 0,2 0,0 2"),
    ('T', 8, "0 12,8 12;4 12,4 0"),
    ('U', 8, "0 12,0 2,2 0,6 0,8 2,8 12"),
    ('V', 8, "0 12,4 0,8 12"),
    ('W', 10, "0 12,2 0,5 8,8 0,10 12"),
    ('X', 8, "0 0,8 12;0 12,8 0"),
    ('Y', 8, "0 12,4 6,8 12;4 6,4 0"),
    ('Z', 8, "0 12,8 12,0 0,8 0"),
    ('a', 7, "1 8,5 8,7 6,7 0;7 5,2 5,0 3,0 2,2 0,5 0,7 2"),
    ('b', 7, "0 12,0 0;0 6,2 8,5 8,7 6,7 2,5 0,2 0,0 2"),
    ('c', 7, "7 7,5 8,2 8,0 6,0 2,2 0,5 0,7 1"),
    ('d', 7, "7 12,7 0;7 6,5 8,2 8,0 6,0 2,2 0,5 0,7 2"),
    ('e', 7, "0 4,7 4,7 6,5 8,2 8,0 6,0 2,2 0,5 0,7 1"),
    ('f', 5, "5 12,3 12,2 11,2 0;0 8,5 8"),
    ('g', 7, "7 8,7 -2,5 -4,1 -4;7 6,5 8,2 8,0 6,0 2,2 0,5 0,7 2"),
    ('h', 7, "0 12,0 0;0 6,2 8,5 8,7 6,7 0"),
    ('i', 2, "1 0,1 8;1 10,1 11"),
    ('j', 4, "3 8,3 -2,1 -4,0 -4;3 10,3 11"),
    ('k', 6, "0 12,0 0;6 8,0 2;2 4,6 0"),
    ('l', 2, "1 12,1 0"),
    ('m', 10, "0 0,0 8;0 6,2 8,3 8,5 6,5 0;5 6,7 8,8 8,10 6,10 0"),
    ('n', 7, "0 0,0 8;0 6,2 8,5 8,7 6,7 0"),
    ('o', 7, "2 0,0 2,0 6,2 8,5 8,7 6,7 2,5 0,2 0"),
    ('p', 7, "0 8,0 -4;0 6,2 8,5 8,7 6,7 2,5 0,2 0,0 2"),
    ('q', 7, "7 8,7 -4;7 6,5 8,2 8,0 6,0 2,2 0,5 0,7 2"),
    ('r', 6, "0 0,0 8;0 5,3 8,6 8"),
    ('s', 7, "7 7,5 8,2 8,0 7,0 5,2 4,5 4,7 3,7 1,5 0,2 0,0 1"),
    ('t', 5, "2 11,2 2,3 0,5 0;0 8,5 8"),
    ('u', 7, "0 8,0 2,2 0,5 0,7 2;7 8,7 0"),
    ('v', 8, "0 8,4 0,8 8"),
    ('w', 10, "0 8,2 0,5 6,8 0,10 8"),
    ('x', 7, "0 0,7 8;0 8,7 0"),
    ('y', 8, "0 8,4 0;8 8,2 -4,0 -4"),
    ('z', 7, "0 8,7 8,0 0,7 0"),
];

/// Drawn instead of a character the font does not have.
const MISSING: (char, u8, &str) = ('?', 6, "0 0,6 0,6 12,0 12,0 0");

fn glyph(c: char) -> (u8, &'static str) {
    let g = GLYPHS.iter().find(|g| g.0 == c).unwrap_or(&MISSING);
    (g.1, g.2)
}

/// Strokes of one glyph in grid units (y up).
fn strokes(data: &str) -> impl Iterator<Item = Vec<Vec2>> + '_ {
    data.split(';').filter(|s| !s.is_empty()).map(|stroke| {
        stroke
            .split(',')
            .map(|p| {
                let mut xy = p.split(' ').map(|v| v.parse::<f64>().expect("font data holds numbers"));
                let x = xy.next().expect("x");
                let y = xy.next().expect("y");
                Vec2::new(x, y)
            })
            .collect()
    })
}

/// A text set in the stroke font.
#[derive(Clone, Debug, PartialEq)]
pub struct Set {
    /// Polylines in cm, origin at the start of the baseline, y down.
    pub strokes: Vec<Vec<Vec2>>,
    /// Advance width of the whole text, cm.
    pub width: f64,
}

/// Set `text` at font size `size` (cm per em).
pub fn set(text: &str, size: f64) -> Set {
    let unit = size * CAP_HEIGHT / CAP_UNITS;
    let mut x = 0.0;
    let mut out = Vec::new();
    for (k, c) in text.chars().enumerate() {
        if k > 0 {
            x += SPACING;
        }
        let (width, data) = glyph(c);
        for s in strokes(data) {
            out.push(s.into_iter().map(|p| Vec2::new((x + p.x) * unit, -p.y * unit)).collect());
        }
        x += f64::from(width);
    }
    Set { strokes: out, width: x * unit }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn covers_the_promised_characters() {
        let wanted = ('a'..='z').chain('A'..='Z').chain('0'..='9').chain("_-.: ".chars());
        for c in wanted {
            assert!(GLYPHS.iter().any(|g| g.0 == c), "missing glyph {c:?}");
        }
    }

    #[test]
    fn glyphs_stay_on_their_grid() {
        for &(c, w, data) in GLYPHS.iter().chain([&MISSING]) {
            for s in strokes(data) {
                assert!(s.len() >= 2, "{c:?}: a stroke needs two points");
                for p in s {
                    assert!(p.x >= 0.0 && p.x <= f64::from(w), "{c:?}: x {} outside 0..{w}", p.x);
                    assert!(p.y >= -4.0 && p.y <= 12.0, "{c:?}: y {}", p.y);
                }
            }
        }
    }

    #[test]
    fn width_adds_up() {
        // "ab": 7 + 2.5 + 7 units of 0.7/12 em.
        let s = set("ab", 12.0);
        assert!((s.width - 16.5 * 0.7).abs() < 1e-12);
        assert!(set("", 7.0).strokes.is_empty());
        assert_eq!(set("é", 12.0).width, 6.0 * 0.7);
    }
}
