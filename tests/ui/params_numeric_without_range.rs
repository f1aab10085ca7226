use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(default = 0.5)]
    length: f64,
}

fn main() {}
