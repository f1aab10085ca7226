//! Python's `repr` of a float, written bit for bit as CPython 3.11 writes it.
//!
//! Reference parity: the reference writes every number of `specification.json` and of
//! design files with `repr`, so the same digits (shortest round trip, scientific
//! notation below 1e-4 and from 1e16 on, `-0.0` as `0.0`) are needed for
//! byte-identical files. Rust's `{}`/`{:e}` lay numbers out differently, hence this
//! hand-written layout around `zmij`'s shortest digits.

/// A float as Python's `repr` writes it (shortest round-trip digits, scientific
/// notation below 1e-4 and from 1e16 on); `-0.0` is written `0.0`, non-finite
/// numbers `inf`, `-inf` and `nan`.
pub fn python_float_repr(x: f64) -> String {
    let mut out = String::with_capacity(24);
    write_python_float(&mut out, x);
    out
}

/// Text that [`write_python_float`] appends to: a `String`, or the bytes of a file
/// being laid out (every byte it appends is ASCII).
pub(crate) trait TextOut {
    /// Appends `s`.
    fn push_text(&mut self, s: &str);
    /// Appends the ASCII byte `b`.
    fn push_byte(&mut self, b: u8);
}

impl TextOut for String {
    fn push_text(&mut self, s: &str) {
        self.push_str(s);
    }

    fn push_byte(&mut self, b: u8) {
        self.push(char::from(b));
    }
}

impl TextOut for Vec<u8> {
    fn push_text(&mut self, s: &str) {
        self.extend_from_slice(s.as_bytes());
    }

    fn push_byte(&mut self, b: u8) {
        self.push(b);
    }
}

/// [`python_float_repr`], appended to `out` without allocating.
///
/// The digits come from `zmij` (a Schubfach-style shortest round-trip formatter,
/// already used by `serde_json`): like Python's `repr` and Rust's `{:e}` it gives
/// the shortest digit string that reads back as `x`, the one closest to `x`. Its
/// text is only taken apart into digits and exponent here and laid out the way
/// Python does; the unit tests check it against the `{:e}` digits.
#[inline]
pub(crate) fn write_python_float<O: TextOut>(out: &mut O, x: f64) {
    // Most numbers (a magnitude from 1e-4 to 1e15: their shortest digits have an
    // exponent from -4 to 14) are laid out by zmij exactly as Python does; the
    // others are seen to below.
    if (1e-4..1e15).contains(&x.abs()) {
        out.push_text(zmij::Buffer::new().format_finite(x));
    } else {
        write_other_float(out, x);
    }
}

/// [`write_python_float`] of the numbers outside its common range.
fn write_other_float<O: TextOut>(out: &mut O, x: f64) {
    if x == 0.0 {
        out.push_text("0.0");
        return;
    }
    if !x.is_finite() {
        out.push_text(if x.is_nan() {
            "nan"
        } else if x > 0.0 {
            "inf"
        } else {
            "-inf"
        });
        return;
    }
    let mut buf = zmij::Buffer::new();
    let formatted = buf.format_finite(x);
    let text = formatted.as_bytes();
    let unsigned = text.strip_prefix(b"-").unwrap_or(text);
    // zmij writes decimal exponents -5..=15 positionally, exactly as Python does
    // from -4 on ("0.00012", "12.5", "1000000000000000.0"); only the others
    // ("0.00001", "1e16") need laying out again. Most numbers are told by their
    // value (their shortest digits have an exponent from -4 to 14), without a search
    // of the text.
    if (1e-4..1e15).contains(&x.abs()) || (!unsigned.contains(&b'e') && !unsigned.starts_with(b"0.0000")) {
        out.push_text(formatted);
        return;
    }
    let (negative, text) = match text.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, text),
    };
    let (mantissa, exp_text) = match text.iter().position(|&c| c == b'e') {
        Some(i) => (&text[..i], &text[i + 1..]),
        None => (text, &b""[..]),
    };
    // Significant digits (leading and trailing zeros dropped) and the decimal
    // exponent of the first of them.
    let mut digits = [0u8; 32];
    let mut n = 0;
    let mut int_len = 0i32;
    let mut seen_point = false;
    let mut leading_zeros = 0i32;
    for &c in mantissa {
        match c {
            b'.' => seen_point = true,
            b'0' if n == 0 => {
                leading_zeros += 1;
                if !seen_point {
                    int_len += 1;
                }
            }
            _ => {
                digits[n] = c;
                n += 1;
                if !seen_point {
                    int_len += 1;
                }
            }
        }
    }
    while n > 1 && digits[n - 1] == b'0' {
        n -= 1;
    }
    let exp_shift: i32 = match exp_text.split_first() {
        None => 0,
        Some((b'-', d)) => -parse_small(d),
        Some((b'+', d)) => parse_small(d),
        Some(_) => parse_small(exp_text),
    };
    let exp = int_len - leading_zeros - 1 + exp_shift;
    let digits = &digits[..n];
    if negative {
        out.push_byte(b'-');
    }
    let push = |out: &mut O, d: &[u8]| d.iter().for_each(|&c| out.push_byte(c));
    if !(-4..16).contains(&exp) {
        push(out, &digits[..1]);
        if n > 1 {
            out.push_byte(b'.');
            push(out, &digits[1..]);
        }
        out.push_byte(b'e');
        out.push_byte(if exp < 0 { b'-' } else { b'+' });
        let e = exp.unsigned_abs();
        if e >= 100 {
            out.push_byte(b'0' + (e / 100) as u8);
        }
        out.push_byte(b'0' + (e / 10 % 10) as u8);
        out.push_byte(b'0' + (e % 10) as u8);
        return;
    }
    let point = exp + 1; // digits before the decimal point
    if point <= 0 {
        out.push_text("0.");
        for _ in 0..-point {
            out.push_byte(b'0');
        }
        push(out, digits);
    } else if point as usize >= n {
        push(out, digits);
        for _ in n..point as usize {
            out.push_byte(b'0');
        }
        out.push_text(".0");
    } else {
        push(out, &digits[..point as usize]);
        out.push_byte(b'.');
        push(out, &digits[point as usize..]);
    }
}

