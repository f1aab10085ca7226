//! The design space: every parameter's path, type, range, default and sampling
//! probability, in document order.

use super::spec::{Kind, ParamSpec, Range, Value};
use std::collections::HashMap;
use std::sync::OnceLock;
use std::sync::atomic::AtomicUsize;

/// The flattened schema of a design.
///
/// ```
/// use garmentcode::Params;
///
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Skirt {
///     /// Number of panels.
///     #[param(range = 3..=12, default = 6, prob = 0.4)]
///     n_panels: i64,
/// }
///
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Design {
///     skirt: Skirt,
/// }
///
/// let space = Design::design_space();
/// assert!(space.problems().is_empty());
/// let spec = space.get("skirt.n_panels").unwrap();
/// assert_eq!((spec.range.to_string(), spec.default.to_string()), ("[3.0, 12.0]".to_string(), "6".to_string()));
/// assert!(space.is_group("skirt"));
/// assert!(space.to_yaml().starts_with("design:\n  skirt:\n    n_panels:\n"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct DesignSpace {
    pub(crate) params: Vec<ParamSpec>,
    /// Every parameter's path and every group's path (a proper prefix of some
    /// parameter's path, at a dot), for lookups while reading design files.
    pub(crate) index: HashMap<String, Entry>,
    /// Every parameter's path split at its dots (the keys `Params::set_value`
    /// takes), so that reading a design does not split them again.
    pub(crate) keys: Vec<Vec<String>>,
    /// The space's file layout, for reading the files written for it quickly.
    pub(crate) skeleton: SkeletonSlot,
}

/// A design space's own file layout (as [`DesignSpace::to_yaml_with`] writes it)
/// with holes where the parameters' `v` values go.
///
/// Why: files written for a space (the dataset sampler's, the benchmark's) repeat
/// its ranges, types and probabilities around the values, about nine lines out of
/// ten. When a file is the layout with plain values in the holes, comparing the
/// literal text and reading only the values gives what the line reader gives, in a
/// fraction of the time; anything else goes to the line reader.
#[derive(Debug)]
pub(crate) struct Skeleton {
    /// Literal text before each value, and the index of the value's parameter.
    pub(crate) parts: Vec<(String, usize)>,
    /// Literal text after the last value.
    pub(crate) tail: String,
}

/// Lazily built [`Skeleton`], derived from the parameters (so it is not cloned
/// and does not take part in comparisons).
#[derive(Default)]
pub(crate) struct SkeletonSlot {
    /// Files read so far; the layout is built on the second (a single read
    /// would not repay building it).
    pub(crate) reads: AtomicUsize,
    pub(crate) cell: OnceLock<Option<Skeleton>>,
}

impl Clone for SkeletonSlot {
    fn clone(&self) -> Self {
        SkeletonSlot::default()
    }
}

impl PartialEq for SkeletonSlot {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl std::fmt::Debug for SkeletonSlot {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SkeletonSlot")
    }
}

/// What a dotted path names.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Entry {
    /// The parameter at this index.
    Param(usize),
    /// A group: some parameter lies below it.
    Group,
}

impl DesignSpace {
    /// A space from parameter specs (in document order).
    pub fn new(params: Vec<ParamSpec>) -> DesignSpace {
        let mut index = HashMap::with_capacity(params.len() * 2);
        for (i, p) in params.iter().enumerate() {
            index.insert(p.path.clone(), Entry::Param(i));
        }
        for p in &params {
            for (dot, _) in p.path.match_indices('.') {
                index.entry(p.path[..dot].to_string()).or_insert(Entry::Group);
            }
        }
        let keys = params.iter().map(|p| p.path.split('.').map(str::to_string).collect()).collect();
        DesignSpace { params, index, keys, skeleton: SkeletonSlot::default() }
    }

    /// Every parameter, in document order.
    pub fn params(&self) -> &[ParamSpec] {
        &self.params
    }

    /// A parameter by dotted path.
    pub fn get(&self, path: &str) -> Option<&ParamSpec> {
        self.index_of(path).map(|i| &self.params[i])
    }

    /// The keys of parameter `i`'s path.
    pub(crate) fn keys(&self, i: usize) -> &[String] {
        &self.keys[i]
    }

    /// Index of the parameter at `path` in [`DesignSpace::params`].
    pub(crate) fn index_of(&self, path: &str) -> Option<usize> {
        match self.index.get(path) {
            Some(Entry::Param(i)) => Some(*i),
            _ => None,
        }
    }

    /// What `path` names: a parameter (its index), a group, or nothing.
    pub(crate) fn lookup(&self, path: &str) -> Option<Entry> {
        self.index.get(path).copied()
    }

    /// Whether `prefix` is a group (some parameter lies below it).
    pub fn is_group(&self, prefix: &str) -> bool {
        self.params.iter().any(|s| s.path.len() > prefix.len() && s.path.starts_with(prefix) && s.path.as_bytes()[prefix.len()] == b'.')
    }

    /// Problems that make the space unusable for sampling (empty or reversed ranges,
    /// defaults outside their range, probabilities outside [0, 1], a default that is
    /// the only option while it must be avoided).
    pub fn problems(&self) -> Vec<String> {
        let mut out = Vec::new();
        for p in &self.params {
            let here = &p.path;
            if let Some(prob) = p.default_prob
                && !(0.0..=1.0).contains(&prob)
            {
                out.push(format!("{here}: default_prob {prob} is outside [0, 1]"));
            }
            match (&p.kind, &p.range) {
                (Kind::Float | Kind::Int, Range::Numeric { lo, hi }) => {
                    if !(lo.is_finite() && hi.is_finite()) || lo >= hi {
                        out.push(format!("{here}: range [{lo}, {hi}] is empty or reversed"));
                    }
                }
                (Kind::Float | Kind::Int, Range::Options(_)) => {
                    out.push(format!("{here}: a {} parameter needs a [min, max] range", p.kind.as_str()))
                }
                (_, Range::Options(opts)) => {
                    if opts.is_empty() {
                        out.push(format!("{here}: no options"));
                    }
                    let others = opts.iter().filter(|o| !o.loosely_eq(&p.default)).count()
                        + usize::from(p.kind == Kind::SelectNull && p.default != Value::Null && !opts.contains(&Value::Null));
                    if p.default_prob.is_some_and(|x| x < 1.0) && others == 0 {
                        out.push(format!("{here}: the default is the only option, so it cannot be avoided when sampling"));
                    }
                }
                (_, Range::Numeric { .. }) => out.push(format!("{here}: a {} parameter needs a list of options", p.kind.as_str())),
            }
            if let Err(e) = p.check(&p.default) {
                out.push(format!("{here}: default: {e}"));
            }
        }
        out
    }
}
