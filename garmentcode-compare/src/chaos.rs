//! The chaotic rule (see the script's docstring): sleeve, sleeve-cuff and hood panels come
//! from a numerically chaotic fit in the reference, so they and the stitches touching them
//! are judged by what makes the garment sew, with limits that grow with how far the
//! group's fitted seam curves moved (fit_dev).

use super::ChaosParams;
use super::dist::{fast_pointwise, hausdorff, lift};
use super::geom::dist2;
use super::geom::{EdgeGeom, PanelGeom};
use super::py::{self, PyErr};
use super::stitch::{Side, Stitch, flags_repr, stitch_str};
use std::collections::{BTreeMap, BTreeSet, HashMap};

/// `CHAOTIC_PANEL_RE`: {right,left}_sleeve_{f,b}, {right,left}_hood,
/// sl_{right,left}_cuff[_skirt]_{f,b}. Like Python's `$`, a single trailing newline is allowed.
pub fn is_chaotic(name: &str) -> bool {
    let n = name.strip_suffix('\n').unwrap_or(name);
    fn side_rest(s: &str) -> Option<&str> {
        s.strip_prefix("right_").or_else(|| s.strip_prefix("left_"))
    }
    if let Some(rest) = side_rest(n) {
        if matches!(rest, "sleeve_f" | "sleeve_b" | "hood") {
            return true;
        }
    }
    if let Some(rest) = n.strip_prefix("sl_").and_then(side_rest) {
        if let Some(r) = rest.strip_prefix("cuff_") {
            return matches!(r, "f" | "b" | "skirt_f" | "skirt_b");
        }
    }
    false
}

/// Can type sequence te (edge lengths le) be aligned with ta (lengths la) in order,
/// matching equal types one to one and skipping only edges of length <= sliver?
fn align_linear<T: PartialEq>(te: &[T], le: &[f64], ta: &[T], la: &[f64], sliver: f64) -> bool {
    let (n, m) = (te.len(), ta.len());
    let mut reach = vec![vec![false; m + 1]; n + 1];
    reach[0][0] = true;
    for i in 0..=n {
        for j in 0..=m {
            if !reach[i][j] {
                continue;
            }
            if i < n && j < m && te[i] == ta[j] {
                reach[i + 1][j + 1] = true;
            }
            if i < n && le[i] <= sliver {
                reach[i + 1][j] = true;
            }
            if j < m && la[j] <= sliver {
                reach[i][j + 1] = true;
            }
        }
    }
    reach[n][m]
}

/// Same cyclic sequence of edge types (any start vertex, either loop direction), up to
/// sliver edges present in only one of the two panels.
pub fn cyclic_types_match(pe: &PanelGeom, pa: &PanelGeom, sliver: f64) -> bool {
    let te: Vec<_> = pe.edges.iter().map(|e| e.kind).collect();
    let le: Vec<_> = pe.edges.iter().map(|e| e.length()).collect();
    let ta: Vec<_> = pa.edges.iter().map(|e| e.kind).collect();
    let la: Vec<_> = pa.edges.iter().map(|e| e.length()).collect();
    let (tr, lr): (Vec<_>, Vec<_>) = (ta.iter().rev().copied().collect(), la.iter().rev().copied().collect());
    for (tt, ll) in [(&ta, &la), (&tr, &lr)] {
        for k in 0..tt.len() {
            let t2: Vec<_> = tt[k..].iter().chain(&tt[..k]).copied().collect();
            let l2: Vec<_> = ll[k..].iter().chain(&ll[..k]).copied().collect();
            if align_linear(&te, &le, &t2, &l2, sliver) {
                return true;
            }
        }
    }
    false
}

fn types_str(p: &PanelGeom, sliver: f64) -> String {
    let parts: Vec<String> = p.edges.iter().map(|e| format!("{}{}", e.kind.name(), if e.length() <= sliver { "*" } else { "" })).collect();
    format!("[{}]", parts.join(" "))
}

pub struct ChaoticPanelResult {
    pub reasons: Vec<String>,
    pub notes: Vec<String>,
    /// outline2d, outline3d, perimeter
    pub devs: [f64; 3],
}

