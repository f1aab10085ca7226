use garmentcode::Params;

#[derive(Clone, Params)]
struct Sleeve {
    #[param(range = 0.1..=1.15, default = 1.5)]
    length: f64,
}

fn main() {}
