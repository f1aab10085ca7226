//! Mannequins: a closed body mesh made from a body file's measurements, and the measuring
//! of a body mesh the way the reference defines its measurements.
//!
//! The reference ships meshes only for its five bodies; any other body file gets a
//! mannequin: the nearest of the three `mean_*` bodies (same topology and part
//! segmentation), deformed. Heights are mapped piecewise linearly between the landmark
//! levels (floor, crotch, hips, waist, underbust, bust, nape, top of the head); horizontal
//! sections are scaled about their centre by factors set at the hips, waist, underbust, bust,
//! shoulder joint and nape levels and interpolated in between; both maps are monotone in
//! every section, so they cannot make the surface cross itself. The arms move with the
//! torso's side at the armpit, turned to the file's `arm_pose_angle` and stretched to its
//! `arm_length`, blended into the torso over their first [`ARM_BLEND`] cm (distance from the
//! torso along the surface). The girths, the shoulder width and the neck are then measured
//! back ([`measure`]) and the section factors corrected, a few times.
//!
//! Levels come from the file as the garment programs use them (cm above the floor): nape
//! `height − head_l`, bust `nape − vert_bust_line` (`bust_line` when absent), waist
//! `nape − waist_line`, hips `waist − hips_line`, crotch `hips − crotch_hip_diff`, underbust
//! [`UNDERBUST_FRACTION`] of the way from the bust down to the waist.

use std::collections::HashMap;

use garmentcode::{Body, Vec3};

use crate::body::{BodyError, BodyMesh, PARTS};

/// The underbust level: this fraction of the way from the bust level down to the waist level
/// (the reference defines it as "right below the bust"; on the three mean bodies this
/// reproduces their files' underbust within 0.5 cm).
pub const UNDERBUST_FRACTION: f64 = 0.45;

/// Largest arm angle (degrees below the horizontal) of a mannequin.
pub const MAX_ARM_ANGLE: f64 = 85.0;

/// Correction rounds of the section factors.
const ROUNDS: usize = 5;

/// Distance (cm) from the torso, along the arm's surface, over which the arm's motion blends
/// into the torso's.
pub const ARM_BLEND: f64 = 20.0;

/// The templates: the reference's mean bodies (meshes in [`crate::body::BUILTIN`]) and their
/// measurement files.
const TEMPLATES: [(&str, &str); 3] = [
    ("mean_all", include_str!("../data/mean_all.yaml")),
    ("mean_female", include_str!("../data/mean_female.yaml")),
    ("mean_male", include_str!("../data/mean_male.yaml")),
];

/// Measurements of a body mesh (cm, degrees), as [`measure`] takes them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    /// Floor to the top of the head (the mesh's y extent).
    pub height: f64,
    /// Girth at the bust level: perimeter of the torso section's convex hull (a tape measure).
    pub bust: f64,
    /// Girth at the underbust level.
    pub underbust: f64,
    /// Girth at the waist level.
    pub waist: f64,
    /// Girth at the hips level.
    pub hips: f64,
    /// Back half of the section (hull arc through the back between the leftmost and rightmost
    /// points: balance line to balance line) at the nape level.
    pub neck_w: f64,
    /// Back half of the section at the bust level.
    pub back_width: f64,
    /// Back half of the section at the waist level.
    pub waist_back_width: f64,
    /// Back half of the section at the hips level.
    pub hip_back_width: f64,
    /// Arm direction below the horizontal (mean of both arms' principal axes), degrees.
    pub arm_pose_angle: f64,
    /// Arm extent along its axis, from where it meets the shoulder to the fingertips (the
    /// reference's shoulder-to-wrist length is shorter by the hand).
    pub arm_extent: f64,
    /// Left-right distance between the highest points of the two arms' roots (where each arm
    /// meets the shoulder): the outer ends of the collarbones.
    pub shoulder_w: f64,
}

/// The landmark levels of a body file (cm above the floor).
#[derive(Clone, Copy, Debug)]
struct Levels {
    crotch: f64,
    hips: f64,
    waist: f64,
    underbust: f64,
    bust: f64,
    nape: f64,
    top: f64,
}

impl Levels {
    fn of(b: &Body) -> Levels {
        let nape = b.height - b.head_l;
        let waist = nape - b.waist_line;
        let bust = nape - b.vert_bust_line.unwrap_or(b.bust_line);
        let hips = waist - b.hips_line;
        Levels {
            crotch: hips - b.crotch_hip_diff,
            hips,
            waist,
            underbust: bust - UNDERBUST_FRACTION * (bust - waist),
            bust,
            nape,
            top: b.height,
        }
    }