/// Chaotic-rule judgement of one chaotic panel; `limit` bounds its 2D and 3D outline
/// distance and perimeter difference.
#[allow(clippy::too_many_arguments)]
pub fn compare_chaotic_panel(
    name: &str,
    pe: &PanelGeom,
    pa: &PanelGeom,
    step: f64,
    strict: bool,
    limit: f64,
    exact: bool,
    cp: &ChaosParams,
) -> ChaoticPanelResult {
    let (mut reasons, mut notes) = (Vec::new(), Vec::new());
    let mut cell = py::max(2.0 * step, 1.0);
    let fast = if exact { None } else { fast_pointwise(pe, pa) };
    let (d2, d3) = match fast {
        Some(f) if py::max(f.0, f.1) <= limit => f, // upper bounds are enough here
        _ => {
            // exact values up to the limit, a lower bound above it
            cell = py::max(cell, py::min(limit, 5.0));
            let stop = if exact { None } else { Some(limit) };
            let d2 = hausdorff(&lift(pe.dense(step)), &lift(pa.dense(step)), cell, true, stop);
            let d3 = hausdorff(&pe.dense3d(step), &pa.dense3d(step), cell, true, stop);
            (d2, d3)
        }
    };
    let devs = [d2, d3, (pe.perimeter() - pa.perimeter()).abs()];
    for (k, what) in ["2D outline", "3D outline", "perimeter"].iter().enumerate() {
        if devs[k] > limit {
            let bound = if k != 2 && !exact { "at least " } else { "" };
            reasons.push(format!(
                "chaotic panel {name}: {what} deviates by {bound}{} cm (> {} cm)",
                py::fixed(devs[k], 4),
                py::fixed(limit, 4)
            ));
        }
    }
    let sliver = cp.sliver_len;
    if !cyclic_types_match(pe, pa, sliver) {
        reasons.push(format!("chaotic panel {name}: edge types {} vs expected {}", types_str(pa, sliver), types_str(pe, sliver)));
    } else if pe.n_vertices as i64 - pe.edges.len() as i64 != pa.n_vertices as i64 - pa.edges.len() as i64 {
        reasons.push(format!(
            "chaotic panel {name}: {} vertices for {} edges vs expected {} for {}",
            pa.n_vertices,
            pa.edges.len(),
            pe.n_vertices,
            pe.edges.len()
        ));
    } else if pe.edges.len() != pa.edges.len() {
        notes.push(format!(
            "chaotic panel {name}: {} edges vs expected {} (sliver edges <= {} cm)",
            pa.edges.len(),
            pe.edges.len(),
            py::float_repr(sliver)
        ));
    }
    super::orientation_and_label(name, pe, pa, strict, &mut reasons, &mut notes);
    ChaoticPanelResult { reasons, notes, devs }
}

/// Group chaotic panels stitched to each other (a sleeve with its cuff, the two hood
/// halves). Returns {panel name: group label "a+b+..."}.
pub fn chaotic_groups(stitches: &[Stitch], chaotic: &BTreeSet<String>) -> BTreeMap<String, String> {
    let mut parent: HashMap<String, String> = chaotic.iter().map(|n| (n.clone(), n.clone())).collect();
    fn find(parent: &mut HashMap<String, String>, x: &str) -> String {
        let mut x = x.to_string();
        loop {
            let p = parent[&x].clone();
            if p == x {
                return x;
            }
            let gp = parent[&p].clone();
            parent.insert(x.clone(), gp.clone());
            x = gp;
        }
    }
    for st in stitches {
        let (a, b) = (st.sides[0].panel, st.sides[1].panel);
        if parent.contains_key(a) && parent.contains_key(b) {
            let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
            if ra != rb {
                let (hi, lo) = if ra > rb { (ra, rb) } else { (rb, ra) };
                parent.insert(hi, lo);
            }
        }
    }
    let mut members: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for n in chaotic {
        let r = find(&mut parent, n);
        members.entry(r).or_default().push(n.clone());
    }
    let mut out = BTreeMap::new();
    for n in chaotic {
        let r = find(&mut parent, n);
        let mut m = members[&r].clone();
        m.sort();
        out.insert(n.clone(), m.join("+"));
    }
    out
}

