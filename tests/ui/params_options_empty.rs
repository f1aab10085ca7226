use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(options = [], default = 4)]
    panels: i64,
}

fn main() {}
