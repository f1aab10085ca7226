//! The model of a `#[derive(Component)]` struct or enum.

use super::Errors;
use proc_macro2::Span;
use syn::spanned::Spanned;
use syn::{Data, DeriveInput, Fields, GenericArgument, Ident, LitStr, Path, PathArguments, Type};

/// Interface names with a standard slot marker in `garmentcode::slots`
/// (name in files, marker type).
pub const STANDARD_SLOTS: &[(&str, &str)] = &[
    ("top", "Top"),
    ("bottom", "Bottom"),
    ("top_f", "TopF"),
    ("top_b", "TopB"),
    ("bottom_f", "BottomF"),
    ("bottom_b", "BottomB"),
    ("front", "Front"),
    ("back", "Back"),
    ("front_in", "FrontIn"),
    ("back_in", "BackIn"),
    ("in", "In"),
    ("out", "Out"),
    ("left", "Left"),
    ("right", "Right"),
    ("inside", "Inside"),
    ("outside", "Outside"),
    ("shoulder", "Shoulder"),
];

/// Types whose values hold arena ids: a field of such a type follows a copy
/// (`Remap`) even without a role attribute; other plain fields are cloned.
const ID_TYPES: &[&str] = &["InterfaceId", "PanelId", "EdgeId", "EdgeSeq", "StitchRule"];

/// Containers the derive looks through for [`ID_TYPES`].
const CONTAINERS: &[&str] = &["Option", "Vec", "Box"];

/// An `#[interface]` field.
pub struct InterfaceField {
    /// The field.
    pub ident: Ident,
    /// Its type.
    pub ty: Type,
    /// Name the interface is listed under.
    pub name: String,
    /// `Option<InterfaceId>` rather than `InterfaceId`.
    pub optional: bool,
    /// Slot marker type to implement `Slot<_>` for.
    pub slot: Option<Path>,
}

/// A field with a role (`#[part]`, `#[panel]`, `#[stitches]`) or none.
pub struct Field {
    /// The field.
    pub ident: Ident,
    /// Its type.
    pub ty: Type,
}

/// A field without a role attribute.
pub struct PlainField {
    /// The field.
    pub ident: Ident,
    /// Its type.
    pub ty: Type,
    /// Its type holds ids (remapped by a copy rather than cloned).
    pub holds_ids: bool,
}

/// A parsed component or panel class (a struct).
pub struct ComponentStruct {
    /// `#[panel]` field: the struct is a panel class.
    pub panel: Option<Field>,
    /// `#[part]` fields in order.
    pub parts: Vec<Field>,
    /// `#[interface]` fields.
    pub interfaces: Vec<InterfaceField>,
    /// `#[stitches]` field.
    pub stitches: Option<Field>,
    /// Fields without a role.
    pub plain: Vec<PlainField>,
    /// `#[component(name = "..")]` or `#[component(name = self.field)]`.
    pub name: Option<syn::Expr>,
    /// `#[component(length = path)]`.
    pub length: Option<Path>,
}

/// One variant of a component enum: `Name(PartType)`.
pub struct Variant {
    /// The variant.
    pub ident: Ident,
    /// The part it holds.
    pub ty: Type,
}

/// A parsed component enum: a part that is one of several kinds.
pub struct ComponentEnum {
    /// The variants.
    pub variants: Vec<Variant>,
    /// `#[component(slots(A, B))]`: slots every variant fills.
    pub slots: Vec<Path>,
}

/// What `#[derive(Component)]` was given.
pub enum Model {
    /// A component or panel class.
    Struct(Box<ComponentStruct>),
    /// A choice between parts.
    Enum(ComponentEnum),
}

fn last_ident(ty: &Type) -> Option<(&Ident, &PathArguments)> {
    match ty {
        Type::Path(p) => p.path.segments.last().map(|s| (&s.ident, &s.arguments)),
        _ => None,
    }
}

/// Whether a type is one of [`ID_TYPES`], possibly inside [`CONTAINERS`].
fn holds_ids(ty: &Type) -> bool {
    match last_ident(ty) {
        Some((i, PathArguments::None)) => ID_TYPES.iter().any(|t| i == t),
        Some((i, PathArguments::AngleBracketed(args))) if CONTAINERS.iter().any(|c| i == c) => {
            args.args.iter().any(|a| matches!(a, GenericArgument::Type(t) if holds_ids(t)))
        }
        _ => false,
    }
}

