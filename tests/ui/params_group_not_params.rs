use garmentcode::Params;

#[derive(Clone)]
struct Cuff {
    len: f64,
}

#[derive(Clone, Params)]
struct Sleeve {
    /// Cuff.
    cuff: Cuff,
}

fn main() {}
