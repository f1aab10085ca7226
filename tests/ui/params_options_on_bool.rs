use garmentcode::Params;

#[derive(Clone, Params)]
struct Shirt {
    #[param(options = [0, 1], default = false)]
    strapless: bool,
}

fn main() {}
