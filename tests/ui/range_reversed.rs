use garmentcode::Params;

#[derive(Clone, Params)]
struct Skirt {
    /// Length.
    #[param(range = 0.9..=0.2, default = 0.5)]
    length: f64,
}

fn main() {}
