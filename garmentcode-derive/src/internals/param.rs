//! The model of a `#[derive(Params)]` struct and of a `#[derive(Choice)]` enum.

use super::{Errors, doc_comment, number};
use proc_macro2::Span;
use syn::ext::IdentExt;
use syn::spanned::Spanned;
use syn::{Data, DeriveInput, Expr, Fields, GenericArgument, Ident, LitStr, PathArguments, RangeLimits, Type};

/// What Rust type a leaf parameter has.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum LeafType {
    /// `f64`
    Float,
    /// `i64`
    Int,
    /// `bool`
    Bool,
    /// An enum deriving `Choice` (or another `ParamValue` type).
    Other,
    /// `Option<Enum>`
    OptionalOther,
}

/// A leaf parameter.
pub struct Leaf {
    /// The field.
    pub ident: Ident,
    /// The field's type.
    pub ty: Type,
    /// Rust type class.
    pub leaf_type: LeafType,
    /// Name in design files.
    pub name: String,
    /// Span for errors about the name.
    pub name_span: Span,
    /// `range = lo..=hi`.
    pub range: Option<(f64, f64)>,
    /// `options = [..]` (numbers).
    pub options: Option<Vec<f64>>,
    /// `default = ..`.
    pub default: Expr,
    /// `prob = ..`.
    pub prob: Option<f64>,
    /// Doc comment.
    pub description: String,
    /// `null_option = false`: leave null out of the written options of an
    /// optional parameter (it stays a valid value, as in the reference).
    pub null_option: bool,
}

/// A nested group.
pub struct Group {
    /// The field.
    pub ident: Ident,
    /// Group type.
    pub ty: Type,
    /// Name in design files.
    pub name: String,
    /// Per-instance overrides of the group's parameters.
    pub overrides: Vec<Override>,
    /// `#[param(skip)]`: the whole group is left out of the schema (its values stay
    /// reachable by path and at their defaults unless set).
    pub skip: bool,
}

/// `#[param(field(default = .., range = .., prob = .., doc = "..", skip))]` on a nested
/// group field: changes one parameter of this instance of the group.
pub struct Override {
    /// Field path inside the group (`cuff.top_ruffle` is `[cuff, top_ruffle]`).
    pub path: Vec<Ident>,
    /// Span of the last field name.
    pub span: Span,
    /// `default = ..`: a new default (a number, `true`/`false` or an expression of the field's type).
    pub default: Option<Expr>,
    /// `range = lo..=hi`: a new range (numeric parameters).
    pub range: Option<(f64, f64)>,
    /// `prob = p` or `prob = None`: a new sampling probability.
    pub prob: Option<Option<f64>>,
    /// `doc = ".."`: a new description.
    pub doc: Option<LitStr>,
    /// `skip`: leave the parameter (or sub-group) out of this instance's schema.
    pub skip: bool,
}

impl Override {
    /// The field path as written, `a.b`.
    pub fn dotted(&self) -> String {
        self.path.iter().map(|i| i.unraw().to_string()).collect::<Vec<_>>().join(".")
    }
}

/// A field of a parameter struct.
#[allow(clippy::large_enum_variant)] // built once per field at compile time
pub enum Field {
    /// A parameter.
    Leaf(Box<Leaf>),
    /// A nested group.
    Group(Group),
}

/// A parsed `#[derive(Params)]` struct.
pub struct ParamStruct {
    /// The fields in order.
    pub fields: Vec<Field>,
}

#[derive(Default)]
struct RawAttr {
    range: Option<(Expr, Span)>,
    options: Option<(Vec<Expr>, Span)>,
    default: Option<Expr>,
    prob: Option<(Expr, Span)>,
    rename: Option<LitStr>,
    null_option: Option<(bool, Span)>,
    overrides: Vec<Override>,
    skip: Option<Span>,
    seen: bool,
}

