//! How error messages show a user's values: short, whatever the input. A 10 MB
//! string or a number like `1e308` in a file must not make a message of the same
//! size, so messages quote text through [`quote`] and numbers through [`short`].

/// Longest text an error message quotes whole; longer text is cut to its start.
pub const QUOTE_CHARS: usize = 40;

/// A user's text as an error message quotes it: whole, in quotes, when short;
/// else its first [`QUOTE_CHARS`] characters and its length, so that a huge value
/// never makes a huge message.
///
/// ```
/// use garmentcode::message::quote;
/// assert_eq!(quote("waist"), "\"waist\"");
/// assert_eq!(quote(&"x".repeat(1_000_000)), format!("\"{}...\" (1000000 characters)", "x".repeat(40)));
/// ```
pub fn quote(text: &str) -> String {
    match text.char_indices().nth(QUOTE_CHARS) {
        None => format!("\"{text}\""),
        Some((cut, _)) => format!("\"{}...\" ({} characters)", &text[..cut], text.chars().count()),
    }
}

/// A name as an error message shows it: in backticks when short, else cut as
/// [`quote`] cuts it.
///
/// ```
/// use garmentcode::message::quote_name;
/// assert_eq!(quote_name("mean_femal"), "`mean_femal`");
/// assert!(quote_name(&"n".repeat(5000)).ends_with("(5000 characters)"));
/// ```
pub fn quote_name(name: &str) -> String {
    if name.chars().count() > QUOTE_CHARS { quote(name) } else { format!("`{name}`") }
}

/// A user's number as an error message shows it: at most 6 significant digits,
/// in exponent form when very large or very small (never a 309-digit decimal).
///
/// ```
/// use garmentcode::message::short;
/// assert_eq!(short(1e308).to_string(), "1e308");
/// assert_eq!(short(-2.5e-12).to_string(), "-2.5e-12");
/// assert_eq!(short(88.123456789).to_string(), "88.1235");
/// assert_eq!(short(175.0).to_string(), "175");
/// assert_eq!(short(f64::NAN).to_string(), "NaN");
/// ```
pub fn short(x: f64) -> Short {
    Short(x)
}

/// A number shown short: see [`short`].
#[derive(Clone, Copy, Debug)]
pub struct Short(pub f64);

impl std::fmt::Display for Short {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let x = self.0;
        if !x.is_finite() || x == 0.0 {
            return write!(f, "{x}");
        }
        let magnitude = x.abs();
        if !(1e-4..1e6).contains(&magnitude) {
            // Exponent form with up to 6 significant digits, trailing zeros dropped.
            let s = format!("{x:.5e}");
            let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
            let mantissa = if mantissa.contains('.') { mantissa.trim_end_matches('0').trim_end_matches('.') } else { mantissa };
            return write!(f, "{mantissa}e{exp}");
        }
        let decimals = (5 - magnitude.log10().floor() as i32).clamp(0, 9) as usize;
        let s = format!("{x:.decimals$}");
        let s = if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.') } else { &s };
        f.write_str(s)
    }
}
