//! Values from the user as error messages show them: short, whatever their size.
//!
//! A message that names a bad value should not repeat it whole: a 1 MB name would
//! make a 1 MB message (twice, in a JSON error with its list of problems), and a
//! number such as `1e308` printed with `{}` has 309 digits. These helpers keep the
//! first [`MAX_CHARS`] characters of a text and give its length, escape control
//! characters (a message is one line), and write very large or small numbers with
//! an exponent.
//!
//! ```
//! use garmentcode::shown;
//!
//! assert_eq!(shown::quoted("Shirt"), "\"Shirt\"");
//! let long = "x".repeat(1_000_000);
//! assert_eq!(shown::quoted(&long), format!("\"{}...\" (1000000 characters)", "x".repeat(40)));
//! assert_eq!(shown::text("design.shirt.length"), "design.shirt.length");
//! assert_eq!(shown::number(-3.0), "-3");
//! assert_eq!(shown::number(1e308), "1e308");
//! ```

/// Characters of a text a message shows; a longer text is cut there, with its length.
pub const MAX_CHARS: usize = 40;

/// Longest number written without an exponent, in characters.
const MAX_PLAIN_NUMBER: usize = 20;

/// A text in double quotes (quotes, backslashes and control characters escaped);
/// beyond [`MAX_CHARS`] characters, its beginning, `...` and its length in
/// characters: `"abc..." (1048576 characters)`.
pub fn quoted(s: &str) -> String {
    shorten(s, true)
}

/// A text as it is (a key, a path, a name inside a message), control characters
/// escaped; beyond [`MAX_CHARS`] characters, its beginning, `...` and its length.
pub fn text(s: &str) -> String {
    shorten(s, false)
}

/// A number as `{}` writes it (`70`, `0.606592`), unless that takes more than 20
/// characters: then with an exponent (`1e308`, `1.2345678901234568e20`).
pub fn number(x: f64) -> String {
    let plain = x.to_string();
    if plain.len() <= MAX_PLAIN_NUMBER { plain } else { format!("{x:e}") }
}

fn shorten(s: &str, quote: bool) -> String {
    let mut out = String::with_capacity(s.len().min(MAX_CHARS * 2) + 24);
    if quote {
        out.push('"');
    }
    let mut chars = s.chars();
    for c in chars.by_ref().take(MAX_CHARS) {
        match c {
            '"' if quote => out.push_str("\\\""),
            '\\' if quote => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => out.push_str(&format!("\\x{:02X}", c as u32)),
            c => out.push(c),
        }
    }
    let cut = chars.next().is_some();
    if cut {
        out.push_str("...");
    }
    if quote {
        out.push('"');
    }
    if cut {
        out.push_str(&format!(" ({} characters)", s.chars().count()));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_texts_are_shown_whole_and_escaped() {
        assert_eq!(quoted(""), "\"\"");
        assert_eq!(quoted("a \"b\" \\ c\nd\te\u{1}"), "\"a \\\"b\\\" \\\\ c\\nd\\te\\x01\"");
        assert_eq!(text("a \"b\"\n"), "a \"b\"\\n");
        let exactly = "é".repeat(MAX_CHARS);
        assert_eq!(quoted(&exactly), format!("\"{exactly}\""), "at the limit: whole");
    }

    #[test]
    fn long_texts_are_cut_with_their_length() {
        let s = "é".repeat(MAX_CHARS + 1);
        assert_eq!(quoted(&s), format!("\"{}...\" (41 characters)", "é".repeat(MAX_CHARS)));
        assert_eq!(text(&s), format!("{}... (41 characters)", "é".repeat(MAX_CHARS)));
        let huge = "a\n".repeat(1 << 20);
        assert!(quoted(&huge).len() < 120 && text(&huge).len() < 120);
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(number(70.0), "70");
        assert_eq!(number(0.606592), "0.606592");
        assert_eq!(number(-1e308), "-1e308");
        assert_eq!(number(f64::MIN_POSITIVE), "2.2250738585072014e-308");
        assert_eq!(number(f64::MAX), "1.7976931348623157e308");
        assert_eq!(number(f64::INFINITY), "inf");
        assert_eq!(number(f64::NAN), "NaN");
        assert_eq!(number(0.1 + 0.2), "0.30000000000000004");
    }
}
