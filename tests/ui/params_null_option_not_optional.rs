use garmentcode::Params;

#[derive(Clone, Params)]
struct Shirt {
    #[param(default = false, null_option = false)]
    strapless: bool,
}

fn main() {}
