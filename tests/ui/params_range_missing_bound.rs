use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = ..=12, default = 4)]
    panels: i64,
}

fn main() {}