    /// Floor to top, in order.
    fn knots(&self) -> [f64; 8] {
        [0.0, self.crotch, self.hips, self.waist, self.underbust, self.bust, self.nape, self.top]
    }
}

/// Measures a body mesh at the levels of the body file `levels` (its `height`, `head_l`,
/// `waist_line`, `vert_bust_line`, `hips_line`, `crotch_hip_diff`): the levels are where the
/// garment programs put the waistband, the bust line and the hip line, so the girths there
/// are the ones a drape depends on. The floor is the mesh's lowest point. The arm values
/// (`arm_pose_angle`, `arm_extent`, `shoulder_w`) need a part segmentation: NaN without one.
pub fn measure(body: &BodyMesh, levels: &Body) -> Measured {
    Shape { vertices: &body.vertices, faces: &body.faces, parts: body.parts() }.measure(levels)
}

/// A triangle mesh as [`measure`] reads it (a mannequin is measured before it is a checked
/// [`BodyMesh`]).
struct Shape<'a> {
    vertices: &'a [Vec3],
    faces: &'a [[u32; 3]],
    parts: Option<&'a [u8]>,
}

impl Shape<'_> {
    fn measure(&self, levels: &Body) -> Measured {
        let body = self;
        let l = Levels::of(levels);
        let (lo, hi) = body.vertices.iter().fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), v| (lo.min(*v), hi.max(*v)));
        let torso = |level: f64| Section::torso(body, lo.y + level);
        let (bust, under, waist, hips, nape) = (torso(l.bust), torso(l.underbust), torso(l.waist), torso(l.hips), torso(l.nape));
        let arms = Arms::of(body);
        let (angle, extent) = arms.as_ref().map_or((f64::NAN, f64::NAN), |a| {
            let n = a.len() as f64;
            (a.iter().map(|a| a.angle()).sum::<f64>() / n, a.iter().map(|a| a.extent(body)).sum::<f64>() / n)
        });
        Measured {
            height: hi.y - lo.y,
            bust: bust.girth(),
            underbust: under.girth(),
            waist: waist.girth(),
            hips: hips.girth(),
            neck_w: nape.back(),
            back_width: bust.back(),
            waist_back_width: waist.back(),
            hip_back_width: hips.back(),
            arm_pose_angle: angle,
            arm_extent: extent,
            shoulder_w: arms.as_ref().map_or(f64::NAN, |a| (a[0].top.x - a[1].top.x).abs()),
        }
    }
}

/// The convex hull (x, z), counter-clockwise, of the largest piece of a horizontal section.
struct Section {
    hull: Vec<[f64; 2]>,
}

impl Section {
    /// The section of `body` at height `y` whose convex hull has the largest area: the torso
    /// (arms and hands are separate, smaller pieces at every torso level of an A-pose).
    fn torso(body: &Shape, y: f64) -> Section {
        // Points where mesh edges cross the plane, joined into pieces through the triangles.
        let mut index: HashMap<(u32, u32), usize> = HashMap::new();
        let mut points: Vec<[f64; 2]> = Vec::new();
        let mut parent: Vec<usize> = Vec::new();
        fn find(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for f in body.faces {
            let mut ends = [0usize; 2];
            let mut n = 0;
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                let (pa, pb) = (body.vertices[a as usize], body.vertices[b as usize]);
                if (pa.y < y) == (pb.y < y) {
                    continue;
                }
                let key = (a.min(b), a.max(b));
                let i = *index.entry(key).or_insert_with(|| {
                    let t = (y - pa.y) / (pb.y - pa.y);
                    let p = pa + (pb - pa) * t;
                    points.push([p.x, p.z]);
                    parent.push(parent.len());
                    parent.len() - 1
                });
                if n < 2 {
                    ends[n] = i;
                }
                n += 1;
            }
            if n == 2 {
                let (ra, rb) = (find(&mut parent, ends[0]), find(&mut parent, ends[1]));
                parent[ra.max(rb)] = ra.min(rb);
            }
        }
        let mut pieces: Vec<Vec<[f64; 2]>> = Vec::new();
        let mut piece_of: HashMap<usize, usize> = HashMap::new();
        for i in 0..points.len() {
            let r = find(&mut parent, i);
            let k = *piece_of.entry(r).or_insert_with(|| {
                pieces.push(Vec::new());
                pieces.len() - 1
            });
            pieces[k].push(points[i]);
        }
        let hull = pieces.into_iter().map(hull).max_by(|a, b| area(a).total_cmp(&area(b))).unwrap_or_default();
        Section { hull }
    }