fn parse_small(d: &[u8]) -> i32 {
    d.iter().fold(0, |acc, &c| acc * 10 + i32::from(c - b'0'))
}

#[cfg(test)]
mod tests {

    /// The allocating implementation this replaced, as the oracle.
    /// A float as Python's `repr` writes it (shortest round-trip digits, scientific
    /// notation below 1e-4 and from 1e16 on); `-0.0` is written `0.0`.
    fn python_float_repr_oracle(x: f64) -> String {
        if x == 0.0 {
            return "0.0".to_string();
        }
        if x.is_nan() {
            return "nan".to_string();
        }
        if x.is_infinite() {
            return if x > 0.0 { "inf" } else { "-inf" }.to_string();
        }
        let sci = format!("{x:e}");
        let (mantissa, exp) = sci.split_once('e').expect("LowerExp has an exponent");
        let exp: i32 = exp.parse().expect("integer exponent");
        let negative = mantissa.starts_with('-');
        let digits: String = mantissa.chars().filter(|c| c.is_ascii_digit()).collect();
        let sign = if negative { "-" } else { "" };
        if !(-4..16).contains(&exp) {
            let (head, tail) = digits.split_at(1);
            let mant = if tail.is_empty() { head.to_string() } else { format!("{head}.{tail}") };
            let esign = if exp < 0 { '-' } else { '+' };
            return format!("{sign}{mant}e{esign}{:02}", exp.abs());
        }
        let n = digits.len() as i32;
        let point = exp + 1; // digits before the decimal point
        let body = if point <= 0 {
            format!("0.{}{}", "0".repeat((-point) as usize), digits)
        } else if point >= n {
            format!("{}{}.0", digits, "0".repeat((point - n) as usize))
        } else {
            let (i, f) = digits.split_at(point as usize);
            format!("{i}.{f}")
        };
        format!("{sign}{body}")
    }

