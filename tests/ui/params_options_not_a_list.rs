use garmentcode::Params;

#[derive(Clone, Params)]
struct Godet {
    #[param(options = 4, default = 4)]
    inserts: i64,
}

fn main() {}
