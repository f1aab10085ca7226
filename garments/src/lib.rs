//! # garments
//!
//! The GarmentCode garment configurator library in Rust: upper garments (loose and
//! fitted shirts, strapless variants), sleeves and cuffs, necklines and collars
//! (turtle neck, lapel, hood), skirts (circle, asymmetric, godet, two-panel,
//! many-panel, pencil, tiered), trousers, waistbands, and the meta garment that
//! combines them into tops, skirts, dresses and jumpsuits from one [`Design`].
//!
//! Every component reproduces the reference implementation's (pygarment) sewing
//! patterns for the same design and body; places where the reference behaves
//! surprisingly and that change its output are reproduced and marked `QUIRK`.

pub mod bands;
pub mod bodice;
pub mod build;
pub mod builtin;
pub mod circle_skirt;
pub mod collars;
mod common;
pub mod design;
pub mod extension;
pub mod godet;
pub mod logo;
pub mod meta;
pub mod pants;
pub mod sample;
pub mod shapes;
pub mod shared;
pub mod skirt_levels;
pub mod skirt_paneled;
pub mod sleeves;

pub use design::Design;
pub use meta::MetaGarment;
pub use shared::{Fit, Side};
