//! Built-in bodies and named designs, embedded in the binary.

use garmentcode::io::read_design;
use garmentcode::{Body, BodyError};

use crate::Design;

/// Names and YAML of the built-in bodies (the reference's five bodies; the figures
/// carry over, the files are the project's own).
pub const BODIES: &[(&str, &str)] = &[
    ("mean_all", include_str!("../data/bodies/mean_all.yaml")),
    ("mean_female", include_str!("../data/bodies/mean_female.yaml")),
    ("mean_male", include_str!("../data/bodies/mean_male.yaml")),
    ("f_smpl_average_A40", include_str!("../data/bodies/f_smpl_average_A40.yaml")),
    ("m_smpl_average_A40", include_str!("../data/bodies/m_smpl_average_A40.yaml")),
];

/// The neutral body used when none is given.
pub const DEFAULT_BODY: &str = "mean_all";

/// A built-in body by name.
pub fn body(name: &str) -> Option<Body> {
    BODIES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(n, text)| Body::from_yaml(text, &format!("<built-in body {n}>")).expect("built-in bodies are valid"))
}

/// Read a body file, which may start from a built-in body: a `body:` mapping
/// with `base: mean_female` takes that body's measurements, and the ones it
/// lists replace them (see [`Body::from_yaml_with_bases`]). How the command-line
/// tool, the web API and the Python package read body files.
pub fn body_from_yaml(text: &str, file: &str) -> Result<Body, BodyError> {
    Body::from_yaml_with_bases(text, file, BODIES)
}

/// Names and YAML of the built-in designs (only the values that differ from the
/// defaults are listed).
pub const DESIGNS: &[(&str, &str)] = &[
    ("t-shirt", include_str!("../data/designs/t-shirt.yaml")),
    ("fitted-dress", include_str!("../data/designs/fitted-dress.yaml")),
    ("sundress", include_str!("../data/designs/sundress.yaml")),
    ("shirt-dress", include_str!("../data/designs/shirt-dress.yaml")),
    ("jumpsuit", include_str!("../data/designs/jumpsuit.yaml")),
    ("birch-dress", include_str!("../data/designs/birch-dress.yaml")),
    ("pleated-skirt", include_str!("../data/designs/pleated-skirt.yaml")),
    ("pocket-shirt", include_str!("../data/designs/pocket-shirt.yaml")),
];

/// The design built when none is given.
pub const DEFAULT_DESIGN: &str = "t-shirt";

/// A built-in design by name.
pub fn design(name: &str) -> Option<Design> {
    DESIGNS.iter().find(|(n, _)| *n == name).map(|(n, text)| {
        read_design(text, &format!("<built-in design {n}>"), &crate::design::extended_design_space()).expect("built-in designs are valid")
    })
}
