//! Drape a GarmentCode garment on a body: the reference's cloth simulation.
//!
//! The reference (GarmentCode's `pygarment/meshgen`, on its fork of NVIDIA Warp) drapes a
//! pattern by simulating its box mesh ([`garmentcode::mesh::BoxMesh`]) as XPBD cloth
//! falling onto a static body mesh: the stretched seam faces shrink to their rest lengths,
//! the waistband and collars are held by attachment planes for the first frames, and the
//! run stops when the garment is static. This crate reproduces that scheme with the
//! reference's constants (see [`solver`]):
//!
//! ```no_run
//! use garmentcode_drape::{BodyMesh, Settings, drape, sim_obj};
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let pattern = garmentcode::Pattern::from_json(&std::fs::read_to_string("t-shirt_specification.json")?)?;
//! let mesh = garmentcode::mesh::BoxMesh::new(&pattern, 1.0)?;
//! let body = BodyMesh::load("mean_all.obj".as_ref())?; // metres, scaled to cm
//! let measurements = garmentcode::Body::from_yaml(&std::fs::read_to_string("mean_all.yaml")?, "mean_all.yaml")?;
//! let result = drape(&mesh, &body, &Settings::for_body(&measurements))?;
//! std::fs::write("t-shirt_sim.obj", sim_obj(&mesh, &result.positions))?;
//! println!("{} frames, converged: {}", result.stats.frames, result.stats.converged);
//! # Ok(())
//! # }
//! ```

pub mod body;
mod bvh;
mod check;
pub mod fabric;
mod glb;
pub mod mannequin;
mod par;
mod parts;
pub mod render;
mod selfcol;
#[cfg(test)]
mod sheets;
pub mod solver;
mod strain;
mod untangle;

pub use body::{BodyError, BodyMesh};
pub use check::crossing_edges;
pub use fabric::{Fabric, FabricError};
pub use glb::glb;
pub use solver::{Attachment, Drape, DrapeError, Next, Progress, Settings, Stats, drape, drape_with_progress};
pub use strain::Strain;

use garmentcode::Vec3;
use garmentcode::mesh::BoxMesh;

/// Suffixes (after the box mesh's name) of the files of a drape besides the box mesh's:
/// the draped mesh as OBJ ([`sim_obj`]) and GLB ([`glb`]), its figures, and the front and
/// back pictures ([`render::render_png`]).
pub const FILE_SUFFIXES: [&str; 5] = ["_sim.obj", "_sim.glb", "_drape.json", "_render_front.png", "_render_back.png"];

/// `<name>_sim.obj`: the box mesh's OBJ (same vertices, texture coordinates and faces, in the
/// same order) with the vertices moved to `positions` (cm), as the reference saves a drape.
///
/// # Panics
/// If `positions` does not have one entry per box-mesh vertex.
pub fn sim_obj(mesh: &BoxMesh, positions: &[Vec3]) -> String {
    assert_eq!(positions.len(), mesh.vertices.len(), "one position per box-mesh vertex");
    BoxMesh { vertices: positions.to_vec(), ..mesh.clone() }.obj()
}
