use garmentcode::Params;

const MAX: i64 = 12;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = 4..=MAX, default = 4)]
    panels: i64,
}

fn main() {}
