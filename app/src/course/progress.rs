//! The course progress kept in the browser: per lesson whether it was opened and which
//! exercises were solved, as one versioned text record (`k2;lessons=1:3,0:0,…`, see
//! [`crate::persist`]), so a corrupt or old record is recognised and reported. The language and
//! the instructor view are the preferences both pages share ([`crate::persist::Prefs`]).

use super::lessons::COUNT;
use crate::i18n::Text;
use crate::persist::{RestoreError, read_flag, read_record, write_record};

const KIND: char = 'k';
const VERSION: u32 = 2;

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
        write_record(KIND, VERSION, &[("lessons", &lessons.join(","))])
    }

    /// Reads a saved record; `Err` for anything not written by [`Progress::to_text`]. The
    /// first layout (`k1;de;0;…`, language and instructor view inside) still gives its lessons:
    /// a trainee's solved exercises are work, not a setting.
    pub fn from_text(text: &str) -> Result<Progress, Text> {
        let lessons = match read_record(text, KIND, VERSION, ["lessons"]) {
            Ok([lessons]) => lessons,
            Err(RestoreError::OldVersion) => match text.split(';').collect::<Vec<_>>().as_slice() {
                ["k1", _lang, _instructor, lessons] => (*lessons).to_owned(),
                _ => return Err(UNREADABLE),
            },
            Err(RestoreError::Corrupt) => return Err(UNREADABLE),
        };
        let mut out = Progress::default();
        let items: Vec<&str> = lessons.split(',').collect();
        if items.len() != COUNT {
            return Err(UNREADABLE);
        }
        for (slot, item) in out.lessons.iter_mut().zip(items) {
            let (v, s) = item.split_once(':').ok_or(UNREADABLE)?;
            slot.visited = read_flag(v).map_err(|_| UNREADABLE)?;
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
        let mut p = Progress::default();
        p.lessons[0] = LessonProgress { visited: true, solved: 0b101 };
        p.lessons[10].visited = true;
        assert_eq!(Progress::from_text(&p.to_text()), Ok(p.clone()));
        assert!(p.to_text().starts_with("k2;lessons=1:5,0:0,"), "{}", p.to_text());
        for bad in [
            "",
            "{\"lessons\":[]}",
            "{kaputt",
            "k1;fr;0",
            "k3;lessons=0:0",
            "k2;lessons=0:0,0:0",
            "k2;lessons=2:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0",
            "k2;lessons=0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:999",
        ] {
            assert_eq!(Progress::from_text(bad), Err(UNREADABLE), "{bad}");
        }
    }

    #[test]
    fn the_first_layout_keeps_its_lessons() {
        let old = "k1;en;1;1:3,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,0:0,1:0";
        let p = Progress::from_text(old).expect("k1 is read");
        assert_eq!(p.lessons[0], LessonProgress { visited: true, solved: 3 });
        assert!(p.lessons[10].visited);
    }
}
