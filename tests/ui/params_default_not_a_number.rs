use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = 0.1..=0.9, default = "long")]
    length: f64,
}

fn main() {}
