use garmentcode::Params;

#[derive(Clone, Params)]
struct Waistband {
    #[param(range = 1.0..=2.0, default = 1.0, prob = 1.7)]
    waist: f64,
}

fn main() {}