/// Parse `field(...)` of an override list: settings of `path` and nested
/// `sub(...)` overrides below it.
fn parse_override(meta: &syn::meta::ParseNestedMeta, path: Vec<Ident>, out: &mut Vec<Override>, errors: &mut Errors) -> syn::Result<()> {
    let span = meta.path.span();
    let mut o = Override { path: path.clone(), span, default: None, range: None, prob: None, doc: None, skip: false };
    let fork = meta.input.fork();
    let content;
    syn::parenthesized!(content in fork);
    if content.is_empty() {
        return Err(syn::Error::new(span, "empty override: give `default`, `range`, `prob`, `doc`, `skip` or a nested `field(..)`"));
    }
    meta.parse_nested_meta(|inner| {
        let Some(key) = inner.path.get_ident().cloned() else {
            return Err(inner.error("expected a field name or an override key"));
        };
        if inner.input.peek(syn::token::Paren) {
            let mut sub = path.clone();
            sub.push(key);
            return parse_override(&inner, sub, out, errors);
        }
        match key.to_string().as_str() {
            "default" => o.default = Some(inner.value()?.parse()?),
            "range" => {
                let e: Expr = inner.value()?.parse()?;
                o.range = parse_range(&e, errors);
            }
            "prob" => {
                let e: Expr = inner.value()?.parse()?;
                o.prob = match &e {
                    Expr::Path(p) if p.path.is_ident("None") => Some(None),
                    _ => match number(&e) {
                        Some((p, _)) if (0.0..=1.0).contains(&p) => Some(Some(p)),
                        Some((p, _)) => {
                            errors.spanned(&e, format!("probability {p} is outside [0, 1]"));
                            None
                        }
                        None => {
                            errors.spanned(&e, "prob must be a number in [0, 1] or `None`");
                            None
                        }
                    },
                };
            }
            "doc" => o.doc = Some(inner.value()?.parse()?),
            "skip" => o.skip = true,
            other => {
                return Err(
                    inner.error(format!("unknown override `{other}` (expected default, range, prob, doc, skip or a nested `field(..)`)"))
                );
            }
        }
        Ok(())
    })?;
    let set = o.default.is_some() || o.range.is_some() || o.prob.is_some() || o.doc.is_some();
    if o.skip && set {
        errors.at(span, "a skipped parameter takes no other override");
    }
    if let (Some(d), Some((lo, hi))) = (&o.default, o.range)
        && let Some((v, _)) = number(d)
        && (v < lo || v > hi)
    {
        errors.spanned(d, format!("default {v} is outside the range {lo}..={hi}"));
    }
    if o.skip || set {
        out.push(o);
    }
    Ok(())
}

fn parse_param_attr(attrs: &[syn::Attribute], errors: &mut Errors) -> RawAttr {
    let mut raw = RawAttr::default();
    for attr in attrs.iter().filter(|a| a.path().is_ident("param")) {
        raw.seen = true;
        let res = attr.parse_nested_meta(|meta| {
            let key = meta.path.get_ident().map(|i| i.to_string()).unwrap_or_default();
            let span = meta.path.span();
            match key.as_str() {
                "range" => raw.range = Some((meta.value()?.parse()?, span)),
                "default" => raw.default = Some(meta.value()?.parse()?),
                "prob" => raw.prob = Some((meta.value()?.parse()?, span)),
                "rename" => raw.rename = Some(meta.value()?.parse()?),
                "skip" if !meta.input.peek(syn::token::Paren) => raw.skip = Some(span),
                "null_option" => {
                    let b: syn::LitBool = meta.value()?.parse()?;
                    raw.null_option = Some((b.value, span));
                }
                "options" => {
                    let e: Expr = meta.value()?.parse()?;
                    match e {
                        Expr::Array(arr) => raw.options = Some((arr.elems.into_iter().collect(), span)),
                        other => return Err(syn::Error::new(other.span(), "options must be a list: `options = [a, b, c]`")),
                    }
                }
                _ if meta.input.peek(syn::token::Paren) && meta.path.get_ident().is_some() => {
                    let field = meta.path.get_ident().cloned().expect("checked");
                    parse_override(&meta, vec![field], &mut raw.overrides, errors)?;
                }
                _ => {
                    return Err(meta.error(format!(
                        "unknown parameter attribute `{key}` (expected range, options, default, prob, rename, null_option, \
                         or, on a nested group, `skip` or `field(..)` overrides)"
                    )));
                }
            }
            Ok(())
        });
        if let Err(e) = res {
            errors.push(e);
        }
    }
    raw
}

