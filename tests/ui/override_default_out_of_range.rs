use garmentcode::Params;

#[derive(Clone, Params)]
struct Cuff {
    /// Cuff length.
    #[param(range = 0.05..=0.9, default = 0.1, prob = 0.7)]
    cuff_len: f64,
    /// Number of buttons.
    #[param(range = 0..=4, default = 1)]
    buttons: i64,
    /// Buttoned.
    #[param(default = false)]
    closed: bool,
}

#[derive(Clone, Params)]
struct Sleeve {
    /// Length.
    #[param(range = 0.1..=1.15, default = 0.3)]
    length: f64,
    /// Cuff.
    cuff: Cuff,
}

#[derive(Clone, Params)]
struct Left {
    #[param(cuff(cuff_len(default = 1.5)))]
    sleeve: Sleeve,
}

fn main() {}
