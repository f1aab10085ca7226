//! `#[derive(Component)]`: the `Part`, `Component`, `Interfaces`, `Slot`, `Remap`
//! and `PanelPart` impls of a struct; `Part`, `Interfaces`, `Slot`, `Remap` and
//! `From` of an enum of parts.

use crate::internals::component::{ComponentEnum, ComponentStruct, Model, parse};
use proc_macro2::TokenStream;
use quote::{quote, quote_spanned};
use syn::DeriveInput;
use syn::spanned::Spanned;

pub fn derive(input: &DeriveInput) -> TokenStream {
    let ident = &input.ident;
    let (impl_g, ty_g, where_g) = input.generics.split_for_impl();
    let p = quote!(::garmentcode::__private);
    match parse(input) {
        Ok(Model::Struct(m)) => derive_struct(input, &m),
        Ok(Model::Enum(m)) => derive_enum(input, &m),
        Err(e) => {
            let err = e.to_compile_error();
            let never = super::placeholder_body();
            quote! {
                #err
                #[automatically_derived]
                impl #impl_g #p::Part for #ident #ty_g #where_g {
                    fn node(&self) -> #p::Node<'_> { #never }
                }
            }
        }
    }
}

/// `where` clause of the `Remap` impl: the struct's own plus `T: Remap` for every
/// type parameter.
fn remap_where(input: &DeriveInput) -> TokenStream {
    let p = quote!(::garmentcode::__private);
    let mut preds: Vec<TokenStream> = Vec::new();
    if let Some(w) = &input.generics.where_clause {
        preds.extend(w.predicates.iter().map(|pr| quote!(#pr)));
    }
    for t in input.generics.type_params() {
        let t = &t.ident;
        preds.push(quote!(#t: #p::Remap));
    }
    if preds.is_empty() { quote!() } else { quote!(where #(#preds),*) }
}

fn derive_struct(input: &DeriveInput, model: &ComponentStruct) -> TokenStream {
    let ident = &input.ident;
    let (impl_g, ty_g, where_g) = input.generics.split_for_impl();
    let p = quote!(::garmentcode::__private);

    // Interfaces and slots.
    let listed: Vec<TokenStream> = model
        .interfaces
        .iter()
        .map(|i| {
            let (f, n) = (&i.ident, &i.name);
            if i.optional {
                quote!(if let ::std::option::Option::Some(i) = self.#f { v.push((#n, i)); })
            } else {
                quote!(v.push((#n, self.#f));)
            }
        })
        .collect();
    let slots: Vec<TokenStream> = model
        .interfaces
        .iter()
        .filter_map(|i| {
            let marker = i.slot.as_ref()?;
            let f = &i.ident;
            Some(quote_spanned! {i.ty.span()=>
                #[automatically_derived]
                impl #impl_g #p::Slot<#marker> for #ident #ty_g #where_g {
                    fn slot(&self) -> #p::InterfaceId { self.#f }
                }
            })
        })
        .collect();
    let interfaces = quote! {
        #[automatically_derived]
        impl #impl_g #p::Interfaces for #ident #ty_g #where_g {
            fn interfaces(&self) -> ::std::vec::Vec<(&'static str, #p::InterfaceId)> {
                let mut v = ::std::vec::Vec::new();
                #(#listed)*
                v
            }
        }
        #(#slots)*
    };

    // Copies: fields holding ids follow the copy, the others are cloned.
    let mut remapped: Vec<TokenStream> = Vec::new();
    let role_fields = model
        .panel
        .iter()
        .chain(&model.parts)
        .chain(&model.stitches)
        .map(|f| (&f.ident, &f.ty))
        .chain(model.interfaces.iter().map(|i| (&i.ident, &i.ty)));
    for (f, ty) in role_fields {
        remapped.push(quote_spanned!(ty.span()=> #f: #p::Remap::remap(&self.#f, a, map)));
    }
    for f in &model.plain {
        let (name, ty) = (&f.ident, &f.ty);
        remapped.push(if f.holds_ids {
            quote_spanned!(ty.span()=> #name: #p::Remap::remap(&self.#name, a, map))
        } else {
            quote_spanned!(ty.span()=> #name: ::std::clone::Clone::clone(&self.#name))
        });
    }
    let remap_where = remap_where(input);
    let remap = quote! {
        #[automatically_derived]
        impl #impl_g #p::Remap for #ident #ty_g #remap_where {
            fn remap(&self, a: &mut #p::Arena, map: &mut #p::IdMap) -> Self {
                Self { #(#remapped),* }
            }
        }
    };

    if let Some(panel) = &model.panel {
        let f = &panel.ident;
        return quote! {
            #[automatically_derived]
            impl #impl_g #p::Part for #ident #ty_g #where_g {
                fn node(&self) -> #p::Node<'_> { #p::Node::Panel(self.#f) }
            }
            #[automatically_derived]
            impl #impl_g #p::PanelPart for #ident #ty_g #where_g {
                fn panel_id(&self) -> #p::PanelId { self.#f }
            }
            #interfaces
            #remap
        };
    }
    let visits: Vec<TokenStream> = model
        .parts
        .iter()
        .map(|f| {
            let (name, ty) = (&f.ident, &f.ty);
            quote_spanned!(ty.span()=> #p::Parts::visit_parts(&self.#name, f);)
        })
        .collect();
    let name = match &model.name {
        Some(syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(n), .. })) => quote!(::std::string::String::from(#n)),
        Some(e) => quote!(::std::string::ToString::to_string(&(#e))),
        None => {
            let s = ident.to_string();
            quote!(::std::string::String::from(#s))
        }
    };
    let stitches = match &model.stitches {
        Some(f) => {
            let (name, ty) = (&f.ident, &f.ty);
            quote_spanned!(ty.span()=> ::std::clone::Clone::clone(&self.#name))
        }
        None => quote!(::std::vec::Vec::new()),
    };
    let length = model.length.as_ref().map(|path| {
        quote! {
            fn length(&self, a: &#p::Arena) -> f64 { #path(self, a) }
        }
    });
    quote! {
        #[automatically_derived]
        impl #impl_g #p::Part for #ident #ty_g #where_g {
            fn node(&self) -> #p::Node<'_> { #p::Node::Component(self) }
        }
        #[automatically_derived]
        impl #impl_g #p::Component for #ident #ty_g #where_g {
            fn name(&self) -> ::std::string::String { #name }
            fn for_each_part(&self, f: &mut dyn FnMut(&dyn #p::Part)) {
                #(#visits)*
            }
            fn stitches(&self) -> ::std::vec::Vec<#p::StitchRule> { #stitches }
            #length
        }
        #interfaces
        #remap
    }
}

fn derive_enum(input: &DeriveInput, model: &ComponentEnum) -> TokenStream {
    let ident = &input.ident;
    let (impl_g, ty_g, where_g) = input.generics.split_for_impl();
    let p = quote!(::garmentcode::__private);
    let node_arms = model.variants.iter().map(|v| {
        let (name, ty) = (&v.ident, &v.ty);
        quote_spanned!(ty.span()=> Self::#name(x) => #p::Part::node(x))
    });
    let remap_arms = model.variants.iter().map(|v| {
        let (name, ty) = (&v.ident, &v.ty);
        quote_spanned!(ty.span()=> Self::#name(x) => Self::#name(#p::Remap::remap(x, a, map)))
    });
    let iface_arms = model.variants.iter().map(|v| {
        let (name, ty) = (&v.ident, &v.ty);
        quote_spanned!(ty.span()=> Self::#name(x) => #p::Interfaces::interfaces(x))
    });
    let slots = model.slots.iter().map(|marker| {
        let arms = model.variants.iter().map(|v| {
            let (name, ty) = (&v.ident, &v.ty);
            quote_spanned!(ty.span()=> Self::#name(x) => <#ty as #p::Slot<#marker>>::slot(x))
        });
        quote! {
            #[automatically_derived]
            impl #impl_g #p::Slot<#marker> for #ident #ty_g #where_g {
                fn slot(&self) -> #p::InterfaceId {
                    match self { #(#arms,)* }
                }
            }
        }
    });
    // `From` for each part type that only one variant holds.
    let type_key = |t: &syn::Type| quote!(#t).to_string();
    let froms =
        model.variants.iter().filter(|v| model.variants.iter().filter(|w| type_key(&w.ty) == type_key(&v.ty)).count() == 1).map(|v| {
            let (name, ty) = (&v.ident, &v.ty);
            quote! {
                #[automatically_derived]
                impl #impl_g ::std::convert::From<#ty> for #ident #ty_g #where_g {
                    fn from(x: #ty) -> Self { Self::#name(x) }
                }
            }
        });
    let remap_where = remap_where(input);
    quote! {
        #[automatically_derived]
        impl #impl_g #p::Part for #ident #ty_g #where_g {
            fn node(&self) -> #p::Node<'_> {
                match self { #(#node_arms,)* }
            }
        }
        #[automatically_derived]
        impl #impl_g #p::Remap for #ident #ty_g #remap_where {
            fn remap(&self, a: &mut #p::Arena, map: &mut #p::IdMap) -> Self {
                match self { #(#remap_arms,)* }
            }
        }
        #[automatically_derived]
        impl #impl_g #p::Interfaces for #ident #ty_g #where_g {
            fn interfaces(&self) -> ::std::vec::Vec<(&'static str, #p::InterfaceId)> {
                match self { #(#iface_arms,)* }
            }
        }
        #(#slots)*
        #(#froms)*
    }
}
