//! UI language: the core's [`Lang`] (German first), and [`Text`], a German/English pair for
//! every string the UI shows.

pub use schwenkbar_core::Lang;

/// A text in German and English.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Text {
    pub de: &'static str,
    pub en: &'static str,
}

impl Text {
    #[must_use]
    pub const fn new(de: &'static str, en: &'static str) -> Text {
        Text { de, en }
    }

    #[must_use]
    pub fn get(self, lang: Lang) -> &'static str {
        lang.t(self.de, self.en)
    }
}
