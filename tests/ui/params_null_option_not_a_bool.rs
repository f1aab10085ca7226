use garmentcode::Params;

#[derive(Clone, Copy, garmentcode::Choice)]
enum Cut {
    Sun,
}

#[derive(Clone, Params)]
struct Pencil {
    #[param(default = None, null_option = "no")]
    cut: Option<Cut>,
}

fn main() {}
