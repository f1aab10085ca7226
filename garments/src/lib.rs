//! The GarmentCode garment library.