/// Parse and validate a component struct or enum.
pub fn parse(input: &DeriveInput) -> Result<Model, syn::Error> {
    match &input.data {
        Data::Struct(data) => parse_struct(input, &data.fields).map(|s| Model::Struct(Box::new(s))),
        Data::Enum(data) => parse_enum(input, data).map(Model::Enum),
        Data::Union(u) => Err(syn::Error::new(
            u.union_token.span(),
            "#[derive(Component)] expects a struct with named fields (a component or panel class) or an enum of parts",
        )),
    }
}

fn parse_enum(input: &DeriveInput, data: &syn::DataEnum) -> Result<ComponentEnum, syn::Error> {
    let mut errors = Errors::default();
    let mut out = ComponentEnum { variants: Vec::new(), slots: Vec::new() };
    for attr in input.attrs.iter().filter(|a| a.path().is_ident("component")) {
        let res = attr.parse_nested_meta(|meta| {
            if meta.path.is_ident("slots") {
                meta.parse_nested_meta(|slot| {
                    out.slots.push(slot.path.clone());
                    Ok(())
                })
            } else if meta.path.is_ident("name") || meta.path.is_ident("length") {
                Err(meta.error("a component enum takes its name and length from the part it holds; remove this attribute"))
            } else {
                Err(meta.error("unknown attribute of a component enum (expected `slots(Marker, ..)`)"))
            }
        });
        if let Err(e) = res {
            errors.push(e);
        }
    }
    if data.variants.is_empty() {
        errors.at(input.ident.span(), "a component enum needs at least one variant");
    }
    for v in &data.variants {
        match &v.fields {
            Fields::Unnamed(f) if f.unnamed.len() == 1 => {
                let field = f.unnamed.first().expect("one field");
                if let Some(attr) = field.attrs.iter().chain(&v.attrs).find(|a| is_role(a)) {
                    errors.at(attr.span(), "a component enum's variants hold whole parts: remove the role attribute");
                }
                out.variants.push(Variant { ident: v.ident.clone(), ty: field.ty.clone() });
            }
            _ => errors.at(v.span(), "each variant of a component enum holds one part, e.g. `Circle(SkirtCircle)`"),
        }
    }
    errors.finish()?;
    Ok(out)
}

fn is_role(attr: &syn::Attribute) -> bool {
    ["part", "panel", "interface", "stitches"].iter().any(|r| attr.path().is_ident(r))
}

