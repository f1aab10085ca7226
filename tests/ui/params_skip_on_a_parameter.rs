use garmentcode::Params;

#[derive(Clone, Params)]
struct Cuff {
    /// Cuff length.
    #[param(range = 0.05..=0.9, default = 0.1, skip)]
    cuff_len: f64,
}

fn main() {}
