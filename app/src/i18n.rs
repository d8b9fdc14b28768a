//! UI language: the core's [`Lang`] (German first) and [`Text`], the German/English pair of
//! every string the UI shows.

pub use schwenkbar_core::{Lang, Text};
