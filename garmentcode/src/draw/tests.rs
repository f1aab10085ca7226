use std::path::Path;

use super::layout::{self, Shape, Sheet};
use super::svg::{escape, num};
use super::{DrawOptions, to_png, to_svg};
use crate::error::Error;
use crate::math::Vec2;
use crate::pattern::{Curvature, EdgeSpec, PanelSpec, Pattern, StitchSide, StitchSpec};
use crate::test_data::{cases, patterns_in};

fn edge(a: usize, b: usize, curvature: Option<Curvature>) -> EdgeSpec {
    EdgeSpec { endpoints: [a, b], label: None, curvature }
}

fn stitch(a: (&str, usize), b: (&str, usize)) -> StitchSpec {
    let side = |(panel, edge): (&str, usize)| StitchSide { panel: panel.into(), edge };
    StitchSpec { sides: [side(a), side(b)], right_wrong: false }
}

/// Two panels, one in front and one behind (rotated in plane by 90°), every edge
/// type, a seam between them and a dart-like stitch inside the back panel.
fn small() -> Pattern {
    let mut p = Pattern::new("tiny & <test>");
    p.panels.push(PanelSpec {
        name: "front".into(),
        translation: [-10.0, 20.0, 5.0],
        rotation: [0.0, 0.0, 0.0],
        vertices: vec![[0.0, 0.0], [20.0, 0.0], [20.0, 30.0], [0.0, 30.0]],
        edges: vec![
            edge(0, 1, None),
            edge(1, 2, Some(Curvature::Quadratic([0.5, 0.1]))),
            edge(2, 3, Some(Curvature::Circle { radius: 12.0, large_arc: false, right: true })),
            edge(3, 0, None),
        ],
        label: None,
        holes: Vec::new(),
        lines: Vec::new(),
        layer: Default::default(),
    });
    p.panels.push(PanelSpec {
        name: "back".into(),
        translation: [0.0, 20.0, -5.0],
        rotation: [0.0, 0.0, 90.0],
        vertices: vec![[0.0, 0.0], [20.0, 0.0], [10.0, 15.0]],
        edges: vec![edge(0, 1, Some(Curvature::Cubic([0.3, -0.1], [0.7, 0.1]))), edge(1, 2, None), edge(2, 0, None)],
        label: None,
        holes: Vec::new(),
        lines: Vec::new(),
        layer: Default::default(),
    });
    p.stitches = vec![stitch(("front", 0), ("back", 0)), stitch(("back", 1), ("back", 2))];
    p
}

