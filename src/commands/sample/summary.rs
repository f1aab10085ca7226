//! `dataset_properties.yaml`: what the dataset is (seed, size, design space,
//! bodies), what it holds (garment types), what was rejected and why, and how the
//! run went. Everything but the final `run:` section depends on the dataset alone,
//! so it is the same for any number of threads, and after a resume.

use super::store::Record;
use garmentcode::Choice;
use garmentcode::parity::yaml::{self, Node, Value as Y};
use garments::design::{BottomKind, UpperKind, WaistbandKind};
use garments::sample::{Reason, sample_name};

/// Rejected attempts listed per reason as examples to inspect.
const EXAMPLES: usize = 5;

/// Main garment types and style tags of the reference's statistics, in its order.
const MAIN_TYPES: &[&str] = &["upper_garment", "dress", "jumpsuit", "skirt", "pants"];
const STYLES: &[&str] =
    &["asymmetric_top", "hoodie", "sleeveless", "with_sleeves", "short_sleeve", "long_sleeve", "mini", "knee_len", "midi", "maxi"];

/// What the summary describes besides the records.
pub struct About<'a> {
    pub seed: u64,
    pub n: u64,
    /// `I/K` when sharded.
    pub shard: Option<(u64, u64)>,
    pub design_space: &'a str,
    pub bodies: Vec<String>,
    pub formats: Vec<&'static str>,
    pub seconds: f64,
    pub made: usize,
    pub resumed: usize,
    pub jobs: usize,
}

fn s(x: &str) -> Node {
    Node::new(Y::Str(x.to_string()))
}

fn int(x: u64) -> Node {
    Node::new(Y::Int(x as i64))
}

fn map(pairs: Vec<(&str, Node)>) -> Node {
    Node::new(Y::Map(pairs.into_iter().map(|(k, v)| (s(k), v)).collect()))
}

fn seq(items: Vec<Node>) -> Node {
    Node::new(Y::Seq(items))
}

/// Counts of `names` (in that order), then any other value seen, in order of
/// first appearance.
fn counts<'r>(names: &[&str], values: impl Iterator<Item = &'r str>) -> Node {
    let mut out: Vec<(String, u64)> = names.iter().map(|n| (n.to_string(), 0)).collect();
    for v in values {
        match out.iter_mut().find(|(n, _)| n == v) {
            Some(slot) => slot.1 += 1,
            None => out.push((v.to_string(), 1)),
        }
    }
    Node::new(Y::Map(out.into_iter().map(|(k, c)| (s(&k), int(c))).collect()))
}

/// The text of `dataset_properties.yaml` for `records` (sorted by index).
pub fn properties(about: &About, records: &[Record]) -> String {
    let accepted: Vec<_> = records.iter().filter_map(|r| r.accepted.as_ref()).collect();
    let failed: Vec<Node> = records.iter().filter(|r| r.accepted.is_none()).map(|r| s(&sample_name(r.index))).collect();
    let with_none = |names: &[&'static str]| names.iter().copied().chain(["none"]).collect::<Vec<_>>();

    let types = map(vec![
        ("upper", counts(&with_none(UpperKind::NAMES), accepted.iter().map(|a| a.upper.as_str()))),
        ("waistband", counts(&with_none(WaistbandKind::NAMES), accepted.iter().map(|a| a.waistband.as_str()))),
        ("bottom", counts(&with_none(BottomKind::NAMES), accepted.iter().map(|a| a.bottom.as_str()))),
        ("main", counts(MAIN_TYPES, accepted.iter().map(|a| a.main.as_str()))),
        ("style", counts(STYLES, accepted.iter().flat_map(|a| a.styles.iter().map(String::as_str)))),
    ]);

    let all_rejections = || records.iter().flat_map(|r| r.rejections.iter().map(move |x| (r.index, x)));
    let keys: Vec<&str> = Reason::ALL.iter().map(|r| r.key()).collect();
    let by_reason = counts(&keys, all_rejections().map(|(_, x)| x.reason.key()));
    let examples = Reason::ALL
        .iter()
        .filter_map(|reason| {
            let list: Vec<Node> = all_rejections()
                .filter(|(_, x)| x.reason == *reason)
                .take(EXAMPLES)
                .map(|(index, x)| {
                    map(vec![
                        ("sample", s(&sample_name(index))),
                        ("index", int(index)),
                        ("attempt", int(u64::from(x.attempt))),
                        ("body", s(&x.body)),
                        ("message", s(&x.message)),
                    ])
                })
                .collect();
            (!list.is_empty()).then(|| (reason.key(), seq(list)))
        })
        .collect();
    let rejections = map(vec![
        ("total", int(all_rejections().count() as u64)),
        ("by_reason", by_reason),
        ("examples", map(examples)),
        (
            "inspect",
            s(
                "garmentcode sample --seed SEED --replay INDEX:ATTEMPT --out DIR (with the same --design-space and --bodies) rebuilds one attempt",
            ),
        ),
    ]);

    let mut top =
        vec![("generator", s(&format!("garmentcode {}", env!("CARGO_PKG_VERSION")))), ("seed", int(about.seed)), ("count", int(about.n))];
    if let Some((i, k)) = about.shard {
        top.push(("shard", s(&format!("{i}/{k}"))));
    }
    top.extend([
        ("design_space", s(about.design_space)),
        ("bodies", seq(about.bodies.iter().map(|b| s(b)).collect())),
        ("formats", seq(about.formats.iter().map(|f| s(f)).collect())),
        ("samples", int(accepted.len() as u64)),
        ("failed", int(failed.len() as u64)),
    ]);
    if !failed.is_empty() {
        top.push(("failed_samples", seq(failed)));
    }
    top.extend([
        ("garment_types", types),
        ("bodies_used", counts(&about.bodies.iter().map(String::as_str).collect::<Vec<_>>(), accepted.iter().map(|a| a.body.as_str()))),
        ("rejections", rejections),
        (
            "run",
            map(vec![
                ("time_seconds", Node::new(Y::Float((about.seconds * 1000.0).round() / 1000.0))),
                ("made", int(about.made as u64)),
                ("resumed", int(about.resumed as u64)),
                ("jobs", int(about.jobs as u64)),
            ]),
        ),
    ]);
    yaml::to_string(&map(top))
}

/// The file name: one per shard, so shards sharing a folder do not overwrite each
/// other's; a run without `--shard` writes the whole dataset's.
pub fn file_name(shard: Option<(u64, u64)>) -> String {
    match shard {
        None => "dataset_properties.yaml".into(),
        Some((i, k)) => format!("dataset_properties_shard_{i}_of_{k}.yaml"),
    }
}