/// Minimum-cost assignment (Hungarian method, shortest augmenting paths) for an n x m
/// cost matrix with n <= m. Returns col[i] for each row i.
fn assign(cost: &[Vec<f64>]) -> Vec<Option<usize>> {
    let n = cost.len();
    let m = if n > 0 { cost[0].len() } else { 0 };
    let inf = f64::INFINITY;
    let (mut u, mut v) = (vec![0.0f64; n + 1], vec![0.0f64; m + 1]);
    let (mut p, mut way) = (vec![0usize; m + 1], vec![0usize; m + 1]);
    for i in 1..=n {
        p[0] = i;
        let mut j0 = 0;
        let mut minv = vec![inf; m + 1];
        let mut used = vec![false; m + 1];
        loop {
            used[j0] = true;
            let (i0, mut delta, mut j1) = (p[j0], inf, 0usize);
            for j in 1..=m {
                if !used[j] {
                    let cur = cost[i0 - 1][j - 1] - u[i0] - v[j];
                    if cur < minv[j] {
                        minv[j] = cur;
                        way[j] = j0;
                    }
                    if minv[j] < delta {
                        delta = minv[j];
                        j1 = j;
                    }
                }
            }
            for j in 0..=m {
                if used[j] {
                    u[p[j]] += delta;
                    v[j] -= delta;
                } else {
                    minv[j] -= delta;
                }
            }
            j0 = j1;
            if p[j0] == 0 {
                break;
            }
        }
        while j0 != 0 {
            let j1 = way[j0];
            p[j0] = p[j1];
            j0 = j1;
        }
    }
    let mut col = vec![None; n];
    for j in 1..=m {
        if p[j] != 0 {
            col[p[j] - 1] = Some(j - 1);
        }
    }
    col
}

type Oriented<'s, 'a> = (&'s Side<'a>, &'s Side<'a>);

/// The orientations (side on key.0, side on key.1) of stitch st (two for a stitch
/// joining a panel to itself).
fn oriented<'s, 'a>(st: &'s Stitch<'a>, key: &(String, String)) -> Vec<Oriented<'s, 'a>> {
    let mut out = Vec::new();
    for (a, b) in [(&st.sides[0], &st.sides[1]), (&st.sides[1], &st.sides[0])] {
        if a.panel == key.0 && b.panel == key.1 {
            out.push((a, b));
        }
    }
    out
}

/// Like `side_dev`, but with the arc-length midpoint, so that a curve whose control points
/// moved but whose trace barely did is not penalised.
fn side_dev_geo(a: &Side, b: &Side) -> f64 {
    if a.panel != b.panel {
        return f64::INFINITY;
    }
    let d_same = py::max(dist2(a.s, b.s), dist2(a.e, b.e));
    let d_flip = py::max(dist2(a.s, b.e), dist2(a.e, b.s));
    py::max(py::min(d_same, d_flip), dist2(a.edge.arc_midpoint(), b.edge.arc_midpoint()))
}

/// (deviation, expected orientation, actual orientation) of the best way to lay stitch sa
/// onto stitch se.
fn stitch_cost<'s, 'a>(
    se: &'s Stitch<'a>,
    sa: &'s Stitch<'a>,
    key: &(String, String),
) -> (f64, Option<Oriented<'s, 'a>>, Option<Oriented<'s, 'a>>) {
    let mut best = (f64::INFINITY, None, None);
    let oe = oriented(se, key)[0];
    for oa in oriented(sa, key) {
        let d = py::max(side_dev_geo(oe.0, oa.0), side_dev_geo(oe.1, oa.1));
        if d < best.0 {
            best = (d, Some(oe), Some(oa));
        }
    }
    best
}

struct Matched<'s, 'a> {
    e: &'s Stitch<'a>,
    a: &'s Stitch<'a>,
    oe: Option<Oriented<'s, 'a>>,
    oa: Option<Oriented<'s, 'a>>,
}

