use garmentcode::Params;

#[derive(Clone, Params)]
struct Shirt {
    #[param(default = 1)]
    strapless: bool,
}

fn main() {}
