use garmentcode::Choice;

#[derive(Clone, Copy, Choice)]
struct Hem {
    plain: bool,
}

fn main() {}
