//! `#[derive(Choice)]`: option names of a categorical parameter.

use crate::internals::param::parse_enum;
use proc_macro2::TokenStream;
use quote::quote;
use syn::DeriveInput;

pub fn derive(input: &DeriveInput) -> TokenStream {
    let ident = &input.ident;
    let p = quote!(::garmentcode::__private);
    let model = match parse_enum(input) {
        Ok(m) => m,
        Err(e) => {
            let err = e.to_compile_error();
            let never = super::placeholder_body();
            return quote! {
                #err
                #[automatically_derived]
                impl #p::Choice for #ident {
                    const NAMES: &'static [&'static str] = &[];
                    fn name(&self) -> &'static str { #never }
                    fn from_name(_: &str) -> ::std::option::Option<Self> { #never }
                }
            };
        }
    };
    let names: Vec<&String> = model.variants.iter().map(|(_, n)| n).collect();
    let idents: Vec<&syn::Ident> = model.variants.iter().map(|(i, _)| i).collect();
    quote! {
        #[automatically_derived]
        impl #p::Choice for #ident {
            const NAMES: &'static [&'static str] = &[#(#names),*];
            fn name(&self) -> &'static str {
                match self { #(#ident::#idents => #names,)* }
            }
            fn from_name(name: &str) -> ::std::option::Option<Self> {
                match name {
                    #(#names => ::std::option::Option::Some(#ident::#idents),)*
                    _ => ::std::option::Option::None,
                }
            }
        }
    }
}
