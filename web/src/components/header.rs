//! The mode header at the top of the TNC screen.

use yew::prelude::*;

use schwenkbar_app::i18n::Lang;

#[derive(Properties, PartialEq)]
pub struct HeaderProps {
    pub lang: Lang,
    /// The selected machine's name.
    pub machine: AttrValue,
    /// The operating mode (Programmieren, Programmlauf …).
    pub mode: AttrValue,
    /// Show the link to the course (not inside a lesson).
    #[prop_or_default]
    pub course_link: bool,
}

#[function_component(Header)]
pub fn header(props: &HeaderProps) -> Html {
    let l = props.lang;
    html! {
        <header class="mode-header">
            <span class="mode" data-testid="mode">{ props.mode.clone() }</span>
            <span class="title">{ "Schwenkbar" }</span>
            <span class="subtitle">{ l.t("Bearbeitungsebene schwenken", "Tilting the working plane") }</span>
            <span class="machine" data-testid="machine-name">{ props.machine.clone() }</span>
            if props.course_link {
                <a class="course-link" href="kurs.html" data-testid="course-link">{ l.t("Kurs", "Course") }</a>
            }
        </header>
    }
}
