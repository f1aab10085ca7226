use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(options = [4, 6.5], default = 4)]
    panels: i64,
}

fn main() {}
