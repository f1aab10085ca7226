use garmentcode::Params;

#[derive(Clone, Params)]
enum Hem {
    Plain,
    Rolled,
}

fn main() {}
