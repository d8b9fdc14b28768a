//! The course progress kept in the browser: per lesson whether it was opened and which
//! exercises were solved, plus the language and the instructor view. A short text format
//! (`k1;de;0;1:3,0:0,…`) read by hand, so a corrupt or old record is recognised and reported.

use super::lessons::COUNT;
use crate::i18n::{Lang, Text};

/// localStorage key.
pub const KEY: &str = "schwenkbar.kurs";
const VERSION: &str = "k1";

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LessonProgress {
    pub visited: bool,
    /// Bit i set = exercise i solved.
    pub solved: u8,
}

impl LessonProgress {
    #[must_use]
    pub fn solved_count(self) -> u32 {
        self.solved.count_ones()
    }
}

#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Progress {
    pub lang: Lang,
    pub instructor: bool,
    pub lessons: [LessonProgress; COUNT],
}

/// Why a saved record was not used.
pub const UNREADABLE: Text = Text::new(
    "Gespeicherter Kursfortschritt war unlesbar und wurde zurückgesetzt",
    "The saved course progress could not be read and was reset",
);

impl Progress {
    #[must_use]
    pub fn to_text(&self) -> String {
        let lessons: Vec<String> =
            self.lessons.iter().map(|l| format!("{}:{}", u8::from(l.visited), l.solved)).collect();
        format!("{VERSION};{};{};{}", self.lang.code(), u8::from(self.instructor), lessons.join(","))
    }

    /// Reads a saved record; `Err` for anything not written by [`Progress::to_text`].
    pub fn from_text(text: &str) -> Result<Progress, Text> {
        let parts: Vec<&str> = text.split(';').collect();
        let [VERSION, lang, instructor, lessons] = parts.as_slice() else { return Err(UNREADABLE) };
        let lang = match *lang {
            "de" => Lang::De,
            "en" => Lang::En,
            _ => return Err(UNREADABLE),
        };
        let instructor = match *instructor {
            "0" => false,
            "1" => true,
            _ => return Err(UNREADABLE),
        };
        let mut out = Progress { lang, instructor, lessons: [LessonProgress::default(); COUNT] };
        let items: Vec<&str> = lessons.split(',').collect();
        if items.len() != COUNT {
            return Err(UNREADABLE);
        }
        for (slot, item) in out.lessons.iter_mut().zip(items) {
            let (v, s) = item.split_once(':').ok_or(UNREADABLE)?;
            slot.visited = match v {
                "0" => false,
                "1" => true,
                _ => return Err(UNREADABLE),
            };
            slot.solved = s.parse().map_err(|_| UNREADABLE)?;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_and_corrupt_records() {
        let mut p = Progress { lang: Lang::En, instructor: true, ..Progress::default() };
        p.lessons[0] = LessonProgress { visited: true, solved: 0b101 };
        p.lessons[10].visited = true;
        assert_eq!(Progress::from_text(&p.to_text()), Ok(p));
        for bad in [
            "",
            "{\"lessons\":[]}",
            "k1;fr;0;",
            "k2;de;0;0:0",
            "k1;de;0;0:0,0:0",
            "k1;de;2;0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0",
            "k1;de;0;0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:999",
        ] {
            assert_eq!(Progress::from_text(bad), Err(UNREADABLE), "{bad}");
        }
    }
}