/// The expected drawing of [`small`]. Its panel geometry was checked against the
/// reference's own `get_svg` on the same pattern (within the 3-decimal rounding).
/// The triangle's name leaves little room: one marker of stitch 1 goes outside
/// with a leader line, the others are smaller.
const SMALL_SVG: &str = r#"<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="49.577cm" height="39.367cm" viewBox="-12 -57.367 49.577 39.367">
<title>tiny &amp; &lt;test&gt;</title>
<g class="panels">
<g id="front"><path d="M -10,-20 L 10,-20 Q 7,-35 10,-50 A 12,12 0 0 0 -10,-50 L -10,-20 Z" fill="rgb(227,175,186)" stroke="rgb(51,51,51)" stroke-width="0.2"/></g>
<g id="back"><path d="M 35,-20 C 37,-26 33,-34 35,-40 L 20,-30 L 35,-20 Z" fill="rgb(227,175,186)" stroke="rgb(51,51,51)" stroke-width="0.2"/></g>
</g>
<g class="names" font-family="sans-serif">
<text x="0" y="-37.683" font-size="6" fill="rgb(31,31,31)" text-anchor="middle" dominant-baseline="middle">front</text>
<text x="27.789" y="-30" font-size="5.8" fill="rgb(31,31,31)" text-anchor="middle" dominant-baseline="middle">back</text>
</g>
<g class="stitches" font-family="sans-serif">
<g class="traces" fill="none">
<path d="M -10,-20 L 10,-20" stroke="rgb(170,24,24)" stroke-width="0.6" stroke-linecap="round"/>
<path d="M 35,-20 C 37,-26 33,-34 35,-40" stroke="rgb(170,24,24)" stroke-width="0.6" stroke-linecap="round"/>
<path d="M 35,-40 L 20,-30" stroke="rgb(28,110,52)" stroke-width="0.6" stroke-linecap="round"/>
<path class="leader" d="M 27.5,-35 L 25.891,-37.413" stroke="rgb(28,110,52)" stroke-width="0.2"/>
<path d="M 20,-30 L 35,-20" stroke="rgb(28,110,52)" stroke-width="0.6" stroke-linecap="round"/>
</g>
<g class="stitch" data-stitch="0" data-panel="front" data-edge="0">
<circle cx="0" cy="-22.9" r="2.4" fill="rgb(170,24,24)" stroke="rgb(255,255,255)" stroke-width="0.25"/>
<text x="0" y="-22.9" font-size="3.4" fill="rgb(255,255,255)" text-anchor="middle" dominant-baseline="central">0</text>
</g>
<g class="stitch" data-stitch="0" data-panel="back" data-edge="0">
<circle cx="32.267" cy="-34.911" r="1.68" fill="rgb(170,24,24)" stroke="rgb(255,255,255)" stroke-width="0.25"/>
<text x="32.267" y="-34.911" font-size="2.38" fill="rgb(255,255,255)" text-anchor="middle" dominant-baseline="central">0</text>
</g>
<g class="stitch" data-stitch="1" data-panel="back" data-edge="1">
<circle cx="25.891" cy="-37.413" r="2.4" fill="rgb(28,110,52)" stroke="rgb(255,255,255)" stroke-width="0.25"/>
<text x="25.891" y="-37.413" font-size="3.4" fill="rgb(255,255,255)" text-anchor="middle" dominant-baseline="central">1</text>
</g>
<g class="stitch" data-stitch="1" data-panel="back" data-edge="2">
<circle cx="32.304" cy="-24.85" r="2.04" fill="rgb(28,110,52)" stroke="rgb(255,255,255)" stroke-width="0.25"/>
<text x="32.304" y="-24.85" font-size="2.89" fill="rgb(255,255,255)" text-anchor="middle" dominant-baseline="central">1</text>
</g>
</g>
</svg>
"#;

#[test]
fn small_pattern_snapshot() {
    let svg = to_svg(&small(), &DrawOptions::default()).unwrap();
    assert_eq!(svg, SMALL_SVG, "got:\n{svg}");
}

#[test]
fn view_ids_label_vertices_and_edges() {
    let opts = DrawOptions { view_ids: true, stitch_markers: false, with_text: false, ..Default::default() };
    let svg = to_svg(&small(), &opts).unwrap();
    assert!(!svg.contains("class=\"stitch\"") && !svg.contains("class=\"names\""));
    // 7 edges: one vertex and one edge index each.
    assert_eq!(svg.matches("fill=\"rgb(245,96,66)\"").count(), 7);
    assert_eq!(svg.matches("fill=\"rgb(44,131,68)\"").count(), 7);
    // Edge index 0 of `front` sits 3 cm above the midpoint of its bottom edge.
    assert!(svg.contains("<text x=\"0\" y=\"-23\" font-size=\"7\" fill=\"rgb(44,131,68)\" text-anchor=\"middle\">0</text>"));
}

#[test]
fn numbers_are_fixed() {
    assert_eq!(num(0.0), "0");
    assert_eq!(num(-0.0), "0");
    assert_eq!(num(-0.0004), "0");
    assert_eq!(num(1.5), "1.5");
    assert_eq!(num(-2.0), "-2");
    assert_eq!(num(12.34567), "12.346");
    assert_eq!(num(-0.0105), "-0.011");
    assert_eq!(num(100.0001), "100");
    assert_eq!(escape("a&b<\"c\">'"), "a&amp;b&lt;&quot;c&quot;&gt;&apos;");
}

