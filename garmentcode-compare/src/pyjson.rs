//! The message Python's `json.load` gives for a malformed document, so that the port's
//! "cannot read" reason names the same error and position (`<msg>: line L column C (char P)`).
//! Only consulted when serde_json has already refused the text; it follows the structure of
//! CPython 3.11's `json.decoder` / `_json.c` scanner and reports its first error.

type Res = Result<usize, (String, usize)>;

const WS: [char; 4] = [' ', '\t', '\n', '\r'];

struct Scanner {
    s: Vec<char>,
}

impl Scanner {
    fn at(&self, i: usize) -> Option<char> {
        self.s.get(i).copied()
    }

    fn skip_ws(&self, mut i: usize) -> usize {
        while self.at(i).is_some_and(|c| WS.contains(&c)) {
            i += 1;
        }
        i
    }

    fn starts(&self, i: usize, lit: &str) -> bool {
        lit.chars().enumerate().all(|(k, c)| self.at(i + k) == Some(c))
    }

    /// `scan_once`: a value starting at i; Err(("Expecting value", i)) when none starts there.
    fn value(&self, i: usize) -> Res {
        let expecting = || Err(("Expecting value".to_string(), i));
        match self.at(i) {
            None => expecting(),
            Some('"') => self.string(i + 1),
            Some('{') => self.object(i + 1),
            Some('[') => self.array(i + 1),
            Some('n') if self.starts(i, "null") => Ok(i + 4),
            Some('t') if self.starts(i, "true") => Ok(i + 4),
            Some('f') if self.starts(i, "false") => Ok(i + 5),
            Some('N') if self.starts(i, "NaN") => Ok(i + 3),
            Some('I') if self.starts(i, "Infinity") => Ok(i + 8),
            Some('-') if self.starts(i, "-Infinity") => Ok(i + 9),
            Some(_) => match self.number(i) {
                Some(end) => Ok(end),
                None => expecting(),
            },
        }
    }

    /// `-?(0|[1-9]\d*)(\.\d+)?([eE][-+]?\d+)?`
    fn number(&self, i: usize) -> Option<usize> {
        let digit = |k: usize| self.at(k).is_some_and(|c| c.is_ascii_digit());
        let mut k = i;
        if self.at(k) == Some('-') {
            k += 1;
        }
        match self.at(k) {
            Some('0') => k += 1,
            Some(c) if c.is_ascii_digit() => {
                while digit(k) {
                    k += 1;
                }
            }
            _ => return None,
        }
        if self.at(k) == Some('.') && digit(k + 1) {
            k += 1;
            while digit(k) {
                k += 1;
            }
        }
        if matches!(self.at(k), Some('e' | 'E')) {
            let mut j = k + 1;
            if matches!(self.at(j), Some('+' | '-')) {
                j += 1;
            }
            if digit(j) {
                while digit(j) {
                    j += 1;
                }
                k = j;
            }
        }
        Some(k)
    }

    /// A string whose opening quote is at begin - 1.
    fn string(&self, begin: usize) -> Res {
        let unterminated = || Err(("Unterminated string starting at".to_string(), begin - 1));
        let mut i = begin;
        loop {
            match self.at(i) {
                None => return unterminated(),
                Some('"') => return Ok(i + 1),
                Some('\\') => {
                    let Some(c) = self.at(i + 1) else { return unterminated() };
                    if c == 'u' {
                        let hex = (0..4).all(|k| self.at(i + 2 + k).is_some_and(|h| h.is_ascii_hexdigit()));
                        if i + 6 >= self.s.len() || !hex {
                            return Err(("Invalid \\uXXXX escape".to_string(), i + 1));
                        }
                        i += 6;
                    } else if "\"\\/bfnrt".contains(c) {
                        i += 2;
                    } else {
                        return Err(("Invalid \\escape".to_string(), i));
                    }
                }
                Some(c) if (c as u32) < 0x20 => return Err(("Invalid control character at".to_string(), i)),
                Some(_) => i += 1,
            }
        }
    }

    fn object(&self, mut end: usize) -> Res {
        let mut next = self.at(end);
        if next != Some('"') {
            end = self.skip_ws(end);
            next = self.at(end);
            if next == Some('}') {
                return Ok(end + 1);
            }
            if next != Some('"') {
                return Err(("Expecting property name enclosed in double quotes".into(), end));
            }
        }
        end += 1;
        loop {
            end = self.string(end)?;
            if self.at(end) != Some(':') {
                end = self.skip_ws(end);
                if self.at(end) != Some(':') {
                    return Err(("Expecting ':' delimiter".into(), end));
                }
            }
            end = self.skip_ws(end + 1);
            end = self.value(end)?;
            end = self.skip_ws(end);
            let c = self.at(end);
            end += 1;
            if c == Some('}') {
                return Ok(end);
            }
            if c != Some(',') {
                return Err(("Expecting ',' delimiter".into(), end - 1));
            }
            end = self.skip_ws(end);
            let c = self.at(end);
            end += 1;
            if c != Some('"') {
                return Err(("Expecting property name enclosed in double quotes".into(), end - 1));
            }
        }
    }

    fn array(&self, mut end: usize) -> Res {
        end = self.skip_ws(end);
        if self.at(end) == Some(']') {
            return Ok(end + 1);
        }
        loop {
            end = self.value(end)?;
            end = self.skip_ws(end);
            let c = self.at(end);
            end += 1;
            if c == Some(']') {
                return Ok(end);
            }
            if c != Some(',') {
                return Err(("Expecting ',' delimiter".into(), end - 1));
            }
            end = self.skip_ws(end);
        }
    }
}

/// Python's `JSONDecodeError` text for `text`, or None if Python would accept it.
pub fn decode_error(text: &str) -> Option<String> {
    let sc = Scanner { s: text.chars().collect() };
    let err = if text.starts_with('\u{feff}') {
        Some(("Unexpected UTF-8 BOM (decode using utf-8-sig)".to_string(), 0))
    } else {
        match sc.value(sc.skip_ws(0)) {
            Err(e) => Some(e),
            Ok(end) => {
                let end = sc.skip_ws(end);
                (end != sc.s.len()).then(|| ("Extra data".to_string(), end))
            }
        }
    };
    let (msg, pos) = err?;
    let before = &sc.s[..pos.min(sc.s.len())];
    let line = before.iter().filter(|&&c| c == '\n').count() + 1;
    let col = match before.iter().rposition(|&c| c == '\n') {
        Some(nl) => pos - nl,
        None => pos + 1,
    };
    Some(format!("{msg}: line {line} column {col} (char {pos})"))
}

#[cfg(test)]
mod tests {
    use super::decode_error;

    #[test]
    fn messages() {
        assert_eq!(decode_error("{\"pattern\": {\"panels\": ").unwrap(), "Expecting value: line 1 column 24 (char 23)");
        assert_eq!(decode_error("[1, 2] x").unwrap(), "Extra data: line 1 column 8 (char 7)");
        assert_eq!(decode_error("{\"a\" 1}").unwrap(), "Expecting ':' delimiter: line 1 column 6 (char 5)");
        assert_eq!(decode_error("[1 2]").unwrap(), "Expecting ',' delimiter: line 1 column 4 (char 3)");
        assert_eq!(decode_error("{\n \"a\": \"x").unwrap(), "Unterminated string starting at: line 2 column 7 (char 8)");
        assert!(decode_error("[NaN, -Infinity, 1e5]").is_none());
    }
}
