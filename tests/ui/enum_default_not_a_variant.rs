use garmentcode::{Choice, Params};

#[derive(Clone, Copy, Choice)]
enum Upper {
    Shirt,
    FittedShirt,
}

#[derive(Clone, Params)]
struct Meta {
    #[param(default = Blouse)]
    upper: Upper,
}

fn main() {}
