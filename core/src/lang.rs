//! The UI's two languages and the one bilingual text type used by core, app, web and cli.

use std::borrow::Cow;

use serde::{Deserialize, Serialize};

/// Language of a message and of the UI. German is the default: the trainees are mostly
/// German-speaking machinists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
pub enum Lang {
    #[default]
    De,
    En,
}

impl Lang {
    /// Picks the text for this language.
    #[must_use]
    pub fn t<'a>(self, de: &'a str, en: &'a str) -> &'a str {
        match self {
            Lang::De => de,
            Lang::En => en,
        }
    }

    #[must_use]
    pub fn other(self) -> Lang {
        match self {
            Lang::De => Lang::En,
            Lang::En => Lang::De,
        }
    }

    /// The HTML `lang` code.
    #[must_use]
    pub fn code(self) -> &'static str {
        self.t("de", "en")
    }
}

/// A text in German and English: a `const` for the static texts ([`Text::new`]), owned for the
/// texts with numbers or names in them ([`Text::owned`]).
/// As JSON `{"de": …, "en": …}` (machine files: no other fields).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Text {
    pub de: Cow<'static, str>,
    pub en: Cow<'static, str>,
}

impl Text {
    #[must_use]
    pub const fn new(de: &'static str, en: &'static str) -> Text {
        Text { de: Cow::Borrowed(de), en: Cow::Borrowed(en) }
    }

    #[must_use]
    pub fn owned(de: String, en: String) -> Text {
        Text { de: Cow::Owned(de), en: Cow::Owned(en) }
    }

    /// The same words in both languages (NC words, numbers).
    #[must_use]
    pub fn same(text: impl Into<Cow<'static, str>>) -> Text {
        let text = text.into();
        Text { de: text.clone(), en: text }
    }

    /// Not inlined: a hundred call sites in the trainer would each carry the two `Cow` derefs
    /// (measured: the bundle is smaller with one out-of-line copy).
    #[must_use]
    #[inline(never)]
    pub fn get(&self, lang: Lang) -> &str {
        lang.t(&self.de, &self.en)
    }
}