/// Match the stitches of one panel pair one to one (minimum total deviation).
/// Returns (matched, unmatched expected, unmatched actual).
#[allow(clippy::type_complexity)]
fn match_pair<'s, 'a>(
    le: &[&'s Stitch<'a>],
    la: &[&'s Stitch<'a>],
    key: &(String, String),
) -> (Vec<Matched<'s, 'a>>, Vec<&'s Stitch<'a>>, Vec<&'s Stitch<'a>>) {
    if le.is_empty() || la.is_empty() {
        return (Vec::new(), le.to_vec(), la.to_vec());
    }
    let swap = le.len() > la.len();
    let (rows, cols) = if swap { (la, le) } else { (le, la) };
    let pick = |r: usize, c: usize| if swap { (cols[c], rows[r]) } else { (rows[r], cols[c]) };
    let costs: Vec<Vec<f64>> = (0..rows.len())
        .map(|r| {
            (0..cols.len())
                .map(|c| {
                    let (e, a) = pick(r, c);
                    stitch_cost(e, a, key).0
                })
                .collect()
        })
        .collect();
    // big = max([finite costs] + [1.0]) * 10 + 1e6 (Python's max keeps the first maximum)
    let big = costs.iter().flatten().copied().filter(|x| *x != f64::INFINITY).chain(std::iter::once(1.0)).reduce(py::max).unwrap_or(1.0)
        * 10.0
        + 1e6;
    let capped: Vec<Vec<f64>> = costs.iter().map(|row| row.iter().map(|&x| if x != f64::INFINITY { x } else { big }).collect()).collect();
    let col = assign(&capped);
    let mut matched = Vec::new();
    let (mut used_r, mut used_c) = (vec![false; rows.len()], vec![false; cols.len()]);
    for (i, j) in col.iter().enumerate() {
        let j = j.expect("assignment covers every row");
        let (e, a) = pick(i, j);
        let (_, oe, oa) = stitch_cost(e, a, key);
        matched.push(Matched { e, a, oe, oa });
        used_r[i] = true;
        used_c[j] = true;
    }
    let un_r: Vec<_> = (0..rows.len()).filter(|&i| !used_r[i]).map(|i| rows[i]).collect();
    let un_c: Vec<_> = (0..cols.len()).filter(|&j| !used_c[j]).map(|j| cols[j]).collect();
    if swap { (matched, un_c, un_r) } else { (matched, un_r, un_c) }
}

fn is_sliver(st: &Stitch, sliver: f64) -> bool {
    st.sides[0].len <= sliver && st.sides[1].len <= sliver
}

/// How much the shape of edge ea differs from ee, ignoring where it starts:
/// max_t |(ea(t) - ea(0)) - (ee(t) - ee(0))| over either direction of ea.
fn shape_dev(ee: &EdgeGeom, ea: &EdgeGeom) -> f64 {
    let n = 32;
    let mut best = f64::INFINITY;
    for rev in [false, true] {
        let e0 = ee.point(0.0);
        let a0 = ea.point(if rev { 1.0 } else { 0.0 });
        let mut d = 0.0f64;
        for i in 1..=n {
            let t = i as f64 / n as f64;
            let (p, q) = (ee.point(t), ea.point(if rev { 1.0 - t } else { t }));
            d = py::max(d, py::hypot((q[0] - a0[0]) - (p[0] - e0[0]), (q[1] - a0[1]) - (p[1] - e0[1])));
        }
        best = py::min(best, d);
    }
    best
}

/// Allowed deviation of a chaotic panel (or of a stitch side on it) whose group's fitted
/// curves moved by fit_dev: tol + gain * fit_dev, at most cap; without a measurement, cap.
pub fn chaos_limit(tol: f64, fit_dev: Option<f64>, cap: f64, gain: f64) -> f64 {
    match fit_dev {
        None => cap,
        Some(f) => py::min(cap, tol + gain * f),
    }
}

/// Stitches grouped by panel pair, in order of first appearance (Python dict order).
fn by_pair<'s, 'a>(sts: &[&'s Stitch<'a>]) -> Vec<((String, String), Vec<&'s Stitch<'a>>)> {
    let mut out: Vec<((String, String), Vec<&Stitch>)> = Vec::new();
    let mut idx: HashMap<(String, String), usize> = HashMap::new();
    for &st in sts {
        let k = st.key();
        match idx.get(&k) {
            Some(&i) => out[i].1.push(st),
            None => {
                idx.insert(k.clone(), out.len());
                out.push((k, vec![st]));
            }
        }
    }
    out
}

