//! Code generation for each derive.

pub mod choice;
pub mod component;
pub mod params;

use proc_macro2::TokenStream;
use quote::quote;

/// Body of the placeholder impls emitted beside a derive's `compile_error!`
/// (as `serde_derive` does): they keep uses of the type from adding unrelated
/// errors, and a crate that contains them never compiles, so they never run.
pub fn placeholder_body() -> TokenStream {
    quote!(::core::unreachable!("placeholder beside a derive error; the crate does not compile"))
}
