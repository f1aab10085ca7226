//! The sleeve-opening / hood inversion (`garmentcode::curves::inversion`) on the
//! 574 calls logged from the reference (28 from the reference cases, 546 from
//! random designs with sleeves or hoods on the five bodies): never worse than the
//! reference on its own objective, within the length and tangent bounds,
//! deterministic, and continuous in its inputs (sweeps without jumps).

mod common;
mod continuity;
mod vectors;
