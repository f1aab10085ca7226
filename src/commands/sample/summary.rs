//! `dataset_properties.yaml`: what the dataset is (seed, size, design space,
//! bodies), what it holds (garment types), what was rejected and why, and how the
//! run went. Everything but the final `run:` section depends on the dataset alone,
//! so it is the same for any number of threads, and after a resume.

use super::store::{Record, RejectionRecord};
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

/// Counts of named values: `names` first (in that order, zero when unseen), then
/// any other value in order of the first sample index it was seen at, so that the
/// order does not depend on the order samples come in.
struct Counts {
    /// `(value, count, first index)`: the named values, then the others.
    items: Vec<(String, u64, u64)>,
    named: usize,
}

impl Counts {
    fn new(names: &[&str]) -> Counts {
        Counts { items: names.iter().map(|n| (n.to_string(), 0, 0)).collect(), named: names.len() }
    }

    fn add(&mut self, value: &str, index: u64) {
        match self.items.iter_mut().find(|(n, ..)| n == value) {
            Some(slot) => {
                slot.1 += 1;
                slot.2 = slot.2.min(index);
            }
            None => self.items.push((value.to_string(), 1, index)),
        }
    }

    fn node(&self) -> Node {
        let mut others: Vec<&(String, u64, u64)> = self.items[self.named..].iter().collect();
        others.sort_by_key(|(_, _, first)| *first);
        let all = self.items[..self.named].iter().chain(others);
        Node::new(Y::Map(all.map(|(k, c, _)| (s(k), int(*c))).collect()))
    }
}

/// A tally of sample records (the whole of `dataset_properties.yaml` but the
/// run's figures), taken as records come in, in any order: its size depends on
/// the number of distinct values, the failed samples and [`EXAMPLES`], not on the
/// number of samples, so a run of millions keeps a flat memory.
pub struct Tally {
    upper: Counts,
    waistband: Counts,
    bottom: Counts,
    main: Counts,
    style: Counts,
    bodies: Counts,
    reasons: Counts,
    samples: u64,
    rejected: u64,
    /// Indices of samples with every attempt rejected.
    failed: Vec<u64>,
    /// Per reason of [`Reason::ALL`], the first [`EXAMPLES`] rejections by (index, attempt).
    examples: Vec<Vec<(u64, RejectionRecord)>>,
    /// Drapes made (with the `drape` format).
    draped: u64,
    /// Failed drapes: per reason (in order of first index), the sample indices, as the
    /// reference lists failed simulations (`sim.stats.fails`).
    drape_fails: Vec<(String, Vec<u64>)>,
    /// The first [`EXAMPLES`] messages of drapes that could not run, by index.
    drape_errors: Vec<(u64, String)>,
}