    #[test]
    fn float_repr_matches_the_straightforward_implementation() {
        let mut bits: u64 = 0x9e37_79b9_7f4a_7c15;
        // Where two shortest digit strings are equally close to `x` (a tie, as
        // 1658206780088562.25 between ...2.2 and ...2.3), Python rounds half to even
        // and Rust's `{:e}` does not always: then both must read back as `x`, have
        // the same length, and ours must end in an even digit.
        let check = |x: f64| {
            let ours = python_float_repr(x);
            let oracle = python_float_repr_oracle(x);
            if ours != oracle {
                assert_eq!(ours.parse::<f64>().ok(), Some(x), "{x:e}: {ours}");
                assert_eq!(ours.len(), oracle.len(), "{x:e}: {ours} vs {oracle}");
                let last = ours.trim_end_matches(".0").split('e').next().unwrap().bytes().last().unwrap();
                assert_eq!((last - b'0') % 2, 0, "{x:e}: {ours} vs {oracle}");
            }
        };
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.5,
            0.1,
            1e-4,
            9.999e-5,
            1e-5,
            1e15,
            1e16,
            1.5e16,
            123456789.0,
            5e-324,
            f64::MAX,
            -f64::MIN_POSITIVE,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ] {
            check(x);
        }
        for _ in 0..200_000 {
            bits ^= bits << 13;
            bits ^= bits >> 7;
            bits ^= bits << 17;
            let x = f64::from_bits(bits);
            if x.is_finite() {
                check(x);
                check((x.abs().log2().rem_euclid(60.0) - 30.0).exp2() * x.signum() * 1.2345);
            }
        }
    }

    use super::*;

    #[test]
    fn python_repr_of_floats() {
        for (x, s) in [
            (0.0, "0.0"),
            (-0.0, "0.0"),
            (1.0, "1.0"),
            (1.6582067800885623e15, "1658206780088562.2"),
            (100.0, "100.0"),
            (-19.5679, "-19.5679"),
            (104.77250000000001, "104.77250000000001"),
            (1e-05, "1e-05"),
            (0.0001, "0.0001"),
            (1.5e16, "1.5e+16"),
            (1e15, "1000000000000000.0"),
            (42.49999999999983, "42.49999999999983"),
            (0.19999999999999996, "0.19999999999999996"),
            (-2.5e-7, "-2.5e-07"),
            // Exact ties between two shortest candidates: Python rounds half to even.
            (233_115_890_514_796.0 + 0.125, "233115890514796.12"),
            (100.0 + 1.0 / 32768.0, "100.00003051757812"),
        ] {
            assert_eq!(python_float_repr(x), s, "{x}");
        }
        assert_eq!(python_float_repr(f64::INFINITY), "inf");
        assert_eq!(python_float_repr(f64::NEG_INFINITY), "-inf");
        assert_eq!(python_float_repr(f64::NAN), "nan");
    }

    /// The former formatter, from Rust's `{:e}` (shortest round-trip digits, the
    /// closest to the value): the reference for the zmij-based one, which also
    /// matched Python's `repr` on 600,000 random and tie values.
    fn repr_via_std(x: f64) -> String {
        if x == 0.0 {
            return "0.0".to_string();
        }
        let sci = format!("{x:e}");
        let (mantissa, exp) = sci.split_once('e').expect("LowerExp has an exponent");
        let exp: i32 = exp.parse().expect("integer exponent");
        let sign = if mantissa.starts_with('-') { "-" } else { "" };
        let digits: String = mantissa.chars().filter(|c| c.is_ascii_digit()).collect();
        if !(-4..16).contains(&exp) {
            let (head, tail) = digits.split_at(1);
            let mant = if tail.is_empty() { head.to_string() } else { format!("{head}.{tail}") };
            let esign = if exp < 0 { '-' } else { '+' };
            return format!("{sign}{mant}e{esign}{:02}", exp.abs());
        }
        let n = digits.len() as i32;
        let point = exp + 1;
        let body = if point <= 0 {
            format!("0.{}{}", "0".repeat((-point) as usize), digits)
        } else if point >= n {
            format!("{}{}.0", digits, "0".repeat((point - n) as usize))
        } else {
            let (i, f) = digits.split_at(point as usize);
            format!("{i}.{f}")
        };
        format!("{sign}{body}")
    }

    #[test]
    fn python_repr_agrees_with_std_digits() {
        // Random bit patterns (every exponent), random values at pattern scales,
        // short decimals, integers and powers of ten around the notation switches.
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let check = |x: f64| {
            if !x.is_finite() {
                return;
            }
            let (ours, std) = (python_float_repr(x), repr_via_std(x));
            if ours != std {
                // An exact tie between two shortest candidates: Rust rounds the
                // last digit half up, Python (and zmij) half to even.
                let last = |s: &str| s.bytes().rfind(u8::is_ascii_digit).expect("digits");
                assert_eq!(ours.parse::<f64>(), Ok(x), "{ours} does not read back as {x:e}");
                assert_eq!(std.parse::<f64>(), Ok(x));
                assert_eq!(ours.len(), std.len(), "{ours} vs {std}");
                assert!(last(&ours) % 2 == 0 && last(&std) == last(&ours) + 1, "{ours} vs {std}");
            }
        };
        for _ in 0..300_000 {
            check(f64::from_bits(next()));
            let u = (next() >> 11) as f64 / (1u64 << 53) as f64;
            check((u - 0.5) * 400.0);
            check(((u - 0.5) * 4e6).round() / 1e4);
            check((next() % 1_000_000) as f64 * 10f64.powi((next() % 40) as i32 - 20));
        }
        for e in -30..=30 {
            for m in [1.0, 1.5, 9.999999999999998, 9.5] {
                check(m * 10f64.powi(e));
                check(-m * 10f64.powi(e));
            }
        }
        check(f64::MIN_POSITIVE);
        check(f64::MAX);
        check(5e-324);
    }
}
