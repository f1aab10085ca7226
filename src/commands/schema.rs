//! `garmentcode schema [--format reference-yaml|json-schema|table]`

use crate::args::{Args, UsageError};
use crate::commands::CliError;
use garmentcode::Params;
use garments::Design;

pub fn run(mut args: Args) -> Result<i32, CliError> {
    let format = args.value("format")?.unwrap_or_else(|| "reference-yaml".into());
    let rest = args.finish()?;
    if !rest.is_empty() {
        return Err(UsageError(format!("schema: unexpected argument '{}'", rest[0])).into());
    }
    let space = Design::design_space();
    match format.as_str() {
        "reference-yaml" => out!("{}", space.to_yaml()),
        "json-schema" => outln!("{}", serde_json::to_string_pretty(&space.json_schema()).expect("schema serialises")),
        "table" => {
            for p in space.params() {
                let prob = p.default_prob.map(|x| x.to_string()).unwrap_or_else(|| "-".into());
                outln!(
                    "{:<45} {:<11} {:<40} default {:<14} p {:<4} {}",
                    p.path,
                    p.kind.as_str(),
                    p.range.to_string(),
                    p.default.to_string(),
                    prob,
                    p.description
                );
            }
        }
        other => return Err(UsageError(format!("schema --format: expected reference-yaml, json-schema or table, got '{other}'")).into()),
    }
    Ok(0)
}