    /// Perimeter of the hull.
    fn girth(&self) -> f64 {
        let h = &self.hull;
        (0..h.len()).map(|i| dist(h[i], h[(i + 1) % h.len()])).sum()
    }

    /// Length of the hull's arc through the back (−z) between its leftmost and rightmost points.
    fn back(&self) -> f64 {
        let h = &self.hull;
        if h.len() < 3 {
            return 0.0;
        }
        let extreme = |sign: f64| (0..h.len()).max_by(|&i, &j| (sign * h[i][0]).total_cmp(&(sign * h[j][0]))).unwrap_or(0);
        let arc = |from: usize, to: usize| {
            let (mut len, mut z, mut n, mut i) = (0.0, 0.0, 0.0, from);
            while i != to {
                let j = (i + 1) % h.len();
                len += dist(h[i], h[j]);
                z += h[j][1];
                n += 1.0;
                i = j;
            }
            (len, z / n)
        };
        let (right, left) = (extreme(-1.0), extreme(1.0));
        let (a, b) = (arc(right, left), arc(left, right));
        if a.1 < b.1 { a.0 } else { b.0 }
    }

    /// Centre of the hull's corners (x, z).
    fn centre(&self) -> [f64; 2] {
        let n = self.hull.len().max(1) as f64;
        let s = self.hull.iter().fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
        [s[0] / n, s[1] / n]
    }
}