fn parse_struct(input: &DeriveInput, fields: &Fields) -> Result<ComponentStruct, syn::Error> {
    let mut errors = Errors::default();
    let Fields::Named(named) = fields else {
        return Err(syn::Error::new(fields.span(), "#[derive(Component)] expects a struct with named fields"));
    };
    let mut out = ComponentStruct {
        panel: None,
        parts: Vec::new(),
        interfaces: Vec::new(),
        stitches: None,
        plain: Vec::new(),
        name: None,
        length: None,
    };
    for attr in input.attrs.iter().filter(|a| a.path().is_ident("component")) {
        let res = attr.parse_nested_meta(|meta| {
            if meta.path.is_ident("name") {
                out.name = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("length") {
                out.length = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("slots") {
                return Err(meta.error("`slots(..)` is for component enums; a struct fills the slots named by its #[interface] fields"));
            } else {
                return Err(meta.error("unknown component attribute (expected `name = \"..\"`, `name = self.field` or `length = path`)"));
            }
            Ok(())
        });
        if let Err(e) = res {
            errors.push(e);
        }
    }
    for f in &named.named {
        let ident = f.ident.clone().expect("named field");
        let field = || Field { ident: ident.clone(), ty: f.ty.clone() };
        let mut roles: Vec<(&str, Span)> = Vec::new();
        for attr in &f.attrs {
            let p = attr.path();
            if p.is_ident("part") {
                roles.push(("part", attr.span()));
                if !matches!(attr.meta, syn::Meta::Path(_)) {
                    errors.at(attr.span(), "#[part] takes no arguments");
                }
                out.parts.push(field());
            } else if p.is_ident("panel") {
                roles.push(("panel", attr.span()));
                if !matches!(attr.meta, syn::Meta::Path(_)) {
                    errors.at(attr.span(), "#[panel] takes no arguments");
                }
                if out.panel.is_some() {
                    errors.at(attr.span(), "a panel class has exactly one #[panel] field");
                }
                if last_ident(&f.ty).map(|(i, _)| i != "PanelId").unwrap_or(true) {
                    errors.at(f.ty.span(), "a #[panel] field must be a PanelId");
                }
                out.panel = Some(field());
            } else if p.is_ident("stitches") {
                roles.push(("stitches", attr.span()));
                if !matches!(attr.meta, syn::Meta::Path(_)) {
                    errors.at(attr.span(), "#[stitches] takes no arguments");
                }
                if out.stitches.is_some() {
                    errors.at(attr.span(), "only one #[stitches] field");
                }
                out.stitches = Some(field());
            } else if p.is_ident("interface") {
                roles.push(("interface", attr.span()));
                if let Some(i) = parse_interface(&ident, &f.ty, attr, &out.interfaces, &mut errors) {
                    out.interfaces.push(i);
                }
            }
        }
        if roles.len() > 1 {
            errors.at(roles[1].1, format!("a field has one role: #[{}] and #[{}] both given", roles[0].0, roles[1].0));
        }
        if roles.is_empty() {
            out.plain.push(PlainField { ident: ident.clone(), ty: f.ty.clone(), holds_ids: holds_ids(&f.ty) });
        }
    }
    if out.panel.is_some() && !out.parts.is_empty() {
        errors.at(input.ident.span(), "a panel class (#[panel]) cannot have #[part] sub-parts");
    }
    if out.panel.is_some() && out.stitches.is_some() {
        errors.at(input.ident.span(), "a panel class keeps its stitches (darts) in the panel; remove #[stitches]");
    }
    if out.panel.is_some() && (out.name.is_some() || out.length.is_some()) {
        errors.at(input.ident.span(), "a panel class takes its name and length from its panel; remove `name`/`length`");
    }
    errors.finish()?;
    Ok(out)
}

fn parse_interface(
    ident: &Ident,
    ty: &Type,
    attr: &syn::Attribute,
    seen: &[InterfaceField],
    errors: &mut Errors,
) -> Option<InterfaceField> {
    let mut name = syn::ext::IdentExt::unraw(ident).to_string();
    let mut slot: Option<Path> = None;
    if !matches!(attr.meta, syn::Meta::Path(_)) {
        let res = attr.parse_nested_meta(|meta| {
            if meta.path.is_ident("rename") {
                name = meta.value()?.parse::<LitStr>()?.value();
            } else if meta.path.is_ident("slot") {
                slot = Some(meta.value()?.parse()?);
            } else {
                return Err(meta.error("unknown interface attribute (expected `rename = \"..\"` or `slot = Marker`)"));
            }
            Ok(())
        });
        if let Err(e) = res {
            errors.push(e);
        }
    }
    let optional = match last_ident(ty) {
        Some((i, PathArguments::None)) if i == "InterfaceId" => false,
        Some((i, PathArguments::AngleBracketed(args))) if i == "Option" => match args.args.first() {
            Some(GenericArgument::Type(inner)) if last_ident(inner).map(|(i, _)| i == "InterfaceId").unwrap_or(false) => true,
            _ => {
                errors.at(ty.span(), "an #[interface] field must be an InterfaceId or Option<InterfaceId>");
                return None;
            }
        },
        _ => {
            errors.at(ty.span(), "an #[interface] field must be an InterfaceId or Option<InterfaceId>");
            return None;
        }
    };
    if optional && slot.is_some() {
        errors.at(attr.span(), "an optional interface cannot fill a slot");
    }
    if seen.iter().any(|i| i.name == name) {
        errors.at(ident.span(), format!("duplicate interface name `{name}`"));
    }
    let slot = slot.or_else(|| {
        if optional {
            return None;
        }
        STANDARD_SLOTS.iter().find(|(n, _)| *n == name).map(|(_, m)| {
            let m = Ident::new(m, Span::call_site());
            syn::parse_quote!(::garmentcode::slots::#m)
        })
    });
    Some(InterfaceField { ident: ident.clone(), ty: ty.clone(), name, optional, slot })
}
