//! Error messages: position and wording for typical mistakes and for every
//! unsupported feature.

use garmentcode::parity::yaml::{Value, parse};

/// (input, line, column, expected part of the message)
const CASES: &[(&str, u32, u32, &str)] = &[
    // Typical mistakes in hand-written files.
    ("a:\n  v: 1\n  range\n", 3, 8, "expected ':' after mapping key \"range\""),
    ("a:\n  v: 1\n  range [1, 2]\n  type: float\n", 3, 15, "expected ':' after mapping key \"range [1, 2]\""),
    ("a:\n  range [1, 2]\n  type: float\n", 3, 7, "continues the plain value \"range [1, 2]\" started at line 2, column 3"),
    ("a: 1\nkey:value\n", 2, 10, "(a ':' only separates key and value when followed by a space)"),
    (
        "design:\n  meta:\n    upper:\n      v: null\n     range: [a]\n",
        5,
        6,
        "bad indentation: mapping key \"range\" is at column 6, expected column 5",
    ),
    ("a:\n  b: 1\n c: 2\n", 3, 2, "bad indentation: mapping key \"c\""),
    ("a: 1\n  b: 2\n", 2, 4, "continues the plain value \"1\" started at line 1, column 4"),
    ("a:\n  range: [1, 2\n  type: float\n", 3, 7, "inside the '[' opened at line 2, column 10; is the closing ']' missing?"),
    ("a: b: c\n", 1, 5, "mapping values are not allowed here"),
    ("a:\tb\n", 1, 3, "tab character"),
    ("a: 1\t\n", 1, 5, "tab character"),
    ("a: 1\na: 2\n", 2, 1, "duplicate mapping key \"a\" (first defined on line 1, column 1)"),
    ("a: {b: 1, b: 2}\n", 1, 11, "duplicate mapping key \"b\""),
    ("1: x\n1.0: y\n", 2, 1, "duplicate mapping key 1.0"),
    ("a: 'unterminated\n", 1, 4, "unterminated single-quoted string"),
    ("a: \"unterminated\n", 1, 4, "unterminated double-quoted string"),
    ("a: \"bad \\q escape\"\n", 1, 10, "unknown escape '\\q'"),
    ("a: \"\\x4\"\n", 1, 8, "expected 2 hexadecimal digits after '\\x'"),
    ("- a\nb\n", 2, 2, "expected a sequence entry ('- ') at this indentation, found \"b\""),
    ("a: 1\n- b\n", 2, 1, "a mapping cannot also contain sequence entries"),
    ("- a\nb: 1\n", 2, 1, "inside a sequence every line at this column must start with '- '"),
    ("a: [1, 2]]\n", 1, 10, "unexpected ']' without a matching '['"),
    ("{a: 1\n", 1, 1, "unclosed '{'"),
    ("a: [1, 2\n", 1, 4, "unclosed '['"),
    ("a: @x\n", 1, 4, "'@' is reserved"),
    ("[a, b]: 1\n", 1, 1, "a sequence cannot be a mapping key"),
    ("a: 1\n...\nb\n", 3, 1, "after the document end marker '...'"),
    ("\u{7}", 1, 1, "special character U+0007"),
    ("a: x\u{0}\n", 1, 5, "special character U+0000"),
    ("a: x\u{2028}y\n", 1, 5, "Unicode line break U+2028 is not supported"),
    ("a: -\n", 1, 4, "sequence entry ('- ') is not allowed here"),
    ("a: 1\n\"a\": 2\n", 2, 1, "duplicate mapping key \"a\""),
    // Unsupported features: named, with their position.
    ("a: &x 1\n", 1, 4, "anchors ('&name') are not supported"),
    ("a: *x\n", 1, 4, "aliases ('*name') are not supported"),
    ("a: !!int 1\n", 1, 4, "tags ('!tag', '!!type') are not supported"),
    ("a: |\n  text\n", 1, 4, "block scalars ('|') are not supported"),
    ("a: >\n  text\n", 1, 4, "block scalars ('>') are not supported"),
    ("? a\n: b\n", 1, 1, "explicit mapping keys ('? key') are not supported"),
    ("a: 1\n---\nb: 2\n", 2, 1, "a second document ('---') is not supported"),
    ("%YAML 1.1\n---\na: 1\n", 1, 1, "directives ('%YAML', '%TAG') are not supported"),
    ("a: 2001-12-14\n", 1, 4, "timestamps are not supported"),
    ("a: 99999999999999999999\n", 1, 4, "out of the supported range"),
    ("<<: {a: 1}\n", 1, 1, "merge keys ('<<') are not supported"),
    ("a: \"\\ud800\"\n", 1, 7, "not a valid Unicode character"),
];

#[test]
fn error_messages() {
    let mut failures = Vec::new();
    for &(input, line, col, part) in CASES {
        match parse(input) {
            Ok(n) => failures.push(format!("{:?}: expected an error, got {:?}", input, n.value)),
            Err(e) => {
                if e.line != line || e.col != col || !e.message.contains(part) {
                    failures.push(format!("{:?}:\n  got      {}\n  expected line {}, column {}: ...{}...", input, e, line, col, part));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{} wrong messages:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn display_format() {
    let e = parse("a:\n  v: 1\n  range\n").unwrap_err();
    assert_eq!(e.to_string(), "line 3, column 8: expected ':' after mapping key \"range\"");
    let as_dyn: &dyn std::error::Error = &e;
    assert!(as_dyn.to_string().starts_with("line 3"));
}

#[test]
fn accepted_oddities_match_pyyaml() {
    // Things PyYAML accepts that look like mistakes; we must read them the same.
    let v = |s: &str| parse(s).unwrap().value;
    let s = |x: &str| Value::Str(x.to_string());
    // A deeper-indented line continues a plain value.
    assert_eq!(v("a:\n- 1\n - 2\n").as_map_first(), Value::Seq(vec![s("1 - 2").into()]));
    // `#` without a space before it is part of the value; a quoted scalar may be followed by `#`.
    assert_eq!(v("a: b#c").as_map_first(), s("b#c"));
    assert_eq!(v("a: 'b'#c").as_map_first(), s("b"));
    // Empty values, `~`, flow mappings without values.
    assert_eq!(v("a:").as_map_first(), Value::Null);
    assert_eq!(v("a: {b, c: }").as_map_first(), Value::Map(vec![(s("b").into(), Value::Null.into()), (s("c").into(), Value::Null.into())]));
    // A `=` key is a string (a `=` value is an error).
    assert_eq!(v("=: 1"), Value::Map(vec![(s("=").into(), Value::Int(1).into())]));
    assert!(parse("a: =").is_err());
    // Empty documents.
    assert_eq!(v(""), Value::Null);
    assert_eq!(v("# only a comment\n"), Value::Null);
    assert_eq!(v("---\n"), Value::Null);
    assert_eq!(v("--- 5\n..."), Value::Int(5));
}

trait First {
    fn as_map_first(&self) -> Value;
}
impl First for Value {
    fn as_map_first(&self) -> Value {
        match self {
            Value::Map(p) => p[0].1.value.clone(),
            _ => panic!("not a map: {:?}", self),
        }
    }
}
