use garmentcode::Params;

#[derive(Clone, Params)]
struct Hem(f64);

fn main() {}
