//! `garmentcode schema [--format reference-yaml|json-schema|table] [--design NAME|FILE.yaml] [--extended]`

use crate::cli::{SchemaArgs, SchemaFormat};
use crate::commands::CliError;
use garmentcode::Params;
use garmentcode::io::write_design;
use garments::Design;

pub fn run(args: SchemaArgs) -> Result<i32, CliError> {
    let space = if args.extended { garments::design::extended_design_space() } else { Design::design_space() };
    if args.design.is_some() && args.format != SchemaFormat::ReferenceYaml {
        return Err(CliError::Usage("--design writes a design file: it goes with --format reference-yaml (the default)".into()));
    }
    match args.format {
        // The design space exactly, as the reference's `default.yaml` has it; with
        // --design, that design as `v` (a design file that builds).
        SchemaFormat::ReferenceYaml => match &args.design {
            None => out!("{}", space.to_yaml()),
            Some(arg) => {
                // A design using the extension is written with it (as `build` writes it).
                let (design, _) = crate::commands::load_design(arg)?;
                let space = if args.extended { space } else { garments::design::space_of(&design) };
                out!("{}", write_design(&design, &space))
            }
        },
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
