//! Validation of a pattern: structural errors that make it unusable, and warnings
//! about things a pattern maker should look at (crossing outlines, seams whose two
//! sides differ in length).

pub(crate) mod inner;

use super::{EdgePlace, LineKind, Pattern, arc_radius_too_small};
use crate::intersect;
use std::collections::HashMap;
use std::fmt;

/// How serious a problem is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// The pattern cannot be used as it is.
    Error,
    /// Worth a look; the pattern is usable.
    Warning,
}

/// Stable kinds of problems (the `kind` of the JSON report).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ProblemKind {
    /// The pattern has no panels.
    EmptyPattern,
    /// A panel with no edges or fewer than three vertices.
    EmptyPanel,
    /// A panel whose outline encloses no area (its corners on one line, or an
    /// outline that goes out and back the same way).
    ZeroArea,
    /// An edge's end is not the next edge's start.
    OpenLoop,
    /// An edge refers to a vertex that does not exist.
    VertexOutOfRange,
    /// An edge whose two end points coincide.
    DegenerateEdge,
    /// A stitch names a panel that does not exist.
    UnknownPanel,
    /// A stitch names an edge that does not exist.
    EdgeOutOfRange,
    /// An edge used by more than one stitch (or twice by one).
    EdgeStitchedTwice,
    /// `panel_order` does not list exactly the panels.
    PanelOrderMismatch,
    /// A panel outline crosses itself.
    SelfIntersection,
    /// The two edges of a stitch have different lengths (a gather, or a mistake).
    StitchLengthMismatch,
    /// A hole (format extension) lies outside its panel's outline.
    HoleOutsidePanel,
    /// A hole crosses or touches its panel's outline, another hole, or itself.
    HoleCrossing,
    /// An inner line leaves its panel.
    LineOutsidePanel,
    /// A fold line whose ends are not both on the panel's outline.
    FoldNotAcross,
    /// A fold angle outside 0 to 180 degrees.
    FoldAngleOutOfRange,
    /// Two holes or lines of a panel with the same name.
    DuplicateName,
    /// An inner stitch names a hole or line that does not exist.
    UnknownHoleOrLine,
    /// A circular arc whose radius is under half the distance between its ends: no
    /// circle of that radius joins them.
    ArcRadiusTooSmall,
}

impl ProblemKind {
    /// Snake-case name used in reports.
    pub fn as_str(self) -> &'static str {
        match self {
            ProblemKind::EmptyPattern => "empty_pattern",
            ProblemKind::EmptyPanel => "empty_panel",
            ProblemKind::ZeroArea => "zero_area",
            ProblemKind::OpenLoop => "open_loop",
            ProblemKind::VertexOutOfRange => "vertex_out_of_range",
            ProblemKind::DegenerateEdge => "degenerate_edge",
            ProblemKind::UnknownPanel => "unknown_panel",
            ProblemKind::EdgeOutOfRange => "edge_out_of_range",
            ProblemKind::EdgeStitchedTwice => "edge_stitched_twice",
            ProblemKind::PanelOrderMismatch => "panel_order_mismatch",
            ProblemKind::SelfIntersection => "self_intersection",
            ProblemKind::StitchLengthMismatch => "stitch_length_mismatch",
            ProblemKind::HoleOutsidePanel => "hole_outside_panel",
            ProblemKind::HoleCrossing => "hole_crossing",
            ProblemKind::LineOutsidePanel => "line_outside_panel",
            ProblemKind::FoldNotAcross => "fold_not_across",
            ProblemKind::FoldAngleOutOfRange => "fold_angle_out_of_range",
            ProblemKind::DuplicateName => "duplicate_name",
            ProblemKind::UnknownHoleOrLine => "unknown_hole_or_line",
            ProblemKind::ArcRadiusTooSmall => "arc_radius_too_small",
        }
    }
}

/// One problem found in a pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// What kind of problem.
    pub kind: ProblemKind,
    /// Error or warning.
    pub severity: Severity,
    /// Panel concerned, if any.
    pub panel: Option<String>,
    /// Edge concerned (index in the panel), if any.
    pub edge: Option<usize>,
    /// Stitch concerned (index in `stitches`), if any.
    pub stitch: Option<usize>,
    /// Length ratio of the stitch sides (side 1 / side 2), for length mismatches.
    pub ratio: Option<f64>,
    /// Human-readable explanation.
    pub message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let sev = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        write!(f, "{sev}[{}]", self.kind.as_str())?;
        if let Some(p) = &self.panel {
            write!(f, " panel '{p}'")?;
        }
        if let Some(e) = self.edge {
            write!(f, " edge {e}")?;
        }
        if let Some(s) = self.stitch {
            write!(f, " stitch {s}")?;
        }
        write!(f, ": {}", self.message)
    }
}