/// Classify a field type, or explain why it cannot be a parameter.
fn classify(ty: &Type) -> Result<LeafType, String> {
    let Type::Path(p) = ty else {
        return Err(format!(
            "type `{}` cannot be a parameter: use f64, i64, bool, an enum deriving Choice, Option<enum> or a group deriving Params",
            quote::quote!(#ty)
        ));
    };
    let seg = p.path.segments.last().expect("a path has segments");
    let name = seg.ident.to_string();
    match name.as_str() {
        "f64" => Ok(LeafType::Float),
        "i64" => Ok(LeafType::Int),
        "bool" => Ok(LeafType::Bool),
        "Option" => {
            if let PathArguments::AngleBracketed(args) = &seg.arguments
                && let Some(GenericArgument::Type(inner)) = args.args.first()
                && matches!(classify(inner), Ok(LeafType::Other))
            {
                return Ok(LeafType::OptionalOther);
            }
            Err("an optional parameter must be `Option<E>` with an enum `E` deriving Choice".into())
        }
        "f32" | "i32" | "i8" | "i16" | "u8" | "u16" | "u32" | "u64" | "usize" | "isize" | "i128" | "u128" => {
            Err(format!("use `f64` or `i64` for numeric parameters, not `{name}`"))
        }
        "String" | "str" | "Vec" | "HashMap" | "BTreeMap" | "Box" | "Rc" | "Arc" | "char" => Err(format!(
            "type `{name}` cannot be a parameter: use f64, i64, bool, an enum deriving Choice, Option<enum> or a group deriving Params"
        )),
        _ => Ok(LeafType::Other),
    }
}

/// Parse and validate a parameter struct.
pub fn parse_struct(input: &DeriveInput) -> Result<ParamStruct, syn::Error> {
    let mut errors = Errors::default();
    let Data::Struct(data) = &input.data else {
        return Err(syn::Error::new(
            input.ident.span(),
            "#[derive(Params)] expects a struct with named fields; use #[derive(Choice)] for enums",
        ));
    };
    let Fields::Named(named) = &data.fields else {
        return Err(syn::Error::new(input.ident.span(), "#[derive(Params)] expects a struct with named fields"));
    };
    let mut fields = Vec::new();
    let mut names: Vec<(String, Span)> = Vec::new();
    for f in &named.named {
        let ident = f.ident.clone().expect("named field");
        let raw = parse_param_attr(&f.attrs, &mut errors);
        let (name, name_span) = match &raw.rename {
            Some(l) => (l.value(), l.span()),
            None => (ident.unraw().to_string(), ident.span()),
        };
        if name.is_empty() || name.contains('.') {
            errors.at(name_span, format!("parameter name `{name}` must be non-empty and contain no `.`"));
        }
        if let Some((_, first)) = names.iter().find(|(n, _)| *n == name) {
            let _ = first;
            errors.at(name_span, format!("duplicate parameter name `{name}` (after renaming)"));
        }
        names.push((name.clone(), name_span));

        let is_leaf = raw.default.is_some() || raw.range.is_some() || raw.options.is_some() || raw.prob.is_some();
        if !is_leaf {
            let mut seen: Vec<String> = Vec::new();
            for o in &raw.overrides {
                let d = o.dotted();
                if seen.contains(&d) {
                    errors.at(o.span, format!("`{d}` is overridden twice"));
                }
                seen.push(d);
            }
            if let (Some(span), false) = (raw.skip, raw.overrides.is_empty()) {
                errors.at(span, "a skipped group takes no `field(..)` overrides (it is left out of the schema whole)");
            }
            let skip = raw.skip.is_some();
            fields.push(Field::Group(Group { ident, ty: f.ty.clone(), name, overrides: raw.overrides, skip }));
            continue;
        }
        if let Some(span) = raw.skip {
            errors.at(span, "`skip` applies to nested groups; a parameter is described by its `default`, `range` and `prob`");
        }
        if let Some(o) = raw.overrides.first() {
            errors.at(o.path[0].span(), "`field(..)` overrides apply to nested groups, not to a parameter");
        }
        let leaf_type = match classify(&f.ty) {
            Ok(t) => t,
            Err(msg) => {
                errors.spanned(&f.ty, msg);
                continue;
            }
        };
        let Some(default) = raw.default.clone() else {
            errors.at(ident.span(), "a parameter needs a `default = ..`");
            continue;
        };
        let range = raw.range.as_ref().and_then(|(e, _)| parse_range(e, &mut errors));
        let options = raw.options.as_ref().map(|(items, _)| {
            items
                .iter()
                .filter_map(|it| match number(it) {
                    Some((v, _)) => Some(v),
                    None => {
                        errors.spanned(it, "options must be numbers (use an enum deriving Choice for named options)");
                        None
                    }
                })
                .collect::<Vec<f64>>()
        });
        let prob = raw.prob.as_ref().and_then(|(e, span)| match number(e) {
            Some((p, _)) if (0.0..=1.0).contains(&p) => Some(p),
            Some((p, _)) => {
                errors.spanned(e, format!("probability {p} is outside [0, 1]"));
                None
            }
            None => {
                let _ = span;
                errors.spanned(e, "prob must be a number in [0, 1]");
                None
            }
        });
        if let Some((_, span)) = raw.null_option
            && leaf_type != LeafType::OptionalOther
        {
            errors.at(span, "`null_option` applies to optional (`Option<E>`) parameters only");
        }
        // Type-specific rules.
        match leaf_type {
            LeafType::Float | LeafType::Int => {
                if raw.range.is_none() && raw.options.is_none() {
                    errors.at(ident.span(), "a numeric parameter needs `range = lo..=hi` or `options = [..]`");
                }
                if raw.range.is_some() && raw.options.is_some() {
                    errors.at(ident.span(), "give either `range` or `options`, not both");
                }
                match number(&default) {
                    None => errors.spanned(&default, "the default of a numeric parameter must be a number"),
                    Some((d, is_int)) => {
                        if leaf_type == LeafType::Int && !is_int {
                            errors.spanned(&default, "the default of an i64 parameter must be an integer");
                        }
                        if let Some((lo, hi)) = range
                            && (d < lo || d > hi)
                        {
                            errors.spanned(&default, format!("default {d} is outside the range {lo}..={hi}"));
                        }
                        if let Some(opts) = &options
                            && !opts.is_empty()
                            && !opts.contains(&d)
                        {
                            let list: Vec<String> = opts.iter().map(|o| o.to_string()).collect();
                            errors.spanned(&default, format!("default {d} is not one of the options [{}]", list.join(", ")));
                        }
                    }
                }
                if let Some(opts) = &options {
                    if leaf_type == LeafType::Int {
                        for item in &raw.options.as_ref().expect("options").0 {
                            if number(item).is_some_and(|(_, is_int)| !is_int) {
                                errors.spanned(item, "options of an i64 parameter must be integers");
                            }
                        }
                    }
                    if opts.is_empty() {
                        errors.at(raw.options.as_ref().expect("options").1, "options must not be empty");
                    }
                }
            }
            LeafType::Bool | LeafType::Other | LeafType::OptionalOther => {
                if let Some((_, span)) = &raw.range {
                    errors.at(*span, "`range` applies to f64 and i64 parameters only");
                }
                if let Some((_, span)) = &raw.options {
                    errors.at(*span, "`options` applies to f64 and i64 parameters; the options of an enum are its variants");
                }
                if leaf_type == LeafType::Bool && !matches!(&default, Expr::Lit(syn::ExprLit { lit: syn::Lit::Bool(_), .. })) {
                    errors.spanned(&default, "the default of a bool parameter must be `true` or `false`");
                }
            }
        }
        fields.push(Field::Leaf(Box::new(Leaf {
            ident,
            ty: f.ty.clone(),
            leaf_type,
            name,
            name_span,
            range,
            options,
            default,
            prob,
            description: doc_comment(&f.attrs),
            null_option: raw.null_option.map(|(b, _)| b).unwrap_or(true),
        })));
    }
    errors.finish()?;
    Ok(ParamStruct { fields })
}

fn parse_range(e: &Expr, errors: &mut Errors) -> Option<(f64, f64)> {
    let Expr::Range(r) = e else {
        errors.spanned(e, "range must be written `lo..=hi`");
        return None;
    };
    if !matches!(r.limits, RangeLimits::Closed(_)) {
        errors.spanned(e, "range must include its upper bound: write `lo..=hi`");
        return None;
    }
    let (Some(start), Some(end)) = (&r.start, &r.end) else {
        errors.spanned(e, "range needs both bounds: `lo..=hi`");
        return None;
    };
    for bound in [start, end] {
        if number(bound).is_none() {
            errors.spanned(bound, "range bounds must be number literals");
        }
    }
    let (Some((lo, _)), Some((hi, _))) = (number(start), number(end)) else {
        return None;
    };
    if lo >= hi {
        errors.spanned(e, format!("empty or reversed range {lo}..={hi}"));
        return None;
    }
    Some((lo, hi))
}

/// A parsed `#[derive(Choice)]` enum: variant idents and option names.
pub struct ChoiceEnum {
    /// `(variant, name in design files)`.
    pub variants: Vec<(Ident, String)>,
}

/// Parse and validate a choice enum.
pub fn parse_enum(input: &DeriveInput) -> Result<ChoiceEnum, syn::Error> {
    let mut errors = Errors::default();
    let Data::Enum(data) = &input.data else {
        return Err(syn::Error::new(input.ident.span(), "#[derive(Choice)] expects an enum of unit variants"));
    };
    if data.variants.is_empty() {
        return Err(syn::Error::new(input.ident.span(), "a choice needs at least one variant"));
    }
    let mut variants: Vec<(Ident, String)> = Vec::new();
    for v in &data.variants {
        if !matches!(v.fields, Fields::Unit) {
            errors.at(v.ident.span(), "choice variants cannot carry data");
        }
        let raw = parse_param_attr(&v.attrs, &mut errors);
        if raw.range.is_some() || raw.options.is_some() || raw.default.is_some() || raw.prob.is_some() || !raw.overrides.is_empty() {
            errors.at(v.ident.span(), "only `rename` applies to choice variants");
        }
        let (name, span) = match &raw.rename {
            Some(l) => (l.value(), l.span()),
            None => (v.ident.unraw().to_string(), v.ident.span()),
        };
        if variants.iter().any(|(_, n)| *n == name) {
            errors.at(span, format!("duplicate option name `{name}` (after renaming)"));
        }
        variants.push((v.ident.clone(), name));
    }
    errors.finish()?;
    Ok(ChoiceEnum { variants })
}
