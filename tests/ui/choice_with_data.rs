use garmentcode::Choice;

#[derive(Clone, Copy, Choice)]
enum Cuff {
    Band(u32),
    Skirt,
}

fn main() {}