/// Relative length difference between stitched edges reported as a warning.
const LENGTH_TOLERANCE: f64 = 0.01;

/// Area, relative to the squared perimeter, at or below which a panel encloses no
/// area: rounding leaves about 1e-16 on an outline whose corners lie on one line,
/// and a sliver 1 µm wide and 1 m long still has 2.5e-7.
const ZERO_AREA: f64 = 1e-12;

/// The structural errors of a pattern, in file order: what `garmentcode check` calls
/// errors, and what drawing, printing and meshing refuse. Cheap (no intersection
/// tests), unlike [`validate`].
pub fn structural_errors(p: &Pattern) -> Vec<Problem> {
    structure(p).0
}

/// All problems of a pattern, errors first (each group in file order).
pub fn validate(p: &Pattern) -> Vec<Problem> {
    let (mut out, structurally_ok) = structure(p);

    // Warnings, only on structurally sound panels.
    for panel in &p.panels {
        if structurally_ok.get(panel.name.as_str()) == Some(&true) && intersect::has_self_intersection(&intersect::spec_segments(panel)) {
            out.push(Problem {
                kind: ProblemKind::SelfIntersection,
                severity: Severity::Warning,
                panel: Some(panel.name.clone()),
                edge: None,
                stitch: None,
                ratio: None,
                message: "the outline crosses itself".into(),
            });
        }
    }
    for (si, s) in p.stitches.iter().enumerate() {
        let len = |side: &super::StitchSide| {
            p.panel(&side.panel)
                .filter(|pp| side.edge < pp.edges.len() && structurally_ok.get(pp.name.as_str()) == Some(&true))
                .map(|pp| pp.edge_geom(side.edge).length())
        };
        if let (Some(l1), Some(l2)) = (len(&s.sides[0]), len(&s.sides[1])) {
            let ratio = l1 / l2;
            if (ratio - 1.0).abs() > LENGTH_TOLERANCE {
                out.push(Problem {
                    kind: ProblemKind::StitchLengthMismatch,
                    severity: Severity::Warning,
                    panel: Some(s.sides[0].panel.clone()),
                    edge: Some(s.sides[0].edge),
                    stitch: Some(si),
                    ratio: Some(ratio),
                    message: format!(
                        "{:.2} cm stitched to {:.2} cm ({}:{}), ratio {ratio:.3} (a gather, or a mistake)",
                        l1, l2, s.sides[1].panel, s.sides[1].edge,
                    ),
                });
            }
        }
    }
    out.sort_by_key(|pr| pr.severity);
    out
}

/// Whether a panel's outline (valid corner indices) encloses no area.
fn zero_area(panel: &super::PanelSpec) -> bool {
    let q = panel.outline_polygon(16);
    let perimeter: f64 = (0..q.len()).map(|k| (q[(k + 1) % q.len()] - q[k]).length()).sum();
    let area = panel.outline_area();
    area.is_nan() || area <= ZERO_AREA * perimeter * perimeter
}

