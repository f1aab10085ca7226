use garmentcode::Params;

#[derive(Clone, Params)]
struct Godet {
    #[param(options = [4, 6, 8, 10, 12], default = 5)]
    num_inserts: i64,
}

fn main() {}
