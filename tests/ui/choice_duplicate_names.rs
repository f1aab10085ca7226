use garmentcode::Choice;

#[derive(Clone, Copy, Choice)]
enum Hem {
    Plain,
    #[param(rename = "Plain")]
    Rolled,
}

fn main() {}