/// The structural errors, and which panels are sound enough for the warnings' tests.
fn structure(p: &Pattern) -> (Vec<Problem>, HashMap<&str, bool>) {
    let mut out = Vec::new();
    let err = |kind, panel: Option<&str>, edge, stitch, message: String| Problem {
        kind,
        severity: Severity::Error,
        panel: panel.map(str::to_string),
        edge,
        stitch,
        ratio: None,
        message,
    };
    if p.panels.is_empty() {
        out.push(err(ProblemKind::EmptyPattern, None, None, None, "the pattern has no panels".into()));
    }
    let mut structurally_ok: HashMap<&str, bool> = HashMap::new();
    for panel in &p.panels {
        let mut ok = true;
        let name = panel.name.as_str();
        let nv = panel.vertices.len();
        if panel.edges.is_empty() || nv < 3 {
            out.push(err(
                ProblemKind::EmptyPanel,
                Some(name),
                None,
                None,
                format!("{} edges and {nv} vertices (a panel needs at least three corners)", panel.edges.len()),
            ));
            ok = false;
        }
        for (i, e) in panel.edges.iter().enumerate() {
            for &v in &e.endpoints {
                if v >= nv {
                    out.push(err(
                        ProblemKind::VertexOutOfRange,
                        Some(name),
                        Some(i),
                        None,
                        format!("vertex {v} does not exist (the panel has {nv})"),
                    ));
                    ok = false;
                }
            }
        }
        if ok {
            let n = panel.edges.len();
            for (i, e) in panel.edges.iter().enumerate() {
                let next = &panel.edges[(i + 1) % n];
                let (end, start) = (panel.vertices[e.endpoints[1]], panel.vertices[next.endpoints[0]]);
                if e.endpoints[1] != next.endpoints[0] && end != start {
                    out.push(err(
                        ProblemKind::OpenLoop,
                        Some(name),
                        Some(i),
                        None,
                        format!("ends at vertex {} but edge {} starts at vertex {}", e.endpoints[1], (i + 1) % n, next.endpoints[0]),
                    ));
                    ok = false;
                }
                let (s, t) = (panel.vertices[e.endpoints[0]], panel.vertices[e.endpoints[1]]);
                if (s[0] - t[0]).abs() < 1e-4 && (s[1] - t[1]).abs() < 1e-4 {
                    out.push(err(ProblemKind::DegenerateEdge, Some(name), Some(i), None, "start and end coincide".into()));
                    ok = false;
                } else if let Some(message) = arc_radius_too_small(&panel.vertices, e) {
                    out.push(err(ProblemKind::ArcRadiusTooSmall, Some(name), Some(i), None, message));
                    ok = false;
                }
            }
        }
        if ok && zero_area(panel) {
            out.push(err(ProblemKind::ZeroArea, Some(name), None, None, "the outline encloses no area".into()));
            ok = false;
        }
        inner::check_panel(panel, ok, &mut |kind, message| out.push(err(kind, Some(name), None, None, message)));
        structurally_ok.insert(name, ok);
    }
    let mut used: HashMap<(&str, EdgePlace, usize), String> = HashMap::new();
    for (si, s) in p.stitches.iter().enumerate() {
        for side in &s.sides {
            match p.panel(&side.panel) {
                None => {
                    out.push(err(ProblemKind::UnknownPanel, Some(&side.panel), Some(side.edge), Some(si), "no panel with this name".into()))
                }
                Some(panel) if side.edge >= panel.edges.len() => out.push(err(
                    ProblemKind::EdgeOutOfRange,
                    Some(&side.panel),
                    Some(side.edge),
                    Some(si),
                    format!("the panel has {} edges", panel.edges.len()),
                )),
                Some(_) => {
                    if let Some(first) = used.insert((side.panel.as_str(), EdgePlace::Outline, side.edge), format!("stitch {si}")) {
                        out.push(err(
                            ProblemKind::EdgeStitchedTwice,
                            Some(&side.panel),
                            Some(side.edge),
                            Some(si),
                            format!("already used by {first}"),
                        ));
                    }
                }
            }
        }
    }
    for (si, s) in p.inner_stitches.iter().enumerate() {
        for side in &s.sides {
            let at = |what: &str| format!("inner stitch {si}: {what}");
            let Some(panel) = p.panel(&side.panel) else {
                out.push(err(ProblemKind::UnknownPanel, Some(&side.panel), None, None, at("no panel with this name")));
                continue;
            };
            let (n_edges, place) = match side.place {
                EdgePlace::Outline => (Some(panel.edges.len()), "the outline".to_string()),
                EdgePlace::Hole(h) => (panel.holes.get(h).map(|x| x.edges.len()), format!("hole {h}")),
                EdgePlace::Line(l) => (panel.lines.get(l).map(|x| x.edges.len()), format!("line {l}")),
            };
            match n_edges {
                None => out.push(err(
                    ProblemKind::UnknownHoleOrLine,
                    Some(&side.panel),
                    None,
                    None,
                    at(&format!("{place} does not exist (the panel has {} holes and {} lines)", panel.holes.len(), panel.lines.len())),
                )),
                Some(n) if side.edge >= n => out.push(err(
                    ProblemKind::EdgeOutOfRange,
                    Some(&side.panel),
                    None,
                    None,
                    at(&format!("edge {} of {place} does not exist (it has {n} edges)", side.edge)),
                )),
                Some(_) => {
                    // Placement lines carry a piece sewn on top and may hold more than one
                    // stitch per edge (a pocket and its flap); other edges are sewn once.
                    let shared = matches!(side.place, EdgePlace::Line(l) if panel.lines[l].kind == LineKind::Placement);
                    let first =
                        if shared { None } else { used.insert((side.panel.as_str(), side.place, side.edge), format!("inner stitch {si}")) };
                    if let Some(first) = first {
                        out.push(err(
                            ProblemKind::EdgeStitchedTwice,
                            Some(&side.panel),
                            None,
                            None,
                            at(&format!("edge {} of {place} is already used by {first}", side.edge)),
                        ));
                    }
                }
            }
        }
    }
    if let Some(order) = &p.panel_order {
        let mut a: Vec<&str> = order.iter().map(String::as_str).collect();
        let mut b: Vec<&str> = p.panels.iter().map(|x| x.name.as_str()).collect();
        a.sort_unstable();
        b.sort_unstable();
        if a != b {
            out.push(err(
                ProblemKind::PanelOrderMismatch,
                None,
                None,
                None,
                "panel_order does not list exactly the pattern's panels".into(),
            ));
        }
    }

    (out, structurally_ok)
}
