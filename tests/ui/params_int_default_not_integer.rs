use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = 4..=12, default = 4.5)]
    panels: i64,
}

fn main() {}