#[test]
fn empty_pattern_is_an_error() {
    let p = Pattern::new("empty");
    assert!(matches!(to_svg(&p, &DrawOptions::default()), Err(Error::Design(_))));
    assert!(matches!(to_png(&p, &DrawOptions::default()), Err(Error::Design(_))));
}

#[test]
fn broken_references_are_errors() {
    let mut p = small();
    p.stitches.push(stitch(("front", 9), ("back", 0)));
    assert!(to_svg(&p, &DrawOptions::default()).is_err());
    let mut p = small();
    p.stitches.push(stitch(("nowhere", 0), ("back", 0)));
    assert!(to_svg(&p, &DrawOptions::default()).is_err());
    let mut p = small();
    p.panels[0].edges[0].endpoints = [0, 7];
    assert!(to_png(&p, &DrawOptions::default()).is_err());
    let mut p = small();
    p.panels[0].vertices[1][0] = f64::NAN;
    assert!(to_svg(&p, &DrawOptions::default()).is_err());
    assert!(to_png(&small(), &DrawOptions { px_per_cm: 0.0, ..Default::default() }).is_err());
}

#[test]
fn broken_loop_starts_a_new_subpath() {
    let mut p = small();
    // Duplicate vertex 2 of `front` as the reference writer does when the loop breaks.
    p.panels[0].vertices.push([20.0, 30.0]);
    p.panels[0].edges[2].endpoints = [4, 3];
    let svg = to_svg(&p, &DrawOptions::default()).unwrap();
    // Two open subpaths (no `Z`: the second one ends at vertex 0, not at its start).
    assert!(svg.contains("d=\"M -10,-20 L 10,-20 Q 7,-35 10,-50 M 10,-50 A 12,12 0 0 0 -10,-50 L -10,-20\""), "{svg}");
}

// ---------------------------------------------------------------------------
// Reference cases

/// Width and height from a PNG's IHDR chunk.
fn png_size(png: &[u8]) -> (u32, u32) {
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(&png[12..16], b"IHDR");
    let be = |b: &[u8]| u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
    (be(&png[16..20]), be(&png[20..24]))
}

fn view_box(svg: &str) -> [f64; 4] {
    let start = svg.find("viewBox=\"").unwrap() + 9;
    let end = start + svg[start..].find('"').unwrap();
    let v: Vec<f64> = svg[start..end].split(' ').map(|x| x.parse().unwrap()).collect();
    [v[0], v[1], v[2], v[3]]
}

#[test]
fn every_reference_case_draws() {
    let opts = DrawOptions::default();
    let all = cases();
    assert_eq!(all.len(), 57);
    for (name, p) in &all {
        let svg = to_svg(p, &opts).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(svg.starts_with("<?xml") && svg.ends_with("</svg>\n"), "{name}");
        assert_eq!(svg.matches("<g id=\"").count(), p.panels.len(), "{name}: one group per panel");
        for panel in &p.panels {
            assert!(svg.contains(&format!("<g id=\"{}\">", escape(&panel.name))), "{name}: {}", panel.name);
        }
        assert_eq!(svg.matches("<g class=\"stitch\" ").count(), 2 * p.stitches.len(), "{name}: markers");
        assert_eq!(svg.matches("<circle ").count(), 2 * p.stitches.len(), "{name}: marker discs");
        assert!(!svg.contains("NaN") && !svg.contains("inf") && !svg.contains("\"-0\"") && !svg.contains(" -0,"));

        let png = to_png(p, &opts).unwrap_or_else(|e| panic!("{name}: {e}"));
        let [_, _, w, h] = view_box(&svg);
        let expected = ((w * 3.0 - 1e-9).ceil() as u32, (h * 3.0 - 1e-9).ceil() as u32);
        assert_eq!(png_size(&png), expected, "{name}: PNG size");
    }
}