/// Chaotic-rule judgement of the stitches that touch a chaotic panel.
/// Returns (reasons, fit_dev per group).
pub fn compare_chaotic_stitches(
    se: &[&Stitch],
    sa: &[&Stitch],
    groups: &BTreeMap<String, String>,
    tol: f64,
    cp: &ChaosParams,
) -> Result<(Vec<String>, BTreeMap<String, f64>), PyErr> {
    let sliver = cp.sliver_len;
    let mut reasons = Vec::new();
    let (pe, pa) = (by_pair(se), by_pair(sa));
    fn get<'s, 'a>(v: &[((String, String), Vec<&'s Stitch<'a>>)], k: &(String, String)) -> Vec<&'s Stitch<'a>> {
        v.iter().find(|(kk, _)| kk == k).map(|(_, l)| l.clone()).unwrap_or_default()
    }
    let keys: BTreeSet<(String, String)> = pe.iter().chain(pa.iter()).map(|(k, _)| k.clone()).collect();

    // Pass 1: match the stitches of each panel pair one to one by position, and measure
    // the fitted curves on the seams between a chaotic and a non-chaotic panel.
    let mut fit_dev: BTreeMap<String, f64> = BTreeMap::new();
    let mut pairs = Vec::new();
    for key in &keys {
        let (le, la) = (get(&pe, key), get(&pa, key));
        let seam = groups.contains_key(&key.0) != groups.contains_key(&key.1);
        let (matched, un_e, un_a) = match_pair(&le, &la, key);
        if seam {
            for m in &matched {
                if !(is_sliver(m.e, sliver) || is_sliver(m.a, sliver)) {
                    let (oe, oa) = (m.oe.unwrap(), m.oa.unwrap());
                    let i = if groups.contains_key(oe.0.panel) { 0 } else { 1 };
                    let (se_i, sa_i) = if i == 0 { (oe.0, oa.0) } else { (oe.1, oa.1) };
                    let g = groups[se_i.panel].clone();
                    let cur = fit_dev.get(&g).copied().unwrap_or(0.0);
                    fit_dev.insert(g, py::max(cur, shape_dev(se_i.edge, sa_i.edge)));
                }
            }
        }
        pairs.push((key, le, la, seam, matched, un_e, un_a));
    }

    // Pass 2: judge.
    for (key, le, la, seam, matched, un_e, un_a) in &pairs {
        let pair = format!("{}<->{}", key.0, key.1);
        // left-over stitches are tolerated only as slivers on a chaotic/non-chaotic seam
        let un_e: Vec<_> = un_e.iter().filter(|st| !(*seam && is_sliver(st, sliver))).collect();
        let un_a: Vec<_> = un_a.iter().filter(|st| !(*seam && is_sliver(st, sliver))).collect();
        if !un_e.is_empty() || !un_a.is_empty() {
            reasons.push(format!(
                "stitches {pair}: {} vs expected {}{}",
                la.len(),
                le.len(),
                if *seam { format!(" (slivers <= {} cm may differ)", py::float_repr(sliver)) } else { String::new() }
            ));
        }
        for st in &un_e {
            reasons.push(format!("missing stitch {}", stitch_str(st)));
        }
        for st in &un_a {
            reasons.push(format!("extra stitch {}", stitch_str(st)));
        }
        for m in matched {
            let (oe, oa) = (m.oe.unwrap(), m.oa.unwrap());
            let sl = is_sliver(m.e, sliver) || is_sliver(m.a, sliver);
            // a side on a chaotic panel moves with it (as far as its group's fit allows);
            // a side on a non-chaotic panel only by a sliver
            let oes = [oe.0, oe.1];
            let oas = [oa.0, oa.1];
            let side_devs = [side_dev_geo(oes[0], oas[0]), side_dev_geo(oes[1], oas[1])];
            let lims: [f64; 2] = std::array::from_fn(|i| match groups.get(oes[i].panel) {
                Some(g) => chaos_limit(tol, fit_dev.get(g).copied(), cp.stitch_tol, cp.fit_gain),
                None => sliver,
            });
            let re = py::div(oes[0].len, oes[1].len)?;
            let ra = py::div(oas[0].len, oas[1].len)?;
            let bad: Vec<String> = (0..2)
                .filter(|&i| side_devs[i] > lims[i])
                .map(|i| format!("{} side off by {} cm (> {} cm)", oes[i].panel, py::fixed(side_devs[i], 4), py::fixed(lims[i], 4)))
                .collect();
            if !bad.is_empty() {
                reasons.push(format!("stitch {}: closest actual stitch: {}", stitch_str(m.e), bad.join(", ")));
                continue;
            }
            if m.a.flags != m.e.flags {
                reasons.push(format!("stitch {pair}: flags {} vs expected {}", flags_repr(&m.a.flags), flags_repr(&m.e.flags)));
            }
            if !sl && (py::div(ra, re)? - 1.0).abs() > cp.ratio_tol {
                reasons.push(format!(
                    "stitch {}: length ratio {} vs expected {} (> {} apart)",
                    stitch_str(m.e),
                    py::fixed(ra, 4),
                    py::fixed(re, 4),
                    py::percent(cp.ratio_tol, 1)
                ));
            }
        }
        // stitched length per non-chaotic side of the pair (slivers included)
        for i in 0..2 {
            let pname = if i == 0 { &key.0 } else { &key.1 };
            if groups.contains_key(pname) {
                continue;
            }
            let total = |l: &Vec<&Stitch>| {
                l.iter().filter_map(|st| oriented(st, key).first().map(|o| if i == 0 { o.0.len } else { o.1.len })).fold(0.0, |a, x| a + x)
            };
            let (te, ta) = (total(le), total(la));
            if (ta - te).abs() > sliver {
                reasons.push(format!(
                    "stitches {pair}: total length on {pname} {} vs expected {} cm (> {} cm)",
                    py::fixed(ta, 4),
                    py::fixed(te, 4),
                    py::float_repr(sliver)
                ));
            }
        }
    }

    // Per non-chaotic panel, the length stitched to each chaotic group: normal tolerance.
    // Per group, total seam length with non-chaotic panels relative to theirs: the fit's
    // target length, so only the fit's length error may change it.
    type Tot = BTreeMap<(String, String), f64>;
    let mut gtot_e: Tot = BTreeMap::new();
    let mut gtot_a: Tot = BTreeMap::new();
    let mut seam_e: BTreeMap<String, [f64; 2]> = BTreeMap::new();
    let mut seam_a: BTreeMap<String, [f64; 2]> = BTreeMap::new();
    for (tot, seam, prs) in [(&mut gtot_e, &mut seam_e, &pe), (&mut gtot_a, &mut seam_a, &pa)] {
        for (_, sts) in prs.iter() {
            for st in sts {
                for (mine, other) in [(&st.sides[0], &st.sides[1]), (&st.sides[1], &st.sides[0])] {
                    if !groups.contains_key(mine.panel) {
                        if let Some(g) = groups.get(other.panel) {
                            *tot.entry((mine.panel.to_string(), g.clone())).or_insert(0.0) += mine.len;
                            let sl = seam.entry(g.clone()).or_insert([0.0, 0.0]);
                            sl[0] += other.len;
                            sl[1] += mine.len;
                        }
                    }
                }
            }
        }
    }
    let tkeys: BTreeSet<_> = gtot_e.keys().chain(gtot_a.keys()).cloned().collect();
    for k in tkeys {
        let (te, ta) = (gtot_e.get(&k).copied().unwrap_or(0.0), gtot_a.get(&k).copied().unwrap_or(0.0));
        if (ta - te).abs() > tol {
            reasons.push(format!("length of {} stitched to {}: {} vs expected {} cm", k.0, k.1, py::fixed(ta, 4), py::fixed(te, 4)));
        }
    }
    for (g, [ge, ne]) in &seam_e {
        let Some([ga, na]) = seam_a.get(g) else { continue };
        let (ge, ne, ga, na) = (*ge, *ne, *ga, *na);
        if py::min(py::min(py::min(ge, ne), ga), na) <= 0.0 {
            continue;
        }
        let rel = (ga / na) / (ge / ne) - 1.0;
        if rel.abs() > cp.seam_ratio_tol {
            reasons.push(format!(
                "seams of {g} with other panels: length ratio {} vs expected {} (> {} apart)",
                py::fixed(ga / na, 4),
                py::fixed(ge / ne, 4),
                py::percent(cp.seam_ratio_tol, 2)
            ));
        }
    }
    Ok((reasons, fit_dev))
}
