use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = 4..=12, options = [4, 6], default = 4)]
    panels: i64,
}

fn main() {}