#[test]
fn drawings_are_deterministic() {
    let all = cases();
    // The case with the most stitches, and the hand-made one with view ids.
    let (_, p) = all.iter().max_by_key(|(_, p)| p.stitches.len()).unwrap();
    let opts = DrawOptions { view_ids: true, background: Some([255, 255, 255]), ..Default::default() };
    for (p, opts) in [(p, &DrawOptions::default()), (p, &opts), (&small(), &opts)] {
        assert_eq!(to_svg(p, opts).unwrap(), to_svg(p, opts).unwrap());
        assert_eq!(to_png(p, opts).unwrap(), to_png(p, opts).unwrap());
    }
}

/// Outline of a placed panel as a dense polygon.
fn polygon(sheet: &Sheet, panel: usize) -> Vec<Vec2> {
    let mut pts = Vec::new();
    for s in &sheet.panels[panel].segments {
        let n = if matches!(s.shape, Shape::Line) { 1 } else { 64 };
        pts.extend((0..n).map(|k| s.point(k as f64 / n as f64)));
    }
    pts
}

/// The marker of each stitched edge sits inside its panel (but for those moved
/// outside with a leader line), next to a point of its edge. Panels that intersect
/// themselves (curves crossing a neighbouring edge; flagged in the cases'
/// `checks.json`) have no well-defined inside near the crossing, so those cases
/// are skipped.
#[test]
fn markers_point_into_their_panel() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../tests/data/cases");
    let mut checked = 0;
    for (name, p) in cases() {
        let checks = std::fs::read_to_string(dir.join(&name).join("checks.json")).unwrap_or_default();
        if checks.contains("\"self_intersecting\": true") {
            continue;
        }
        let sheet = layout::layout(&p, &DrawOptions::default()).unwrap();
        for m in sheet.markers.iter().filter(|m| !m.leader) {
            let q = &sheet.panels[m.panel];
            let seg = m.segment(&sheet);
            let on_edge = (0..=64).any(|k| (seg.point(k as f64 / 64.0) - m.anchor).length() < 0.05 * seg.start.distance(seg.end).max(1.0));
            assert!(on_edge, "{name}: marker of stitch {} on {} edge {} is not anchored on its edge", m.stitch, q.name, m.edge);
            let probe = m.anchor + (m.centre - m.anchor).normalize() * 0.3;
            assert!(
                super::layout::inside(&polygon(&sheet, m.panel), probe) && super::layout::inside(&polygon(&sheet, m.panel), m.centre),
                "{name}: marker of stitch {} on {} edge {} is outside",
                m.stitch,
                q.name,
                m.edge
            );
            checked += 1;
        }
    }
    assert!(checked > 1000, "{checked} markers checked");
}

