//! Per-thread memo tables of pure geometric computations that a garment program
//! repeats many times on unchanged geometry.
//!
//! Keys are the exact bits of every input the computation reads and values are
//! what the computation gave, so results are identical with or without the memo,
//! whatever was computed before. The tables are therefore kept from one garment
//! to the next (at most `CAPACITY` entries each): random designs share many parameter
//! values (a parameter often keeps its default), so a stream of designs meets the
//! same curves again (a third of the sleeve inversions and edge linearisations of
//! the dataset sampler, two thirds of the tangent fits).

use crate::math::Vec2;
use std::cell::RefCell;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hash, Hasher};

/// Multiply-rotate hashing of integer keys (few, not adversarial; SipHash cost
/// more than the lookups saved).
#[derive(Default)]
struct WordHasher(u64);

impl Hasher for WordHasher {
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut w = [0u8; 8];
            w[..chunk.len()].copy_from_slice(chunk);
            self.write_u64(u64::from_le_bytes(w));
        }
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
    fn write_u8(&mut self, x: u8) {
        self.write_u64(u64::from(x));
    }
    fn write_u32(&mut self, x: u32) {
        self.write_u64(u64::from(x));
    }
    fn write_usize(&mut self, x: usize) {
        self.write_u64(x as u64);
    }
    fn finish(&self) -> u64 {
        self.0
    }
}

type Table<K, V> = RefCell<HashMap<K, V, BuildHasherDefault<WordHasher>>>;

/// Entries kept at most per table (then emptied): a garment needs a few dozen, and
/// the reuse between garments is among nearby ones (a larger table found few more).
const CAPACITY: usize = 4096;

/// Calls `read` with the value for `key`, computed with `make` the first time
/// (outside any borrow of the table).
fn lookup<K: Eq + Hash, V, R>(table: &Table<K, V>, key: K, make: impl FnOnce() -> V, read: impl FnOnce(&V) -> R) -> R {
    if let Some(v) = table.borrow().get(&key) {
        return read(v);
    }
    let v = make();
    let mut table = table.borrow_mut();
    if table.len() >= CAPACITY {
        table.clear();
    }
    read(table.entry(key).or_insert(v))
}

/// Key of one edge linearisation: shape or geometry bits, kind, number of points.
pub(crate) type EdgeKey = ([u64; 6], u8, usize);

/// Key of one curve inversion: the bits of its control points, end tangents and
/// target length.
pub(crate) type InversionKey = [u64; 13];

/// Key of one quadratic tangent fit: which end tangents are given, their bits and
/// the bits of the initial guess.
pub(crate) type TangentFitKey = [u64; 7];

thread_local! {
    static EDGE_POINTS: Table<EdgeKey, Vec<Vec2>> = RefCell::default();
    static INVERSIONS: Table<InversionKey, [[f64; 2]; 4]> = RefCell::default();
    static TANGENT_FITS: Table<TangentFitKey, [f64; 2]> = RefCell::default();
}

/// Calls `f` with the memoised linearisation points for `key`, computing them
/// with `make` once.
pub(crate) fn edge_points<R>(key: EdgeKey, make: impl FnOnce() -> Vec<Vec2>, f: impl FnOnce(&[Vec2]) -> R) -> R {
    EDGE_POINTS.with(|table| lookup(table, key, make, |pts| f(pts)))
}

/// The memoised result of the inversion `key`, computed with `make` once. The
/// two sleeves of a symmetric garment (and a sleeve's front and back where their
/// armholes agree) invert the very same curve.
pub(crate) fn inversion(key: InversionKey, make: impl FnOnce() -> [[f64; 2]; 4]) -> [[f64; 2]; 4] {
    INVERSIONS.with(|table| lookup(table, key, make, |r| *r))
}

/// The memoised result of the quadratic tangent fit `key`, computed with `make`
/// once: the right and left halves of a symmetric garment fit the same curves.
pub(crate) fn tangent_fit(key: TangentFitKey, make: impl FnOnce() -> [f64; 2]) -> [f64; 2] {
    TANGENT_FITS.with(|table| lookup(table, key, make, |r| *r))
}

/// Forget every entry of this thread's tables (tests and benchmarks: to compute
/// afresh; results do not change).
pub fn clear() {
    EDGE_POINTS.with(|c| c.borrow_mut().clear());
    INVERSIONS.with(|c| c.borrow_mut().clear());
    TANGENT_FITS.with(|c| c.borrow_mut().clear());
}