impl Tally {
    /// An empty tally for a dataset of these bodies.
    pub fn new(bodies: &[String]) -> Tally {
        let with_none = |names: &[&'static str]| names.iter().copied().chain(["none"]).collect::<Vec<_>>();
        let keys: Vec<&str> = Reason::ALL.iter().map(|r| r.key()).collect();
        Tally {
            upper: Counts::new(&with_none(UpperKind::NAMES)),
            waistband: Counts::new(&with_none(WaistbandKind::NAMES)),
            bottom: Counts::new(&with_none(BottomKind::NAMES)),
            main: Counts::new(MAIN_TYPES),
            style: Counts::new(STYLES),
            bodies: Counts::new(&bodies.iter().map(String::as_str).collect::<Vec<_>>()),
            reasons: Counts::new(&keys),
            samples: 0,
            rejected: 0,
            failed: Vec::new(),
            examples: vec![Vec::new(); Reason::ALL.len()],
            draped: 0,
            drape_fails: Vec::new(),
            drape_errors: Vec::new(),
        }
    }

    /// Count one sample's record.
    pub fn add(&mut self, r: &Record) {
        let i = r.index;
        match &r.accepted {
            Some(a) => {
                self.samples += 1;
                self.upper.add(&a.upper, i);
                self.waistband.add(&a.waistband, i);
                self.bottom.add(&a.bottom, i);
                self.main.add(&a.main, i);
                for style in &a.styles {
                    self.style.add(style, i);
                }
                self.bodies.add(&a.body, i);
            }
            None => self.failed.push(i),
        }
        if let Some(d) = &r.drape {
            self.draped += 1;
            for reason in &d.fails {
                match self.drape_fails.iter_mut().find(|(k, _)| k == reason) {
                    Some((_, list)) => list.push(i),
                    None => self.drape_fails.push((reason.clone(), vec![i])),
                }
            }
            if let Some(m) = &d.message {
                let at = self.drape_errors.partition_point(|(j, _)| *j < i);
                self.drape_errors.insert(at, (i, m.clone()));
                self.drape_errors.truncate(EXAMPLES);
            }
        }
        for x in &r.rejections {
            self.rejected += 1;
            self.reasons.add(x.reason.key(), i);
            let slot = Reason::ALL.iter().position(|reason| *reason == x.reason).expect("every reason is listed");
            let list = &mut self.examples[slot];
            let key = (i, x.attempt);
            if list.len() < EXAMPLES || list.last().is_some_and(|(j, y)| key < (*j, y.attempt)) {
                let at = list.partition_point(|(j, y)| (*j, y.attempt) < key);
                list.insert(at, (i, x.clone()));
                list.truncate(EXAMPLES);
            }
        }
    }

    /// Accepted samples.
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// Samples whose drape failed (any reason).
    pub fn failed_drapes(&self) -> u64 {
        let mut all: Vec<u64> = self.drape_fails.iter().flat_map(|(_, l)| l.iter().copied()).collect();
        all.sort_unstable();
        all.dedup();
        all.len() as u64
    }

    /// Rejected designs (drawn again).
    pub fn rejected(&self) -> u64 {
        self.rejected
    }

    /// Names of the samples with every attempt rejected, by index.
    pub fn failed(&self) -> Vec<String> {
        let mut failed = self.failed.clone();
        failed.sort_unstable();
        failed.into_iter().map(sample_name).collect()
    }

    /// The text of `dataset_properties.yaml`.
    pub fn properties(&self, about: &About) -> String {
        let failed: Vec<Node> = self.failed().iter().map(|n| s(n)).collect();
        let types = map(vec![
            ("upper", self.upper.node()),
            ("waistband", self.waistband.node()),
            ("bottom", self.bottom.node()),
            ("main", self.main.node()),
            ("style", self.style.node()),
        ]);
        let examples = Reason::ALL
            .iter()
            .zip(&self.examples)
            .filter(|(_, list)| !list.is_empty())
            .map(|(reason, list)| {
                let list = list
                    .iter()
                    .map(|(index, x)| {
                        map(vec![
                            ("sample", s(&sample_name(*index))),
                            ("index", int(*index)),
                            ("attempt", int(u64::from(x.attempt))),
                            ("body", s(&x.body)),
                            ("message", s(&x.message)),
                        ])
                    })
                    .collect();
                (reason.key(), seq(list))
            })
            .collect();
        let rejections = map(vec![
            ("total", int(self.rejected)),
            ("by_reason", self.reasons.node()),
            ("examples", map(examples)),
            (
                "inspect",
                s(
                    "garmentcode sample --seed SEED --replay INDEX:ATTEMPT --out DIR (with the same --design-space and --bodies) rebuilds one attempt",
                ),
            ),
        ]);

        let mut top = vec![
            ("generator", s(&format!("garmentcode {}", env!("CARGO_PKG_VERSION")))),
            ("seed", int(about.seed)),
            ("count", int(about.n)),
        ];
        if let Some((i, k)) = about.shard {
            top.push(("shard", s(&format!("{i}/{k}"))));
        }
        top.extend([
            ("design_space", s(about.design_space)),
            ("bodies", seq(about.bodies.iter().map(|b| s(b)).collect())),
            ("formats", seq(about.formats.iter().map(|f| s(f)).collect())),
            ("samples", int(self.samples)),
            ("failed", int(failed.len() as u64)),
        ]);
        if !failed.is_empty() {
            top.push(("failed_samples", seq(failed)));
        }
        if about.formats.contains(&"drape") {
            let mut fails: Vec<(String, Vec<u64>)> = self.drape_fails.clone();
            fails.iter_mut().for_each(|(_, l)| l.sort_unstable());
            fails.sort_by_key(|(_, l)| l[0]);
            let names = |l: &[u64]| seq(l.iter().map(|&i| s(&sample_name(i))).collect());
            let by_reason = fails.iter().map(|(k, l)| (k.as_str(), int(l.len() as u64))).collect();
            let errors = self.drape_errors.iter().map(|(i, m)| map(vec![("sample", s(&sample_name(*i))), ("message", s(m))])).collect();
            top.push((
                "drape",
                map(vec![
                    ("draped", int(self.draped)),
                    ("failed", int(self.failed_drapes())),
                    ("by_reason", map(by_reason)),
                    ("fails", map(fails.iter().map(|(k, l)| (k.as_str(), names(l))).collect())),
                    ("errors", seq(errors)),
                ]),
            ));
        }
        top.extend([
            ("garment_types", types),
            ("bodies_used", self.bodies.node()),
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
}

/// The file name: one per shard, so shards sharing a folder do not overwrite each
/// other's; a run without `--shard` writes the whole dataset's.
pub fn file_name(shard: Option<(u64, u64)>) -> String {
    match shard {
        None => "dataset_properties.yaml".into(),
        Some((i, k)) => format!("dataset_properties_shard_{i}_of_{k}.yaml"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::commands::sample::store::Accepted;

    /// Records with a mix of accepted, failed and rejected samples, and a style
    /// and a garment type the summary does not name.
    fn records() -> Vec<Record> {
        (0..60u64)
            .map(|i| {
                let rejections = (0..(i % 3) as u32)
                    .map(|attempt| RejectionRecord {
                        attempt,
                        body: "mean_all".into(),
                        reason: Reason::ALL[(i as usize + attempt as usize) % 2 * 3],
                        message: format!("sample {i} attempt {attempt}"),
                    })
                    .collect();
                let accepted = (i % 7 != 3).then(|| Accepted {
                    attempt: (i % 3) as u32,
                    body: if i % 2 == 0 { "mean_all" } else { "f_smpl" }.into(),
                    upper: if i % 5 == 0 { "none" } else { "Shirt" }.into(),
                    waistband: "none".into(),
                    bottom: if i % 4 == 0 { "Pants" } else { "none" }.into(),
                    main: if i == 41 { "cape" } else { "upper_garment" }.into(),
                    styles: if i > 30 { vec!["long_sleeve".into(), format!("odd_{}", i % 2)] } else { vec![] },
                    panels: 4,
                });
                Record { index: i, accepted, rejections, drape: None }
            })
            .collect()
    }

    fn text(records: &[Record]) -> String {
        let bodies = vec!["mean_all".to_string(), "f_smpl".to_string()];
        let mut tally = Tally::new(&bodies);
        records.iter().for_each(|r| tally.add(r));
        let about = About {
            seed: 1,
            n: 60,
            shard: None,
            design_space: "built-in",
            bodies,
            formats: vec!["json"],
            seconds: 1.0,
            made: 60,
            resumed: 0,
            jobs: 2,
        };
        tally.properties(&about)
    }

    #[test]
    fn the_summary_does_not_depend_on_the_order_records_come_in() {
        let mut shuffled = records();
        let sorted = text(&shuffled);
        shuffled.reverse();
        shuffled.swap(3, 40);
        assert_eq!(text(&shuffled), sorted);
        // Other values in order of the first sample they appear in.
        assert!(sorted.contains("  style:\n"), "{sorted}");
        let odd_0 = sorted.find("odd_0").unwrap();
        let odd_1 = sorted.find("odd_1").unwrap();
        assert!(odd_0 < odd_1, "odd_0 (first at sample 32; 31 failed) before odd_1 (33)");
        assert!(sorted.contains("cape: 1"));
    }

    #[test]
    fn rejection_examples_are_the_first_by_index_and_attempt() {
        let all = records();
        let t = text(&all);
        let first = Reason::ALL[0];
        let expected: Vec<String> = all
            .iter()
            .flat_map(|r| r.rejections.iter().map(move |x| (r.index, x)))
            .filter(|(_, x)| x.reason == first)
            .take(EXAMPLES)
            .map(|(_, x)| x.message.clone())
            .collect();
        assert_eq!(expected.len(), EXAMPLES);
        let section = &t[t.find(&format!("    {}:\n", first.key())).unwrap()..];
        let shown: Vec<&str> = section.lines().filter_map(|l| l.trim().strip_prefix("message: ")).take(EXAMPLES).collect();
        assert_eq!(shown, expected);
        let total: usize = all.iter().map(|r| r.rejections.len()).sum();
        assert!(t.contains(&format!("  total: {total}\n")));
        let failed = all.iter().filter(|r| r.accepted.is_none()).count();
        assert!(t.contains(&format!("failed: {failed}\n")));
    }
}
