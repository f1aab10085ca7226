use garmentcode::Params;

#[derive(Clone, Params)]
struct Cuff {
    /// Cuff length.
    #[param(range = 0.05..=0.9, default = 0.1, prob = 0.7)]
    cuff_len: f64,
}

#[derive(Clone, Params)]
struct Sleeve {
    /// Cuff.
    #[param(skip, cuff_len(default = 0.2))]
    cuff: Cuff,
}

fn main() {}