fn dist(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

fn cross(o: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
}

/// Convex hull (Andrew's monotone chain), counter-clockwise.
fn hull(mut p: Vec<[f64; 2]>) -> Vec<[f64; 2]> {
    p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let mut h: Vec<[f64; 2]> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = h.len();
        let iter: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 { Box::new(p.iter()) } else { Box::new(p.iter().rev()) };
        for &q in iter {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

fn area(h: &[[f64; 2]]) -> f64 {
    (0..h.len()).map(|i| cross([0.0, 0.0], h[i], h[(i + 1) % h.len()])).sum::<f64>().abs() / 2.0
}

/// One arm of a segmented body: its vertices, joint (centre of the ring where it meets the
/// torso) and axis (principal direction, pointing away from the joint).
struct Arm {
    vertices: Vec<usize>,
    joint: Vec3,
    /// The ring's lowest point.
    pit: Vec3,
    /// The ring's highest point.
    top: Vec3,
    axis: Vec3,
}

impl Arm {
    /// Angle of the axis below the horizontal, degrees.
    fn angle(&self) -> f64 {
        (-self.axis.y).atan2(self.axis.x.abs()).to_degrees()
    }

    /// Extent of the arm's vertices along its axis, from the joint.
    fn extent(&self, body: &Shape) -> f64 {
        self.vertices.iter().map(|&i| (body.vertices[i] - self.joint).dot(self.axis)).fold(0.0, f64::max)
    }
}

/// Both arms of a body with a part segmentation (`None` without one).
struct Arms;

impl Arms {
    fn of(body: &Shape) -> Option<Vec<Arm>> {
        let parts = body.parts?;
        let bit = |name: &str| 1u8 << PARTS.iter().position(|p| *p == name).unwrap_or(0);
        let mut arms = Vec::new();
        for name in ["left_arm", "right_arm"] {
            let b = bit(name);
            // The arm's vertices, with the few unsegmented ones that touch the arm and no other
            // part (at the fingertips; those in the armpit stay with the torso).
            let mut in_arm: Vec<bool> = parts.iter().map(|p| p & b != 0).collect();
            let mut touches_other = vec![false; parts.len()];
            for f in body.faces {
                if f.iter().any(|&i| parts[i as usize] != 0 && parts[i as usize] & b == 0) {
                    f.iter().for_each(|&i| touches_other[i as usize] = true);
                }
            }
            for _ in 0..3 {
                for f in body.faces {
                    if f.iter().any(|&i| in_arm[i as usize]) {
                        f.iter()
                            .filter(|&&i| parts[i as usize] == 0 && !touches_other[i as usize])
                            .for_each(|&i| in_arm[i as usize] = true);
                    }
                }
            }
            let vertices: Vec<usize> = (0..body.vertices.len()).filter(|&i| in_arm[i]).collect();
            if vertices.is_empty() {
                return None;
            }
            // The ring: arm vertices on a triangle that also has a vertex of another part.
            let other = |i: u32| parts[i as usize] != 0 && !in_arm[i as usize];
            let mut ring = vec![false; body.vertices.len()];
            for f in body.faces {
                if f.iter().any(|&i| other(i)) {
                    f.iter().filter(|&&i| in_arm[i as usize]).for_each(|&i| ring[i as usize] = true);
                }
            }
            let ring: Vec<Vec3> = (0..ring.len()).filter(|&i| ring[i]).map(|i| body.vertices[i]).collect();
            let joint = ring.iter().copied().sum::<Vec3>() / ring.len().max(1) as f64;
            let pit = ring.iter().copied().min_by(|a, b| a.y.total_cmp(&b.y)).unwrap_or(joint);
            let top = ring.iter().copied().max_by(|a, b| a.y.total_cmp(&b.y)).unwrap_or(joint);
            let centre = vertices.iter().map(|&i| body.vertices[i]).sum::<Vec3>() / vertices.len() as f64;
            // Principal axis by power iteration on the covariance, started along joint → centre.
            let mut cov = [[0.0; 3]; 3];
            for &i in &vertices {
                let d = body.vertices[i] - centre;
                for (r, row) in cov.iter_mut().enumerate() {
                    for (c, x) in row.iter_mut().enumerate() {
                        *x += d[r] * d[c];
                    }
                }
            }
            let mut axis = (centre - joint).normalize_or_zero();
            for _ in 0..50 {
                axis = Vec3::new(
                    cov[0][0] * axis.x + cov[0][1] * axis.y + cov[0][2] * axis.z,
                    cov[1][0] * axis.x + cov[1][1] * axis.y + cov[1][2] * axis.z,
                    cov[2][0] * axis.x + cov[2][1] * axis.y + cov[2][2] * axis.z,
                )
                .normalize_or_zero();
            }
            if axis.dot(centre - joint) < 0.0 {
                axis = -axis;
            }
            arms.push(Arm { vertices, joint, pit, top, axis });
        }
        Some(arms)
    }
}

/// Distance (cm, along the mesh's edges) of each vertex of `region` from the vertices outside
/// it: `(vertex, distance)` for every vertex of `region`.
fn distance_into(body: &BodyMesh, region: &[usize]) -> Vec<(usize, f64)> {
    use std::cmp::Reverse;
    let mut inside = vec![false; body.vertices.len()];
    region.iter().for_each(|&i| inside[i] = true);
    let mut dist = vec![f64::INFINITY; body.vertices.len()];
    let mut next: Vec<Vec<usize>> = vec![Vec::new(); body.vertices.len()];
    for f in &body.faces {
        for k in 0..3 {
            let (a, b) = (f[k] as usize, f[(k + 1) % 3] as usize);
            next[a].push(b);
            next[b].push(a);
            if inside[a] != inside[b] {
                dist[if inside[a] { b } else { a }] = 0.0;
            }
        }
    }
    // Dijkstra from the outside vertices that touch the region (non-negative distances order
    // as their bit patterns).
    let mut heap: std::collections::BinaryHeap<Reverse<(u64, usize)>> =
        (0..dist.len()).filter(|&i| dist[i] == 0.0).map(|i| Reverse((0u64, i))).collect();
    while let Some(Reverse((d, i))) = heap.pop() {
        let d = f64::from_bits(d);
        if d > dist[i] {
            continue;
        }
        for &j in &next[i] {
            let e = d + (body.vertices[i] - body.vertices[j]).length();
            if inside[j] && e < dist[j] {
                dist[j] = e;
                heap.push(Reverse((e.to_bits(), j)));
            }
        }
    }
    region.iter().map(|&i| (i, dist[i])).collect()
}

/// Piecewise-linear interpolation through `(xs[i], ys[i])`, `xs` increasing; constant outside.
fn lerp_knots(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    if x <= xs[0] {
        return ys[0];
    }
    for i in 1..xs.len() {
        if x <= xs[i] {
            let t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
            return ys[i - 1] + (ys[i] - ys[i - 1]) * t;
        }
    }
    ys[ys.len() - 1]
}

/// The template for a body file: the mean body nearest in height, bust, waist and hips
/// (relative differences).
fn template(b: &Body) -> (&'static str, Body) {
    let score = |t: &Body| {
        [(b.height, t.height), (b.bust, t.bust), (b.waist, t.waist), (b.hips, t.hips)]
            .iter()
            .map(|(x, y)| (x / y - 1.0).powi(2))
            .sum::<f64>()
    };
    let bodies = TEMPLATES.map(|(name, text)| (name, Body::from_yaml(text, name).expect("the templates' measurement files are valid")));
    bodies.into_iter().min_by(|a, b| score(&a.1).total_cmp(&score(&b.1))).expect("there are templates")
}

/// A mannequin for the body file `b` (named `name` in errors): the nearest mean body mesh
/// deformed to the file's levels, girths, shoulder and neck widths, arm angle and arm length
/// (see the module documentation), closed, with the template's part segmentation.
///
/// ```
/// use garmentcode_drape::mannequin::{mannequin, measure};
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// let text = "body:\n  height: 180\n  head_l: 26\n  neck_w: 18\n  shoulder_w: 38\n  armscye_depth: 13\n  shoulder_incl: 20\n  arm_pose_angle: 40\n  arm_length: 56\n  wrist: 17\n  waist: 90\n  waist_line: 38\n  waist_over_bust_line: 41\n  waist_back_width: 40\n  bust_line: 26\n  vert_bust_line: 21.5\n  bust: 110\n  bust_points: 18\n  underbust: 96\n  back_width: 50\n  hips: 105\n  hip_back_width: 54\n  hips_line: 24\n  hip_inclination: 7\n  bum_points: 18\n  crotch_hip_diff: 10\n  leg_circ: 60\n";
/// let body = garmentcode::Body::from_yaml(text, "tall.yaml")?;
/// let mesh = mannequin(&body, "tall.yaml")?;
/// let m = measure(&mesh, &body);
/// assert!((m.height - 180.0).abs() < 0.1 && (m.bust - 110.0).abs() < 1.0 && (m.waist - 90.0).abs() < 1.0);
/// # Ok(())
/// # }
/// ```
pub fn mannequin(b: &Body, name: &str) -> Result<BodyMesh, BodyError> {
    if b.arm_pose_angle > MAX_ARM_ANGLE {
        return Err(BodyError::Mannequin {
            file: name.to_string(),
            reason: format!(
                "arm_pose_angle {} is outside 0..{MAX_ARM_ANGLE} degrees for a mannequin (arms straight down would pass through the hips); give a body mesh with --body-mesh",
                b.arm_pose_angle
            ),
        });
    }
    let (template_name, t) = template(b);
    let base = BodyMesh::builtin(template_name)?;
    let (from, to) = (Levels::of(&t), Levels::of(b));
    let (kt, kb) = (from.knots(), to.knots());
    if let Some(i) = (1..kb.len()).find(|&i| kb[i] <= kb[i - 1] + 1.0) {
        const NAMES: [&str; 8] = ["floor", "crotch", "hips", "waist", "underbust", "bust", "nape", "top of the head"];
        return Err(BodyError::Mannequin {
            file: name.to_string(),
            reason: format!(
                "the {} level ({:.1} cm) is not above the {} level ({:.1} cm); the levels come from height, head_l, waist_line, vert_bust_line (or bust_line), hips_line and crotch_hip_diff",
                NAMES[i],
                kb[i],
                NAMES[i - 1],
                kb[i - 1]
            ),
        });
    }
    let floor = base.bounds().0.y;
    let parts = base.parts().expect("the templates have a segmentation").to_vec();
    let shape = Shape { vertices: &base.vertices, faces: &base.faces, parts: Some(&parts) };
    let arms = Arms::of(&shape).expect("the templates have a segmentation");
    let tm = shape.measure(&t);
    // Per vertex: which arm (if any) and its blend weight, from its distance to the torso
    // along the arm's surface.
    let mut arm_of: Vec<Option<(usize, f64)>> = vec![None; base.vertices.len()];
    for (k, arm) in arms.iter().enumerate() {
        for (i, d) in distance_into(&base, &arm.vertices) {
            let s = (d / ARM_BLEND).clamp(0.0, 1.0);
            arm_of[i] = Some((k, s * s * (3.0 - 2.0 * s)));
        }
    }
    // Section knots (template heights above the floor) with their centres, and the joint level.
    let sec_levels = [from.crotch, from.hips, from.waist, from.underbust, from.bust, arms[0].joint.y - floor, from.nape];
    let centres: Vec<[f64; 2]> = sec_levels.iter().map(|&y| Section::torso(&shape, floor + y).centre()).collect();
    // What each section factor is set by: girths and the shoulder width as the file gives
    // them ([`measure`] agrees with the reference's definitions on its bodies); the neck as
    // the file's `neck_w` relative to the template's (its back arc at the nape reads 0.2 to
    // 2.6 cm more than the reference's files).
    let widths = |m: &Measured| [m.hips, m.hips, m.waist, m.underbust, m.bust, m.shoulder_w, m.neck_w];
    let tg = widths(&tm);
    let target = [b.hips, b.hips, b.waist, b.underbust, b.bust, b.shoulder_w, b.neck_w / t.neck_w * tm.neck_w];
    let mut scale: Vec<f64> = (0..7).map(|k| target[k] / tg[k]).collect();
    let arm_turn0 = b.arm_pose_angle - tm.arm_pose_angle;
    let mut arm_turn = arm_turn0;
    let arm_stretch = b.arm_length / t.arm_length;
    let mut round = 0;
    loop {
        // Heights: template (above the floor) → file.
        let ymap = |y: f64| lerp_knots(&kt, &kb, y - floor);
        // Section factor and centre at a template height above the floor: 1 at the floor and
        // the knee and from a few centimetres above the nape up.
        let mut xs = vec![0.0, from.crotch / 2.0];
        let mut ss = vec![1.0, 1.0];
        let mut cx = vec![centres[0], centres[0]];
        for k in 0..7 {
            xs.push(sec_levels[k]);
            ss.push(scale[k]);
            cx.push(centres[k]);
        }
        xs.extend([from.nape + 3.0, from.top]);
        ss.extend([scale[6], 1.0]);
        cx.extend([centres[6], centres[6]]);
        let (cxs, czs): (Vec<f64>, Vec<f64>) = cx.iter().map(|c| (c[0], c[1])).unzip();
        let torso = |p: Vec3| {
            let y = p.y - floor;
            let s = lerp_knots(&xs, &ss, y);
            let (x0, z0) = (lerp_knots(&xs, &cxs, y), lerp_knots(&xs, &czs, y));
            Vec3::new(x0 + s * (p.x - x0), ymap(p.y), z0 + s * (p.z - z0))
        };
        let rigid: Vec<_> = arms
            .iter()
            .map(|a| {
                // Turning down (larger angle) is clockwise seen from the front on the left arm (+x).
                let sign = if a.axis.x > 0.0 { -1.0 } else { 1.0 };
                let rot = glam::DQuat::from_rotation_z(sign * arm_turn.to_radians());
                // The arm follows the torso's side at the armpit, so that a wider or narrower
                // chest neither runs into the arm nor leaves it behind.
                let moved = torso(a.pit) - a.pit;
                let shift = Vec3::new(moved.x, ymap(a.joint.y) - a.joint.y, moved.z);
                // Lowered about the armpit, so that the wedge under the arm closes only from
                // its apex; raised about the joint's centre.
                let pivot = if arm_turn > 0.0 { a.pit } else { a.joint };
                (a.joint, a.axis, pivot, shift, rot)
            })
            .collect();
        let vertices: Vec<Vec3> = base
            .vertices
            .iter()
            .zip(&arm_of)
            .map(|(&p, arm)| {
                let q = torso(p);
                match *arm {
                    None => q,
                    Some((k, w)) => {
                        let (joint, axis, pivot, shift, rot) = rigid[k];
                        let stretched = p + axis * ((p - joint).dot(axis) * (arm_stretch - 1.0));
                        let r = pivot + shift + rot * (stretched - pivot);
                        q * (1.0 - w) + r * w
                    }
                }
            })
            .collect();
        if round == ROUNDS {
            return Ok(BodyMesh::new(name, vertices, base.faces.clone())?.with_part_bits(parts));
        }
        let m = Shape { vertices: &vertices, faces: &base.faces, parts: Some(&parts) }.measure(b);
        let got = widths(&m);
        for k in 0..7 {
            if got[k] > 0.0 {
                scale[k] *= target[k] / got[k];
            }
        }
        arm_turn += b.arm_pose_angle - m.arm_pose_angle;
        if !arm_turn.is_finite() {
            arm_turn = arm_turn0;
        }
        round += 1;
    }
}
