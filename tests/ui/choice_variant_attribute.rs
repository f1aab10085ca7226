use garmentcode::Choice;

#[derive(Clone, Copy, Choice)]
enum Hem {
    #[param(default = true)]
    Plain,
    Rolled,
}

fn main() {}
