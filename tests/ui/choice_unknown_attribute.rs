use garmentcode::Choice;

#[derive(Clone, Copy, Choice)]
enum Hem {
    #[param(label = "plain")]
    Plain,
}

fn main() {}
