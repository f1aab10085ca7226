use garmentcode::Choice;

#[derive(Clone, Copy, Choice)]
enum Hem {}

fn main() {}
