use garmentcode::Params;

#[derive(Clone, Params)]
struct Collar {
    #[param(default = 3)]
    name: String,
}

fn main() {}
