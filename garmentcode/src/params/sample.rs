//! Random designs with the reference's sampling semantics on a named generator.
//!
//! Every parameter is sampled independently, in document order. `default_prob` is
//! the probability of keeping the default; when the default is not kept and a
//! probability is given, the default is excluded (removed from the options, re-drawn
//! for numbers). Without a probability the parameter is always drawn afresh.
//!
//! The generator is ChaCha8 (`rand_chacha`), seeded from `(seed, index)` so that
//! sample `index` of seed `seed` is the same on every machine and can be
//! regenerated alone.

use super::Params;
use super::space::DesignSpace;
use super::spec::{Kind, ParamSpec, Range, Value};
use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{RngCore, SeedableRng};
use std::borrow::Cow;

/// The generator of sample `index` for `seed`: ChaCha8 seeded with `seed`, on
/// stream `index`.
pub fn sample_rng(seed: u64, index: u64) -> ChaCha8Rng {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    rng.set_stream(index);
    rng
}

/// Draws random designs from a design space.
#[derive(Clone, Debug)]
pub struct Sampler {
    space: DesignSpace,
    /// Per parameter, in document order, the options a fresh draw picks from (the
    /// categorical options, with none for categorical-or-none, without the default
    /// when a probability is given); empty for numbers.
    choices: Vec<Vec<Value>>,
}

impl Sampler {
    /// A sampler over `space` (which should have no [`DesignSpace::problems`]).
    pub fn new(space: DesignSpace) -> Sampler {
        let choices = space.params().iter().map(fresh_choices).collect();
        Sampler { space, choices }
    }

    /// The design space.
    pub fn space(&self) -> &DesignSpace {
        &self.space
    }

    /// One random design as `(path, value)` pairs in document order.
    pub fn sample_values(&self, rng: &mut impl RngCore) -> Vec<(String, Value)> {
        self.space.params().iter().zip(&self.choices).map(|(p, c)| (p.path.clone(), draw(p, c, rng).into_owned())).collect()
    }

    /// One random design as a typed parameter tree.
    ///
    /// The same draws as [`Sampler::sample_values`], set straight into the tree.
    pub fn sample<D: Params>(&self, rng: &mut impl RngCore) -> D {
        let mut d = D::defaults();
        let mut keys: Vec<&str> = Vec::with_capacity(8);
        for (i, (p, c)) in self.space.params().iter().zip(&self.choices).enumerate() {
            let v = draw(p, c, rng);
            keys.clear();
            keys.extend(self.space.keys(i).iter().map(String::as_str));
            if let Err(e) = d.set_value(&keys, &v) {
                panic!("sampled value {v:?} does not fit design.{}: {e}", p.path);
            }
        }
        d
    }
}

/// The options a fresh draw of `p` picks from (see [`Sampler::choices`]).
fn fresh_choices(p: &ParamSpec) -> Vec<Value> {
    let Range::Options(opts) = &p.range else { return Vec::new() };
    let mut opts = opts.clone();
    if p.kind == Kind::SelectNull && !opts.contains(&Value::Null) {
        opts.push(Value::Null);
    }
    if p.default_prob.is_some()
        && let Some(i) = opts.iter().position(|o| o.loosely_eq(&p.default))
    {
        opts.remove(i);
    }
    opts
}

#[cfg(test)]
fn sample_one(p: &ParamSpec, rng: &mut impl RngCore) -> Value {
    draw(p, &fresh_choices(p), rng).into_owned()
}

/// One draw of `p`; `choices` are its [`fresh_choices`]. A default or an option
/// is borrowed (a design is set from it; cloning the option names cost more than
/// drawing them).
fn draw<'a>(p: &'a ParamSpec, choices: &'a [Value], rng: &mut impl RngCore) -> Cow<'a, Value> {
    let keep = p.default_prob.is_some_and(|prob| unit(rng) < prob);
    if keep {
        return Cow::Borrowed(&p.default);
    }
    let exclude = p.default_prob.is_some();
    match (&p.kind, &p.range) {
        (Kind::Int, Range::Numeric { lo, hi }) => {
            let (lo, hi) = (*lo as i64, *hi as i64);
            loop {
                let v = lo + below(rng, (hi - lo + 1) as u64) as i64;
                if !(exclude && Value::Int(v).loosely_eq(&p.default)) {
                    return Cow::Owned(Value::Int(v));
                }
            }
        }
        (Kind::Float, Range::Numeric { lo, hi }) => {
            let def = p.default.as_f64().unwrap_or(f64::NAN);
            loop {
                let v = lo + (hi - lo) * unit(rng);
                if !(exclude && (v - def).abs() < 1e-4) {
                    return Cow::Owned(Value::Float(v));
                }
            }
        }
        (_, Range::Options(_)) => {
            if choices.is_empty() {
                return Cow::Borrowed(&p.default);
            }
            Cow::Borrowed(&choices[below(rng, choices.len() as u64) as usize])
        }
        _ => Cow::Borrowed(&p.default),
    }
}

/// Uniform real in [0, 1) with 53 random bits.
fn unit(rng: &mut impl RngCore) -> f64 {
    (rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// Uniform integer in [0, n) without modulo bias (n ≥ 1): the draw behind integer
/// and categorical parameters, shared with samplers built on [`sample_rng`].
pub fn below(rng: &mut impl RngCore, n: u64) -> u64 {
    let zone = (u64::MAX / n) * n;
    loop {
        let x = rng.next_u64();
        if x < zone {
            return x % n;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(kind: Kind, range: Range, default: Value, prob: Option<f64>) -> ParamSpec {
        ParamSpec { path: "x".into(), kind, range, default, default_prob: prob, description: String::new() }
    }

    #[test]
    fn default_prob_is_the_probability_of_the_default() {
        let p = spec(Kind::Int, Range::Numeric { lo: 1.0, hi: 5.0 }, Value::Int(3), Some(0.3));
        let mut rng = sample_rng(7, 0);
        let n = 20000;
        let hits = (0..n).filter(|_| sample_one(&p, &mut rng) == Value::Int(3)).count();
        let rate = hits as f64 / n as f64;
        assert!((rate - 0.3).abs() < 0.02, "{rate}");
    }

    #[test]
    fn integer_bounds_are_inclusive() {
        let p = spec(Kind::Int, Range::Numeric { lo: 4.0, hi: 6.0 }, Value::Int(4), None);
        let mut rng = sample_rng(1, 2);
        let mut seen = [false; 3];
        for _ in 0..200 {
            let Value::Int(v) = sample_one(&p, &mut rng) else { panic!() };
            seen[(v - 4) as usize] = true;
        }
        assert_eq!(seen, [true; 3]);
    }

    #[test]
    fn select_null_includes_null() {
        let p = spec(Kind::SelectNull, Range::Options(vec![Value::Str("A".into())]), Value::Str("A".into()), Some(0.0));
        let mut rng = sample_rng(3, 0);
        for _ in 0..20 {
            assert_eq!(sample_one(&p, &mut rng), Value::Null, "the default is excluded, null remains");
        }
    }

    #[test]
    fn streams_are_reproducible_and_independent() {
        let a: Vec<u64> = (0..4).map(|_| sample_rng(5, 9).next_u64()).collect();
        assert!(a.windows(2).all(|w| w[0] == w[1]));
        assert_ne!(sample_rng(5, 9).next_u64(), sample_rng(5, 10).next_u64());
        assert_ne!(sample_rng(5, 9).next_u64(), sample_rng(6, 9).next_u64());
    }
}
