//! `garmentcode schema [--format reference-yaml|json-schema|table]`

use crate::cli::{SchemaArgs, SchemaFormat};
use crate::commands::CliError;
use garmentcode::Params;
use garmentcode::io::write_design;
use garments::Design;

pub fn run(args: SchemaArgs) -> Result<i32, CliError> {
    let space = Design::design_space();
    match args.format {
        // The built-in default design in the reference's layout (every parameter
        // with its range and probability): a design file that builds.
        SchemaFormat::ReferenceYaml => {
            let default = garments::builtin::design(garments::builtin::DEFAULT_DESIGN).expect("the default design is built in");
            out!("{}", write_design(&default, &space))
        }
        SchemaFormat::JsonSchema => outln!("{}", serde_json::to_string_pretty(&space.json_schema()).expect("schema serialises")),
        SchemaFormat::Table => {
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
    }
    Ok(0)
}
