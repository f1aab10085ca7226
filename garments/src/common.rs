//! Helpers shared by the garment programs.

use garmentcode::math::lerp;
use garmentcode::{Body, Result, Vec2, Vec3};

/// A 2D point.
#[inline]
pub fn v2(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

/// A 3D vector.
#[inline]
pub fn v3(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(x, y, z)
}

/// `tan` of an angle in degrees.
#[inline]
pub fn tan_deg(deg: f64) -> f64 {
    deg.to_radians().tan()
}

/// Waist, hip depth and back waist of a bottom garment sitting at `rise`
/// (1 = natural waist, smaller = lower, towards the hip line).
pub fn eval_rise(body: &Body, rise: f64) -> Result<(f64, f64, f64)> {
    let hips_depth = rise * body.hips_line;
    let waist = lerp(body.hips, body.waist, rise)?;
    let back_waist = lerp(body.hip_back_width, body.waist_back_width, rise)?;
    Ok((waist, hips_depth, back_waist))
}
