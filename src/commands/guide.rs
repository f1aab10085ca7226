//! `garmentcode guide --out DIR [--body NAME|FILE]`: the measuring guide
//! (`garmentcode::guide`) as a printable page and one figure per measurement.

use crate::cli::GuideArgs;
use crate::commands::{CliError, load_body, write_folder};
use crate::output::OutputSet;
use garmentcode::guide::{figure_svg, guide_html};

pub fn run(args: GuideArgs) -> Result<i32, CliError> {
    let (body, label) = load_body(&args.body)?;
    let mut set = OutputSet::default();
    set.add("measuring-guide.html", guide_html(&body, &label).into_bytes());
    for m in garmentcode::MEASUREMENTS {
        let svg = figure_svg(&body, m.name).expect("a figure for every measurement");
        set.add(&format!("figure-{}.svg", m.name), svg.into_bytes());
    }
    set.add_input(&args.body);
    write_folder(&set, &args.out, args.force)?;
    eprintln!("wrote {}: measuring-guide.html and {} figures (drawn on {label})", args.out.display(), garmentcode::MEASUREMENTS.len());
    Ok(0)
}
