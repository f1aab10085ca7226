use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = 0.1..=0.9, default = 0.5, cut(default = 1.0))]
    length: f64,
}

fn main() {}
