#[derive(Clone, Copy)]
enum Hem {
    Plain,
}

fn names<C: garmentcode::Choice>() -> &'static [&'static str] {
    C::NAMES
}

fn demo() -> &'static [&'static str] {
    names::<Hem>()
}

fn main() {
    let _ = demo;
}
