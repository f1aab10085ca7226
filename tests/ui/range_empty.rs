use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = 4..=4, default = 4)]
    panels: i64,
}

fn main() {}
