//! Derive macros for [`garmentcode`](https://docs.rs/garmentcode): typed design
//! parameters (`Params`, `Choice`) and components (`Component`, `#[component]`).
//!
//! Shaped like `serde_derive`: attributes are parsed into a model that keeps spans
//! ([`internals`]), validated with errors at the author's tokens, then code is
//! generated ([`expand`]). Generated code names the runtime crate through its hidden
//! re-export `::garmentcode::__private`, so authors depend on `garmentcode` alone.
//! On an error the macro emits the error plus a minimal impl, so one mistake does not
//! cascade into unrelated errors.

mod expand;
mod internals;

use proc_macro::TokenStream;
use syn::{DeriveInput, parse_macro_input};

/// Design-parameter group: every field is a parameter (`#[param(default = ..)]`
/// with `range`, `options`, `prob`, `rename`) or a nested group.
#[proc_macro_derive(Params, attributes(param))]
pub fn derive_params(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::params::derive(&input).into()
}

/// Categorical parameter: an enum of unit variants, each an option
/// (`#[param(rename = "..")]` to change its name in design files).
#[proc_macro_derive(Choice, attributes(param))]
pub fn derive_choice(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::choice::derive(&input).into()
}

/// Garment component (or panel class): `#[part]` sub-parts in assembly order,
/// `#[panel]` for a panel class, `#[interface]` fields, `#[stitches]`.
#[proc_macro_derive(Component, attributes(part, panel, interface, stitches, component))]
pub fn derive_component(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::component::derive(&input).into()
}

/// `#[component]` on a struct: shorthand for `#[derive(Component)]`, with optional
/// arguments `name = "..."` and `length = path::to_fn`.
#[proc_macro_attribute]
pub fn component(args: TokenStream, item: TokenStream) -> TokenStream {
    let args = proc_macro2::TokenStream::from(args);
    let item = proc_macro2::TokenStream::from(item);
    let attr = if args.is_empty() { quote::quote!() } else { quote::quote!(#[component(#args)]) };
    quote::quote!(
        #[derive(::garmentcode::Component)]
        #attr
        #item
    )
    .into()
}

/// Expansion snapshots: what each derive generates for a small input.
#[cfg(test)]
mod expansion {
    use super::expand;
    use proc_macro2::TokenStream;
    use syn::DeriveInput;

    fn pretty(f: fn(&DeriveInput) -> TokenStream, src: &str) -> String {
        let input: DeriveInput = syn::parse_str(src).expect("valid input");
        let file: syn::File = syn::parse2(f(&input)).expect("the expansion parses");
        prettyplease::unparse(&file)
    }

    #[test]
    fn params() {
        insta::assert_snapshot!(pretty(
            expand::params::derive,
            r#"
            struct Skirt {
                /// Length as a fraction of the leg.
                #[param(range = -0.2..=0.95, default = 0.2)]
                length: f64,
                /// Number of gores.
                #[param(options = [4, 6, 8], default = 4, prob = 0.5)]
                panels: i64,
                /// Hem finish.
                #[param(default = None, prob = 0.3, null_option = false)]
                hem: Option<Hem>,
                #[param(rename = "flare-skirt")]
                flare: Flare,
            }
            "#
        ));
    }

    #[test]
    fn choice() {
        insta::assert_snapshot!(pretty(
            expand::choice::derive,
            r#"
            enum Hem {
                Plain,
                #[param(rename = "rolled-hem")]
                Rolled,
            }
            "#
        ));
    }

    #[test]
    fn component() {
        insta::assert_snapshot!(pretty(
            expand::component::derive,
            r#"
            #[component(name = self.name, length = Self::skirt_length)]
            struct Skirt {
                name: String,
                #[part]
                front: PanelId,
                #[part]
                cuffs: Vec<Cuff>,
                #[interface]
                top: InterfaceId,
                #[interface(rename = "in")]
                in_: Option<InterfaceId>,
                #[stitches]
                stitches: Vec<StitchRule>,
            }
            "#
        ));
    }

    #[test]
    fn panel_class() {
        insta::assert_snapshot!(pretty(
            expand::component::derive,
            r#"
            struct Band {
                #[panel]
                panel: PanelId,
                #[interface]
                top: InterfaceId,
            }
            "#
        ));
    }

    #[test]
    fn component_enum() {
        insta::assert_snapshot!(pretty(
            expand::component::derive,
            r#"
            #[component(slots(Top))]
            enum Bottom {
                Circle(SkirtCircle),
                Pants(Pants),
            }
            "#
        ));
    }

    #[test]
    fn error_comes_with_a_stub_impl() {
        insta::assert_snapshot!(pretty(
            expand::params::derive,
            r#"
            struct Bad {
                #[param(range = 2..=1, default = 1)]
                n: i64,
            }
            "#
        ));
    }
}