/// Every drawing of the reference cases and of the built-in designs, placed and
/// flat: no two stitch markers overlap, no marker overlaps a panel name, every
/// marker is at least the smallest size and lies on the sheet, and a marker moved
/// outside its panel has a leader line. The name boxes are checked to hold the
/// names as the PNG sets them.
#[test]
fn markers_never_overlap() {
    use super::Layout;
    let all: Vec<(String, Pattern)> = cases().into_iter().chain(patterns_in("named")).collect();
    assert_eq!(all.len(), 57 + 5);
    let (mut markers, mut shrunk, mut leaders) = (0, 0, 0);
    for (name, p) in &all {
        for layout in [Layout::Placed, Layout::Flat] {
            let opts = DrawOptions { layout, ..Default::default() };
            let sheet = layout::layout(p, &opts).unwrap();
            let names: Vec<&layout::Text> = sheet.texts.iter().filter(|t| t.kind == layout::TextKind::Name).collect();
            assert_eq!(names.len(), p.panels.len());
            for t in &names {
                let b = t.bbox();
                let set = super::font::set(&t.text, t.size);
                assert!(b.max.x - b.min.x >= set.width - 1e-9 && b.max.y - b.min.y >= t.size - 1e-9, "{name}: box of {}", t.text);
            }
            let [vx, vy, vw, vh] = sheet.view_box;
            for (i, m) in sheet.markers.iter().enumerate() {
                let b = m.bbox();
                let floor = layout::MARKER_RADIUS * layout::MARKER_SCALES[layout::MARKER_SCALES.len() - 1];
                assert!(m.radius >= floor - 1e-9 && m.radius <= layout::MARKER_RADIUS, "{name}: radius {}", m.radius);
                assert!(
                    m.label().size * layout::MARKER_RADIUS == layout::MARKER_FONT_SIZE * m.radius,
                    "{name}: number scales with its disc"
                );
                let what = |m: &layout::Marker| {
                    format!("{name} ({layout:?}): marker of stitch {} on {} edge {}", m.stitch, sheet.panels[m.panel].name, m.edge)
                };
                for other in &sheet.markers[..i] {
                    assert!(!b.overlaps(&other.bbox()), "{} overlaps {}", what(m), what(other));
                }
                for t in &names {
                    assert!(!b.overlaps(&t.bbox()), "{} overlaps the name {}", what(m), t.text);
                }
                let on_sheet = b.min.x >= vx - 1e-3 && b.min.y >= vy - 1e-3 && b.max.x <= vx + vw + 1e-3 && b.max.y <= vy + vh + 1e-3;
                assert!(on_sheet, "{} is off the sheet", what(m));
                markers += 1;
                shrunk += usize::from(m.radius < layout::MARKER_RADIUS);
                leaders += usize::from(m.leader);
            }
            let svg = to_svg(p, &opts).unwrap();
            assert_eq!(svg.matches("<path class=\"leader\"").count(), sheet.markers.iter().filter(|m| m.leader).count(), "{name}");
        }
    }
    eprintln!("{markers} markers: {shrunk} smaller, {leaders} outside with a leader line");
    // Most markers keep their full size inside their panel; at most one in four
    // needs a leader line.
    assert!(markers > 5000, "{markers} markers");
    assert!(
        10 * (shrunk + leaders) < 4 * markers && 4 * leaders < markers,
        "{markers} markers: {shrunk} smaller, {leaders} with a leader line"
    );
}

#[test]
fn bounding_boxes_are_tight() {
    for (name, p) in cases() {
        let sheet = layout::layout(&p, &DrawOptions::default()).unwrap();
        for (k, q) in sheet.panels.iter().enumerate() {
            let poly = polygon(&sheet, k);
            let lo = poly.iter().fold(Vec2::INFINITY, |a, p| a.min(*p));
            let hi = poly.iter().fold(Vec2::NEG_INFINITY, |a, p| a.max(*p));
            // Contains every sample, and no sample-free slack beyond sampling error.
            assert!(q.bbox.min.cmple(lo + 1e-9).all() && q.bbox.max.cmpge(hi - 1e-9).all(), "{name}: {}", q.name);
            assert!((q.bbox.min - lo).abs().max_element() < 0.05 && (q.bbox.max - hi).abs().max_element() < 0.05, "{name}: {}", q.name);
        }
    }
}

#[test]
fn back_panels_are_right_of_front_panels() {
    let sheet = layout::layout(&small(), &DrawOptions::default()).unwrap();
    let (front, back) = (&sheet.panels[0], &sheet.panels[1]);
    assert_eq!((front.name.as_str(), back.name.as_str()), ("front", "back"), "front panels are drawn first");
    assert!((back.bbox.min.x - (front.bbox.max.x + 10.0)).abs() < 1e-12);
}

/// Decoded RGBA pixels of a PNG, and its width.
fn decode(png: &[u8]) -> (Vec<u8>, u32) {
    let mut reader = ::png::Decoder::new(std::io::Cursor::new(png)).read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    assert_eq!((info.color_type, info.bit_depth), (::png::ColorType::Rgba, ::png::BitDepth::Eight));
    buf.truncate(info.buffer_size());
    (buf, info.width)
}

