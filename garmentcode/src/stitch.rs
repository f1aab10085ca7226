//! Stitches between interfaces.
//!
//! The pattern format only knows one-to-one edge stitches, so an abstract stitch
//! between two interfaces is *matched* when it is created: edges on both sides are
//! split at each other's (gather-projected) length fractions until both sides have
//! the same number of edges with the same fractions. Matching happens immediately,
//! so the order in which a program creates stitches shapes the geometry.

use crate::arena::{Arena, InterfaceId, StitchRule};
use crate::error::{Error, Result};
use crate::math::close_enough;
use crate::pattern::EdgePlace;

/// One written stitch: panel name and edge index on each side.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct StitchRecord {
    /// `(panel name, edge index)` of both sides.
    pub sides: [(String, usize); 2],
    /// One fabric is flipped (right side to wrong side).
    pub right_wrong: bool,
    /// Where each side's edge lies in its panel (outline, hole or inner line): a
    /// stitch with a side off the outline is written as an
    /// [`InnerStitch`](crate::InnerStitch).
    pub places: [EdgePlace; 2],
}

impl StitchRule {
    /// Stitch `a` to `b`, splitting edges of both until they match.
    pub fn new(arena: &mut Arena, a: InterfaceId, b: InterfaceId) -> Result<StitchRule> {
        let rule = StitchRule { a, b };
        if !rule.is_matching(arena) {
            rule.match_interfaces(arena)?;
        }
        Ok(rule)
    }

    /// Same number of edges and projected fractions within 0.05 of each other.
    pub fn is_matching(&self, arena: &Arena) -> bool {
        if self.a.len(arena) != self.b.len(arena) {
            return false;
        }
        let f1 = self.a.projecting_fractions(arena);
        let f2 = self.b.projecting_fractions(arena);
        f1.iter().zip(f2.iter()).all(|(x, y)| (x - y).abs() <= 0.05 + 1e-5 * y.abs())
    }

    fn match_interfaces(&self, arena: &mut Arena) -> Result<()> {
        let f1 = self.a.projecting_fractions(arena);
        let f2 = self.b.projecting_fractions(arena);
        let min_frac = f1.iter().chain(f2.iter()).copied().fold(f64::INFINITY, f64::min);
        let tol = f64::min(1e-2, min_frac / 2.0);
        match_to_fractions(arena, self.a, &f2, tol)?;
        match_to_fractions(arena, self.b, &f1, tol)?;
        Ok(())
    }

    /// The written stitches, one per edge pair (after all panels were assembled so
    /// that edge indices are current). Extra edges on the longer side are dropped, as
    /// in the reference.
    pub fn records(&self, arena: &Arena, out: &mut Vec<StitchRecord>) {
        let (ia, ib) = (arena.iface(self.a), arena.iface(self.b));
        for i in 0..ia.edges.len().min(ib.edges.len()) {
            out.push(StitchRecord {
                sides: [
                    (ia.panels[i].name(arena).to_string(), arena.geometric_id(ia.edges[i]) as usize),
                    (ib.panels[i].name(arena).to_string(), arena.geometric_id(ib.edges[i]) as usize),
                ],
                right_wrong: ia.right_wrong[i] || ib.right_wrong[i],
                places: [arena.edges[ia.edges[i].0 as usize].place, arena.edges[ib.edges[i].0 as usize].place],
            });
        }
    }
}

/// Split edges of `inter` so that its projected fractions contain the boundaries of
/// `targets` (boundaries closer than `tol` count as the same).
fn match_to_fractions(arena: &mut Arena, inter: InterfaceId, targets: &[f64], tol: f64) -> Result<()> {
    let (mut in_id, mut add_id) = (0usize, 0usize);
    let (mut covered_init, mut covered_added) = (0.0f64, 0.0f64);
    let mut curr = inter.projecting_fractions(arena);
    while in_id < inter.len(arena) && add_id < targets.len() {
        let next_init = f64::min(covered_init + curr[in_id], 1.0);
        let next_added = f64::min(covered_added + targets[add_id], 1.0);
        if close_enough(next_init, next_added, tol) {
            in_id += 1;
            add_id += 1;
            covered_init = next_init;
            covered_added = next_added;
        } else if next_init < next_added {
            in_id += 1;
            covered_init = next_init;
        } else {
            let in_frac = curr[in_id];
            let new_v_loc = in_frac - (next_init - next_added);
            let mut split = new_v_loc / in_frac;
            let (base, panel, flip) = {
                let d = arena.iface(inter);
                (d.edges[in_id], d.panels[in_id], d.flipping[in_id])
            };
            if flip {
                split = 1.0 - split;
            }
            let mut pieces = arena.subdivide(base, &[split, 1.0 - split], true)?;
            panel.substitute_edge(arena, base, &pieces).map_err(|_| Error::Projection { panels: panel_names(arena, inter) })?;
            if flip {
                pieces.reverse();
            }
            inter.substitute(arena, base, &pieces, panel)?;
            curr = inter.projecting_fractions(arena);
            covered_init += curr[in_id];
            covered_added = next_added;
            in_id += 1;
            add_id += 1;
        }
    }
    if add_id != targets.len() {
        return Err(Error::Projection { panels: panel_names(arena, inter) });
    }
    Ok(())
}

fn panel_names(arena: &Arena, inter: InterfaceId) -> String {
    inter.panels(arena).iter().map(|p| p.name(arena).to_string()).collect::<Vec<_>>().join(", ")
}
