//! `#[derive(Component)]`: the `Part`, `Component`, `Interfaces` and `Slot` impls.

use crate::internals::component::parse;
use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

pub fn derive(input: &DeriveInput) -> TokenStream {
    let ident = &input.ident;
    let (impl_g, ty_g, where_g) = input.generics.split_for_impl();
    let p = quote!(::garmentcode::__private);
    let model = match parse(input) {
        Ok(m) => m,
        Err(e) => {
            let err = e.to_compile_error();
            let never = super::placeholder_body();
            return quote! {
                #err
                impl #impl_g #p::Part for #ident #ty_g #where_g {
                    fn node(&self) -> #p::Node<'_> { #never }
                }
            };
        }
    };
    let names: Vec<&String> = model.interfaces.iter().map(|i| &i.name).collect();
    let lookups: Vec<TokenStream> = model
        .interfaces
        .iter()
        .map(|i| {
            let (f, n) = (&i.ident, &i.name);
            if i.optional { quote!(#n => self.#f) } else { quote!(#n => ::std::option::Option::Some(self.#f)) }
        })
        .collect();
    let slots: Vec<TokenStream> = model
        .interfaces
        .iter()
        .filter_map(|i| {
            let marker = i.slot.as_ref()?;
            let f = &i.ident;
            Some(quote! {
                impl #impl_g #p::Slot<#marker> for #ident #ty_g #where_g {
                    fn slot(&self) -> #p::InterfaceId { self.#f }
                }
            })
        })
        .collect();
    let interfaces = quote! {
        impl #impl_g #p::Interfaces for #ident #ty_g #where_g {
            fn interface(&self, name: &str) -> ::std::option::Option<#p::InterfaceId> {
                match name {
                    #(#lookups,)*
                    _ => ::std::option::Option::None,
                }
            }
            fn interface_names(&self) -> &'static [&'static str] {
                &[#(#names),*]
            }
        }
        #(#slots)*
    };
    if let Some(panel) = &model.panel {
        return quote! {
            impl #impl_g #p::Part for #ident #ty_g #where_g {
                fn node(&self) -> #p::Node<'_> { #p::Node::Panel(self.#panel) }
            }
            #interfaces
        };
    }
    let parts = &model.parts;
    let name = match &model.name {
        Some(syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(n), .. })) => quote!(::std::string::String::from(#n)),
        Some(e) => quote!(::std::string::ToString::to_string(&(#e))),
        None => {
            let s = ident.to_string();
            quote!(::std::string::String::from(#s))
        }
    };
    let stitches = match &model.stitches {
        Some(f) => quote!(self.#f.clone()),
        None => quote!(::std::vec::Vec::new()),
    };
    let length = model.length.as_ref().map(|path| {
        quote! {
            fn length(&self, a: &#p::Arena) -> f64 { #path(self, a) }
        }
    });
    quote! {
        impl #impl_g #p::Part for #ident #ty_g #where_g {
            fn node(&self) -> #p::Node<'_> { #p::Node::Component(self) }
        }
        impl #impl_g #p::Component for #ident #ty_g #where_g {
            fn name(&self) -> ::std::string::String { #name }
            fn for_each_part(&self, f: &mut dyn FnMut(&dyn #p::Part)) {
                #( #p::Parts::visit_parts(&self.#parts, f); )*
            }
            fn stitches(&self) -> ::std::vec::Vec<#p::StitchRule> { #stitches }
            #length
        }
        #interfaces
    }
}
