use garmentcode::Params;

#[derive(Clone, Copy)]
enum Hem {
    Plain,
    Rolled,
}

#[derive(Clone, Params)]
struct Skirt {
    /// Hem finish.
    #[param(default = Plain)]
    hem: Hem,
}

fn main() {}