#[test]
fn png_paints_fill_markers_and_background() {
    let opts = DrawOptions { px_per_cm: 10.0, ..Default::default() };
    let p = small();
    let [vx, vy, _, _] = view_box(&to_svg(&p, &opts).unwrap());
    let (pixels, width) = decode(&to_png(&p, &opts).unwrap());
    let at = |x: f64, y: f64| {
        let (i, j) = (((x - vx) * 10.0) as usize, ((y - vy) * 10.0) as usize);
        let k = 4 * (j * width as usize + i);
        [pixels[k], pixels[k + 1], pixels[k + 2], pixels[k + 3]]
    };
    assert_eq!(at(-7.0, -45.0), [227, 175, 186, 255], "panel fill");
    assert_eq!(at(-11.0, -55.0), [0, 0, 0, 0], "transparent outside the panels");
    assert_eq!(at(-1.5, -22.0), [170, 24, 24, 255], "disc of stitch 0");
    assert_eq!(at(0.0, -20.0), [170, 24, 24, 255], "trace of stitch 0 over the edge");
    let white = DrawOptions { background: Some([255, 255, 255]), ..opts };
    let (pixels, _) = decode(&to_png(&p, &white).unwrap());
    assert_eq!(&pixels[..4], &[255, 255, 255, 255]);
}

/// The flat layout puts every panel of every reference case on the sheet without
/// overlap, keeps each outline's shape, and keeps the markers inside.
#[test]
fn flat_layout_has_no_overlaps() {
    use super::Layout;
    let flat = DrawOptions { layout: Layout::Flat, ..Default::default() };
    for (name, p) in cases() {
        let placed = layout::layout(&p, &DrawOptions::default()).unwrap();
        let sheet = layout::layout(&p, &flat).unwrap();
        assert_eq!(sheet.panels.len(), placed.panels.len());
        for (i, a) in sheet.panels.iter().enumerate() {
            for b in &sheet.panels[i + 1..] {
                let apart = a.bbox.max.x <= b.bbox.min.x
                    || b.bbox.max.x <= a.bbox.min.x
                    || a.bbox.max.y <= b.bbox.min.y
                    || b.bbox.max.y <= a.bbox.min.y;
                assert!(apart, "{name}: {} and {} overlap", a.name, b.name);
            }
            // Same outline, only moved.
            let twin = placed.panels.iter().find(|q| q.name == a.name).unwrap();
            let shift = a.bbox.min - twin.bbox.min;
            assert!(((a.bbox.max - twin.bbox.max) - shift).abs().max_element() < 1e-9, "{name}: {}", a.name);
        }
        let width = sheet.panels.iter().map(|q| q.bbox.max.x).fold(0.0, f64::max);
        let widest = sheet.panels.iter().map(|q| q.bbox.max.x - q.bbox.min.x).fold(0.0, f64::max);
        assert!(width <= super::FLAT_ROW_WIDTH.max(widest) + 1e-9, "{name}: rows fit the fabric width");
        assert_eq!(sheet.markers.len(), placed.markers.len());
    }
    assert_eq!("flat".parse::<Layout>(), Ok(Layout::Flat));
    assert!("diagonal".parse::<Layout>().is_err());
}

#[test]
fn panel_names_fit_their_panels() {
    let mut shrunk = 0;
    for (name, p) in cases() {
        let sheet = layout::layout(&p, &DrawOptions::default()).unwrap();
        for (q, t) in sheet.panels.iter().zip(sheet.texts.iter().filter(|t| t.kind == layout::TextKind::Name)) {
            assert_eq!(q.name, t.text);
            let size = q.bbox.max - q.bbox.min;
            let width = 0.6 * t.size * t.text.chars().count() as f64;
            assert!(t.size <= layout::FONT_SIZE && t.size >= layout::MIN_NAME_SIZE, "{name}/{}", q.name);
            assert!(
                t.size == layout::MIN_NAME_SIZE || (width <= 0.9 * size.x + 1e-9 && t.size <= 0.5 * size.y + 1e-9),
                "{name}/{}: {} cm text",
                q.name,
                t.size
            );
            shrunk += usize::from(t.size < layout::FONT_SIZE);
        }
    }
    assert!(shrunk > 100, "{shrunk}");
}
