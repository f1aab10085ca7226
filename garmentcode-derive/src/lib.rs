//! Derive macros for [`garmentcode`](https://docs.rs/garmentcode): typed design
//! parameters (`Params`, `Choice`) and components (`Component`, `#[component]`).
//!
//! Shaped like `serde_derive`: attributes are parsed into a model that keeps spans
//! (`internals`), validated with errors at the author's tokens, then code is
//! generated (`expand`). Generated code names the runtime crate through its hidden
//! re-export `::garmentcode::__private`, so authors depend on `garmentcode` alone.
//! On an error the macro emits the error plus a minimal impl, so one mistake does not
//! cascade into unrelated errors.
//!
//! The macros are used through their re-exports in `garmentcode`, whose docs have
//! a runnable example of each: [`garmentcode::Params`](../garmentcode/derive.Params.html),
//! [`garmentcode::Choice`](../garmentcode/derive.Choice.html),
//! [`garmentcode::Component`](../garmentcode/derive.Component.html) and
//! [`garmentcode::component`](../garmentcode/attr.component.html).

mod expand;
mod internals;

use proc_macro::TokenStream;
use syn::{DeriveInput, parse_macro_input};

/// Design-parameter group: every field is a parameter (`#[param(default = ..)]`
/// with `range`, `options`, `prob`, `rename`) or a nested group.
///
/// # Parameters
///
/// A field with `default`, `range`, `options` or `prob` is one parameter; its doc
/// comment is its description:
///
/// - `default = ..`: a number, `true`/`false`, a variant of the field's enum
///   (`Plain`), or `None` for an `Option<Enum>`;
/// - `range = lo..=hi` (f64, i64) or `options = [a, b, ..]` (numbers);
/// - `prob = p`: the probability that sampling keeps the default, in `[0, 1]`;
/// - `rename = ".."`: the key in design files;
/// - `null_option = false`: leave `null` out of the written options of an `Option`.
///
/// # Nested groups and per-instance overrides
///
/// A field without those keys is a nested group (a type deriving `Params`; `rename`
/// applies). One group type can serve several places of a design, each place
/// changing some of its parameters with `field(..)` entries on the group field:
///
/// - `field(default = ..)`, `field(range = lo..=hi)`, `field(prob = p)` or
///   `field(prob = None)`, `field(doc = "..")`: a new default, range, sampling
///   probability or description of the parameter `field` of this instance (an enum
///   default is written as a path, `Enum::Variant`);
/// - `field(skip)`: this instance leaves the parameter (or a nested group) out of
///   its schema; the value stays at the group's default;
/// - `group(field(..))`: an override of a parameter of a nested group.
///
/// `#[param(skip)]` on a group field leaves the whole group out of the schema (so out
/// of sampling and of the design files read with it); its values stay at the group's
/// defaults and are reachable by path, and the group's own `describe` still gives its
/// parameters to a larger space that adds them.
///
/// Overrides change the schema, the defaults and sampling of that instance only.
/// They are checked while compiling, at the override's tokens: a field name the
/// group does not have, a default outside the (possibly new) range, a fractional
/// default of an i64, a probability outside `[0, 1]`, a range on a non-numeric
/// parameter, a default, range or probability on a nested group.
///
/// ```
/// use garmentcode::Params;
/// use garmentcode::Value;
///
/// /// A sleeve cuff.
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Cuff {
///     /// Gathering of the sleeve into the cuff.
///     #[param(range = 1..=3, default = 1)]
///     top_ruffle: f64,
///     /// Cuff length as a fraction of the arm.
///     #[param(range = 0.05..=0.9, default = 0.1, prob = 0.7)]
///     len: f64,
///     /// Flare of the cuff.
///     #[param(range = 1..=2, default = 1.2)]
///     flare: f64,
/// }
///
/// /// A sleeve.
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Sleeve {
///     /// Direction of the opening.
///     #[param(range = -0.9..=0.8, default = 0.1, prob = 1.0)]
///     opening: f64,
///     /// Its cuff.
///     cuff: Cuff,
/// }
///
/// /// Both sleeves: one group type, the left one with other defaults.
/// #[derive(Clone, Debug, PartialEq, Params)]
/// struct Design {
///     /// The right sleeve.
///     right: Sleeve,
///     /// The left sleeve.
///     #[param(
///         opening(default = 0.2, doc = "Direction of the left opening."),
///         cuff(top_ruffle(range = 1..=2), len(prob = None), flare(skip))
///     )]
///     left: Sleeve,
/// }
///
/// let d = Design::defaults();
/// assert_eq!((d.right.opening, d.left.opening), (0.1, 0.2));
/// let space = Design::design_space();
/// let spec = |path: &str| space.params().iter().find(|p| p.path == path).unwrap().clone();
/// assert_eq!(spec("left.opening").default, Value::Float(0.2));
/// assert_eq!(spec("left.cuff.top_ruffle").range.to_string(), "[1.0, 2.0]");
/// assert_eq!(spec("right.cuff.top_ruffle").range.to_string(), "[1.0, 3.0]");
/// assert_eq!((spec("left.cuff.len").default_prob, spec("right.cuff.len").default_prob), (None, Some(0.7)));
/// assert_eq!(spec("left.opening").description, "Direction of the left opening.");
/// assert!(space.params().iter().all(|p| p.path != "left.cuff.flare"));
/// assert_eq!(space.params().len(), 8 - 1);
/// ```
///
/// Implements the trait `garmentcode::Params`. A shorter example:
/// [`garmentcode::Params`](../garmentcode/derive.Params.html).
#[proc_macro_derive(Params, attributes(param))]
pub fn derive_params(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::params::derive(&input).into()
}

/// Categorical parameter: an enum of unit variants, each an option
/// (`#[param(rename = "..")]` to change its name in design files).
///
/// Implements the trait `garmentcode::Choice`. Example:
/// [`garmentcode::Choice`](../garmentcode/derive.Choice.html).
#[proc_macro_derive(Choice, attributes(param))]
pub fn derive_choice(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::choice::derive(&input).into()
}

/// Garment component (or panel class): `#[part]` sub-parts in assembly order,
/// `#[panel]` for a panel class, `#[interface]` fields, `#[stitches]`. On an enum
/// of parts (one part per variant), `#[component(slots(Top, ..))]` lists the slots
/// every variant fills.
///
/// Implements `garmentcode`'s part traits (`Part`, `Remap`, `Interfaces`, `Slot`, and
/// `PanelPart` or `Component`). Example, struct and enum forms:
/// [`garmentcode::Component`](../garmentcode/derive.Component.html).
#[proc_macro_derive(Component, attributes(part, panel, interface, stitches, component))]
pub fn derive_component(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as DeriveInput);
    expand::component::derive(&input).into()
}

/// `#[component]` on a struct: shorthand for `#[derive(Component)]`, with optional
/// arguments `name = "..."` and `length = path::to_fn`.
///
/// Example: [`garmentcode::component`](../garmentcode/attr.component.html).
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
    fn params_with_overrides() {
        insta::assert_snapshot!(pretty(
            expand::params::derive,
            r#"
            struct Left {
                #[param(opening(default = 0.2), cuff(top_ruffle(range = 1..=2), kind(default = Some(CuffKind::Band), prob = None)), length(skip))]
                sleeve: Sleeve,
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
