//! `#[derive(Params)]`: schema, defaults and typed access by path.

use crate::internals::number;
use crate::internals::param::{Field, LeafType, Override, parse_struct};
use proc_macro2::TokenStream;
use quote::{quote, quote_spanned};
use syn::ext::IdentExt;
use syn::spanned::Spanned;
use syn::{DeriveInput, Expr, GenericArgument, PathArguments, Type};

pub fn derive(input: &DeriveInput) -> TokenStream {
    let ident = &input.ident;
    let (impl_g, ty_g, where_g) = input.generics.split_for_impl();
    let model = match parse_struct(input) {
        Ok(m) => m,
        Err(e) => {
            // The error plus a stub impl, so uses of the type do not cascade.
            let err = e.to_compile_error();
            let never = super::placeholder_body();
            return quote! {
                #err
                #[automatically_derived]
                impl #impl_g ::garmentcode::__private::Params for #ident #ty_g #where_g {
                    fn describe(_: &str, _: &mut ::std::vec::Vec<::garmentcode::__private::ParamSpec>) { #never }
                    fn defaults() -> Self { #never }
                    fn get_value(&self, _: &[&str]) -> ::std::option::Option<::garmentcode::__private::Value> { #never }
                    fn set_value(&mut self, _: &[&str], _: &::garmentcode::__private::Value) -> ::std::result::Result<(), ::std::string::String> { #never }
                }
            };
        }
    };
    let p = quote!(::garmentcode::__private);
    let mut describe = Vec::new();
    let mut defaults = Vec::new();
    let mut gets = Vec::new();
    let mut sets = Vec::new();
    let mut fields = Vec::new();
    let mut checks = Vec::new();
    for field in &model.fields {
        match field {
            Field::Group(g) => {
                let (fid, ty, name) = (&g.ident, &g.ty, &g.name);
                // Paths spanned at the field's type: a type error points there.
                let p = quote_spanned!(ty.span()=> ::garmentcode::__private);
                let field_name = fid.unraw().to_string();
                fields.push(quote_spanned! {ty.span()=>
                    #p::FieldInfo { field: #field_name, name: #name, shape: #p::FieldShape::Group(<#ty as #p::Params>::FIELDS) }
                });
                if g.skip {
                    defaults.push(quote_spanned! {ty.span()=> #fid: <#ty as #p::Params>::defaults() });
                } else if g.overrides.is_empty() {
                    describe.push(quote_spanned! {ty.span()=>
                        <#ty as #p::Params>::describe(&#p::join_path(prefix, #name), out);
                    });
                    defaults.push(quote_spanned! {ty.span()=> #fid: <#ty as #p::Params>::defaults() });
                } else {
                    let group = overridden_defaults(ty, &g.overrides);
                    let specs = g.overrides.iter().map(override_spec);
                    describe.push(quote_spanned! {ty.span()=>
                        {
                            let start = out.len();
                            let prefix = #p::join_path(prefix, #name);
                            <#ty as #p::Params>::describe(&prefix, out);
                            let group: #ty = #group;
                            #p::apply_overrides(out, start, &prefix, &group, &[#(#specs),*]);
                        }
                    });
                    defaults.push(quote! { #fid: #group });
                    if input.generics.params.is_empty() {
                        checks.extend(g.overrides.iter().filter_map(|o| override_check(ty, o)));
                    }
                }
                gets.push(quote_spanned! {ty.span()=> [#name, rest @ ..] => #p::Params::get_value(&self.#fid, rest) });
                sets.push(quote_spanned! {ty.span()=> [#name, rest @ ..] => #p::Params::set_value(&mut self.#fid, rest, v) });
            }
            Field::Leaf(l) => {
                let (fid, ty, name) = (&l.ident, &l.ty, &l.name);
                let p = quote_spanned!(ty.span()=> ::garmentcode::__private);
                let description = &l.description;
                let default = default_expr(l.leaf_type, ty, &l.default);
                let prob = match l.prob {
                    Some(x) => quote!(::std::option::Option::Some(#x)),
                    None => quote!(::std::option::Option::None),
                };
                let (kind, range) = match (&l.range, &l.options) {
                    (Some((lo, hi)), _) => (quote!(<#ty as #p::ParamValue>::KIND), quote!(#p::Range::Numeric { lo: #lo, hi: #hi })),
                    (None, Some(opts)) => {
                        let vals: Vec<TokenStream> = opts
                            .iter()
                            .map(|o| {
                                if l.leaf_type == LeafType::Int {
                                    let i = *o as i64;
                                    quote!(#p::Value::Int(#i))
                                } else {
                                    quote!(#p::Value::Float(#o))
                                }
                            })
                            .collect();
                        (quote!(#p::Kind::Select), quote!(#p::Range::Options(::std::vec![#(#vals),*])))
                    }
                    (None, None) if !l.null_option => (
                        quote!(<#ty as #p::ParamValue>::KIND),
                        quote!(#p::Range::Options({
                            let mut o = <#ty as #p::ParamValue>::options();
                            o.retain(|v| *v != #p::Value::Null);
                            o
                        })),
                    ),
                    (None, None) => (quote!(<#ty as #p::ParamValue>::KIND), quote!(#p::Range::Options(<#ty as #p::ParamValue>::options()))),
                };
                let span = ty.span();
                let field_name = fid.unraw().to_string();
                let own_range = match &l.range {
                    Some((lo, hi)) => quote!(::std::option::Option::Some((#lo, #hi))),
                    None => quote!(::std::option::Option::None),
                };
                fields.push(quote_spanned! {span=>
                    #p::FieldInfo {
                        field: #field_name,
                        name: #name,
                        shape: #p::FieldShape::Leaf { kind: <#ty as #p::ParamValue>::KIND, range: #own_range },
                    }
                });
                describe.push(quote_spanned! {span=>
                    out.push(#p::ParamSpec {
                        path: #p::join_path(prefix, #name),
                        kind: #kind,
                        range: #range,
                        default: <#ty as #p::ParamValue>::to_value(&(#default)),
                        default_prob: #prob,
                        description: ::std::string::String::from(#description),
                    });
                });
                defaults.push(quote! { #fid: #default });
                gets.push(quote! { [#name] => ::std::option::Option::Some(<#ty as #p::ParamValue>::to_value(&self.#fid)) });
                sets.push(quote! {
                    [#name] => {
                        self.#fid = <#ty as #p::ParamValue>::from_value(v)
                            .ok_or_else(|| ::std::format!("value {} does not fit this parameter", v))?;
                        ::std::result::Result::Ok(())
                    }
                });
                let _ = l.name_span;
            }
        }
    }
    quote! {
        #[automatically_derived]
        impl #impl_g #p::Params for #ident #ty_g #where_g {
            const FIELDS: &'static [#p::FieldInfo] = &[#(#fields),*];
            fn describe(prefix: &str, out: &mut ::std::vec::Vec<#p::ParamSpec>) {
                #(#describe)*
            }
            fn defaults() -> Self {
                #ident { #(#defaults),* }
            }
            fn get_value(&self, path: &[&str]) -> ::std::option::Option<#p::Value> {
                match path {
                    #(#gets,)*
                    _ => ::std::option::Option::None,
                }
            }
            fn set_value(&mut self, path: &[&str], v: &#p::Value) -> ::std::result::Result<(), ::std::string::String> {
                match path {
                    #(#sets,)*
                    _ => ::std::result::Result::Err(::std::format!("unknown parameter {}", path.join("."))),
                }
            }
        }
        #(#checks)*
    }
}

/// The group's defaults with the overridden defaults set; every overridden field is
/// named in a place expression, so the compiler reports an unknown one at its name.
fn overridden_defaults(ty: &Type, overrides: &[Override]) -> TokenStream {
    let p = quote!(::garmentcode::__private);
    let sets = overrides.iter().map(|o| {
        let path = &o.path;
        match &o.default {
            Some(e) => {
                let value = match number(e) {
                    Some((v, _)) => quote_spanned!(e.span()=> ::garmentcode::__private::override_number(#v)),
                    None => quote_spanned!(e.span()=> #e),
                };
                quote_spanned!(o.span=> group.#(#path).* = #value;)
            }
            None => quote_spanned!(o.span=> let _ = &group.#(#path).*;),
        }
    });
    let mutable = if overrides.iter().any(|o| o.default.is_some()) { quote!(mut) } else { quote!() };
    quote_spanned! {ty.span()=>
        {
            let #mutable group = <#ty as #p::Params>::defaults();
            #(#sets)*
            group
        }
    }
}

/// The override as `apply_overrides` takes it.
fn override_spec(o: &Override) -> TokenStream {
    let p = quote!(::garmentcode::__private);
    let path: Vec<String> = o.path.iter().map(|i| i.unraw().to_string()).collect();
    let range = match o.range {
        Some((lo, hi)) => quote!(::std::option::Option::Some((#lo, #hi))),
        None => quote!(::std::option::Option::None),
    };
    let prob = match o.prob {
        Some(Some(x)) => quote!(::std::option::Option::Some(::std::option::Option::Some(#x))),
        Some(None) => quote!(::std::option::Option::Some(::std::option::Option::None)),
        None => quote!(::std::option::Option::None),
    };
    let doc = match &o.doc {
        Some(d) => quote!(::std::option::Option::Some(#d)),
        None => quote!(::std::option::Option::None),
    };
    let (default, skip) = (o.default.is_some(), o.skip);
    quote!(#p::Override { path: &[#(#path),*], range: #range, prob: #prob, doc: #doc, default: #default, skip: #skip })
}

/// A `const` that checks the override against the group's fields while compiling,
/// reported at the override; none when there is nothing to check (`skip`, `doc`).
fn override_check(ty: &Type, o: &Override) -> Option<TokenStream> {
    let dotted = o.dotted();
    let path: Vec<String> = o.path.iter().map(|i| i.unraw().to_string()).collect();
    if o.default.is_none() && o.range.is_none() && o.prob.is_none() {
        return None;
    }
    let default = o.default.as_ref().and_then(number).map(|(v, _)| v);
    let default_q = match default {
        Some(v) => quote!(::std::option::Option::Some(#v)),
        None => quote!(::std::option::Option::None),
    };
    let range = match o.range {
        Some((lo, hi)) => quote!(::std::option::Option::Some((#lo, #hi))),
        None => quote!(::std::option::Option::None),
    };
    let shown = default.map(|v| v.to_string()).unwrap_or_default();
    let not_a_parameter = format!("override of `{dotted}`: a nested group takes no default, range or prob (override its parameters)");
    let not_numeric = format!("override of `{dotted}`: `range` applies to f64 and i64 parameters only");
    let not_an_integer = format!("override of `{dotted}`: default {shown} of an i64 parameter is not an integer");
    let out_of_range = format!("override of `{dotted}`: default {shown} is outside the parameter's range");
    let span = o.default.as_ref().filter(|e| number(e).is_some()).map(|e| e.span()).unwrap_or(o.span);
    Some(quote_spanned! {span=>
        const _: () = match ::garmentcode::__private::override_problem(
            <#ty as ::garmentcode::__private::Params>::FIELDS,
            &[#(#path),*],
            #default_q,
            #range,
        ) {
            ::garmentcode::__private::OverrideProblem::None => {}
            ::garmentcode::__private::OverrideProblem::NotAParameter => ::core::panic!(#not_a_parameter),
            ::garmentcode::__private::OverrideProblem::NotNumeric => ::core::panic!(#not_numeric),
            ::garmentcode::__private::OverrideProblem::NotAnInteger => ::core::panic!(#not_an_integer),
            ::garmentcode::__private::OverrideProblem::OutOfRange => ::core::panic!(#out_of_range),
        };
    })
}

/// The default as a Rust expression of the field's type, spanned at the author's
/// tokens (an unknown enum variant is reported there).
fn default_expr(leaf: LeafType, ty: &Type, e: &Expr) -> TokenStream {
    let span = e.span();
    match leaf {
        LeafType::Float => {
            let v = number(e).map(|(v, _)| v).unwrap_or(0.0);
            quote_spanned!(span=> #v)
        }
        LeafType::Int => {
            let v = number(e).map(|(v, _)| v as i64).unwrap_or(0);
            quote_spanned!(span=> #v)
        }
        LeafType::Bool => quote_spanned!(span=> #e),
        LeafType::Other => variant(ty, e),
        LeafType::OptionalOther => {
            if let Expr::Path(p) = e
                && p.path.is_ident("None")
            {
                return quote_spanned!(span=> ::std::option::Option::None);
            }
            let inner = option_inner(ty).expect("classified as Option<T>");
            let v = variant(inner, e);
            quote_spanned!(span=> ::std::option::Option::Some(#v))
        }
    }
}

/// `Variant` → `Type::Variant`; a path is used as written.
fn variant(ty: &Type, e: &Expr) -> TokenStream {
    let span = e.span();
    if let Expr::Path(p) = e
        && let Some(id) = p.path.get_ident()
    {
        return quote_spanned!(span=> <#ty>::#id);
    }
    quote_spanned!(span=> #e)
}

fn option_inner(ty: &Type) -> Option<&Type> {
    let Type::Path(p) = ty else { return None };
    let seg = p.path.segments.last()?;
    let PathArguments::AngleBracketed(args) = &seg.arguments else { return None };
    match args.args.first()? {
        GenericArgument::Type(t) => Some(t),
        _ => None,
    }
}
