//! The model of a `#[derive(Component)]` struct.

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

/// An `#[interface]` field.
pub struct InterfaceField {
    /// The field.
    pub ident: Ident,
    /// Name for lookups.
    pub name: String,
    /// `Option<InterfaceId>` rather than `InterfaceId`.
    pub optional: bool,
    /// Slot marker type to implement `Slot<_>` for.
    pub slot: Option<Path>,
}

/// A parsed component or panel class.
pub struct ComponentStruct {
    /// `#[panel]` field: the struct is a panel class.
    pub panel: Option<Ident>,
    /// `#[part]` fields in order.
    pub parts: Vec<Ident>,
    /// `#[interface]` fields.
    pub interfaces: Vec<InterfaceField>,
    /// `#[stitches]` field.
    pub stitches: Option<Ident>,
    /// `#[component(name = "..")]` or `#[component(name = self.field)]`.
    pub name: Option<syn::Expr>,
    /// `#[component(length = path)]`.
    pub length: Option<Path>,
}

fn last_ident(ty: &Type) -> Option<(&Ident, &PathArguments)> {
    match ty {
        Type::Path(p) => p.path.segments.last().map(|s| (&s.ident, &s.arguments)),
        _ => None,
    }
}

/// Parse and validate a component struct.
pub fn parse(input: &DeriveInput) -> Result<ComponentStruct, syn::Error> {
    let mut errors = Errors::default();
    let Data::Struct(data) = &input.data else {
        return Err(syn::Error::new(input.ident.span(), "#[derive(Component)] expects a struct with named fields"));
    };
    let Fields::Named(named) = &data.fields else {
        return Err(syn::Error::new(input.ident.span(), "#[derive(Component)] expects a struct with named fields"));
    };
    let mut out = ComponentStruct { panel: None, parts: Vec::new(), interfaces: Vec::new(), stitches: None, name: None, length: None };
    for attr in input.attrs.iter().filter(|a| a.path().is_ident("component")) {
        let res = attr.parse_nested_meta(|meta| {
            if meta.path.is_ident("name") {
                out.name = Some(meta.value()?.parse()?);
            } else if meta.path.is_ident("length") {
                out.length = Some(meta.value()?.parse()?);
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
        let mut roles: Vec<(&str, Span)> = Vec::new();
        for attr in &f.attrs {
            let p = attr.path();
            if p.is_ident("part") {
                roles.push(("part", attr.span()));
                if !matches!(attr.meta, syn::Meta::Path(_)) {
                    errors.at(attr.span(), "#[part] takes no arguments");
                }
                out.parts.push(ident.clone());
            } else if p.is_ident("panel") {
                roles.push(("panel", attr.span()));
                if out.panel.is_some() {
                    errors.at(attr.span(), "a panel class has exactly one #[panel] field");
                }
                if last_ident(&f.ty).map(|(i, _)| i != "PanelId").unwrap_or(true) {
                    errors.at(f.ty.span(), "a #[panel] field must be a PanelId");
                }
                out.panel = Some(ident.clone());
            } else if p.is_ident("stitches") {
                roles.push(("stitches", attr.span()));
                if out.stitches.is_some() {
                    errors.at(attr.span(), "only one #[stitches] field");
                }
                out.stitches = Some(ident.clone());
            } else if p.is_ident("interface") {
                roles.push(("interface", attr.span()));
                let mut name = syn::ext::IdentExt::unraw(&ident).to_string();
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
                let optional = match last_ident(&f.ty) {
                    Some((i, _)) if i == "InterfaceId" => false,
                    Some((i, PathArguments::AngleBracketed(args))) if i == "Option" => match args.args.first() {
                        Some(GenericArgument::Type(inner)) if last_ident(inner).map(|(i, _)| i == "InterfaceId").unwrap_or(false) => true,
                        _ => {
                            errors.at(f.ty.span(), "an #[interface] field must be an InterfaceId or Option<InterfaceId>");
                            false
                        }
                    },
                    _ => {
                        errors.at(f.ty.span(), "an #[interface] field must be an InterfaceId or Option<InterfaceId>");
                        false
                    }
                };
                if optional && slot.is_some() {
                    errors.at(attr.span(), "an optional interface cannot fill a slot");
                }
                if out.interfaces.iter().any(|i| i.name == name) {
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
                out.interfaces.push(InterfaceField { ident: ident.clone(), name, optional, slot });
            }
        }
        if roles.len() > 1 {
            errors.at(roles[1].1, format!("a field has one role: #[{}] and #[{}] both given", roles[0].0, roles[1].0));
        }
    }
    if out.panel.is_some() && !out.parts.is_empty() {
        errors.at(input.ident.span(), "a panel class (#[panel]) cannot have #[part] sub-parts");
    }
    if out.panel.is_some() && out.stitches.is_some() {
        errors.at(input.ident.span(), "a panel class keeps its stitches (darts) in the panel; remove #[stitches]");
    }
    errors.finish()?;
    Ok(out)
}
