use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    #[param(range = 0.1..=0.9, prob = 0.5)]
    length: f64,
}

fn main() {}
