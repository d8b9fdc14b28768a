//! The course (issue 8): eleven lessons from the seed chapters, each with a live view and
//! exercises the core checks; an overview; an instructor view; progress kept in the browser.
//! Routes: `#kurs` (overview), `#kurs/N` (lesson N, 1-based).

pub mod bench;
pub mod lab;
pub mod lessons;
pub mod positioning;
pub mod progress;
pub mod state;
pub mod texts;

/// Where the URL fragment points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Route {
    Overview,
    /// 0-based lesson index.
    Lesson(usize),
}

impl Route {
    /// The route of a URL fragment (with or without `#`); `None` = the trainer.
    #[must_use]
    pub fn parse(fragment: &str) -> Option<Route> {
        let f = fragment.trim_start_matches('#');
        let rest = f.strip_prefix("kurs").or_else(|| f.strip_prefix("course"))?;
        match rest.trim_start_matches('/') {
            "" => Some(Route::Overview),
            n => match n.parse::<usize>() {
                Ok(n) if (1..=lessons::COUNT).contains(&n) => Some(Route::Lesson(n - 1)),
                // A lesson that does not exist (an old link): the overview, not a dead page.
                _ => Some(Route::Overview),
            },
        }
    }

    /// The fragment for this route, without `#`.
    #[must_use]
    pub fn fragment(self) -> String {
        match self {
            Route::Overview => "kurs".to_owned(),
            Route::Lesson(i) => format!("kurs/{}", i + 1),
        }
    }

    /// The next page for a presenter remote: overview → lesson 1 → … → lesson 11 (stays).
    #[must_use]
    pub fn next(self) -> Route {
        match self {
            Route::Overview => Route::Lesson(0),
            Route::Lesson(i) => Route::Lesson((i + 1).min(lessons::COUNT - 1)),
        }
    }

    /// The previous page: lesson 1 → overview.
    #[must_use]
    pub fn prev(self) -> Route {
        match self {
            Route::Overview | Route::Lesson(0) => Route::Overview,
            Route::Lesson(i) => Route::Lesson(i - 1),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn routes_round_trip_and_bad_numbers_fall_back_to_the_overview() {
        assert_eq!(Route::parse("#kurs"), Some(Route::Overview));
        assert_eq!(Route::parse("kurs/3"), Some(Route::Lesson(2)));
        assert_eq!(Route::parse("#course/11"), Some(Route::Lesson(10)));
        assert_eq!(Route::parse("#kurs/12"), Some(Route::Overview));
        assert_eq!(Route::parse("#kurs/x"), Some(Route::Overview));
        assert_eq!(Route::parse("#pgm=abc"), None);
        assert_eq!(Route::parse(""), None);
        for i in 0..lessons::COUNT {
            assert_eq!(Route::parse(&Route::Lesson(i).fragment()), Some(Route::Lesson(i)));
        }
        assert_eq!(Route::Lesson(10).next(), Route::Lesson(10));
        assert_eq!(Route::Lesson(0).prev(), Route::Overview);
        assert_eq!(Route::Overview.next(), Route::Lesson(0));
    }
}
