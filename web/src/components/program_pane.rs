//! The NC program: the lines around the cursor block (like the control's program display, and
//! fast for programs of 100,000 blocks), syntax colours, the parser's diagnostics at their line,
//! a click selects a block. With "edit as text" on, a text area holds the whole program and
//! every change is parsed at once.

use std::rc::Rc;

use web_sys::HtmlTextAreaElement;
use yew::prelude::*;

use crate::document::Document;
use crate::i18n::Lang;
use crate::syntax::highlight;

/// Lines shown above the cursor block and in all.
const ABOVE: usize = 12;
const WINDOW: usize = 48;

#[derive(Properties, PartialEq)]
pub struct ProgramPaneProps {
    pub doc: Rc<Document>,
    pub cursor: usize,
    pub lang: Lang,
    pub text_editing: bool,
    pub on_select: Callback<usize>,
    pub on_text: Callback<String>,
}

#[function_component(ProgramPane)]
pub fn program_pane(props: &ProgramPaneProps) -> Html {
    let l = props.lang;
    let doc = &props.doc;
    let title = l.t("NC-Programm", "NC program");
    let summary = match (doc.error_count(), doc.diagnostics.len()) {
        (0, 0) => l.t("keine Fehler", "no errors").to_owned(),
        (e, n) => format!("{e} {} · {} {}", l.t("Fehler", "errors"), n - e, l.t("Warnungen", "warnings")),
    };
    if props.text_editing {
        let on_text = props.on_text.clone();
        let oninput = Callback::from(move |e: InputEvent| {
            if let Some(area) = e.target_dyn_into::<HtmlTextAreaElement>() {
                on_text.emit(area.value());
            }
        });
        return html! {
            <section class="program-pane editing" aria-label={title}>
                <div class="pane-title">{ title }<span class="summary">{ summary }</span></div>
                <textarea class="program-text" spellcheck="false" value={doc.text.clone()} {oninput}
                    aria-label={l.t("Programmtext", "Program text")} />
                { diagnostics_list(doc, 0, usize::MAX, l) }
            </section>
        };
    }
    let (cur_first, cur_last) = doc.block_lines(props.cursor).unwrap_or((0, 0));
    let first = cur_first.saturating_sub(ABOVE);
    let last = (first + WINDOW).min(doc.line_count());
    let rows = (first..last).map(|i| {
        let block = doc.block_at_line(i);
        let current = (cur_first..=cur_last).contains(&i) && block == Some(props.cursor);
        let diag = doc.diagnostics.iter().find(|d| d.line as usize == i + 1);
        let mut class = classes!("line");
        if current {
            class.push("cursor");
        }
        if let Some(d) = diag {
            class.push(if d.is_error() { "has-error" } else { "has-warning" });
        }
        let onclick = block.map(|b| props.on_select.reform(move |_: MouseEvent| b));
        let pieces = highlight(doc.line(i));
        html! {
            <li {class} {onclick} data-line={(i + 1).to_string()} aria-current={current.then_some("true")}>
                { for pieces.into_iter().map(|(c, s)| html! { <span class={c.css()}>{ s }</span> }) }
                if let Some(d) = diag {
                    <span class="diag-inline">{ d.message(l) }</span>
                }
            </li>
        }
    });
    html! {
        <section class="program-pane" aria-label={title}>
            <div class="pane-title">{ title }<span class="summary">{ summary }</span></div>
            <ol class="blocks">{ for rows }</ol>
        </section>
    }
}

/// The diagnostics of lines `from..to` (1-based) as a list under the text area.
fn diagnostics_list(doc: &Document, from: usize, to: usize, l: Lang) -> Html {
    let items = doc.diagnostics.iter().filter(|d| (from..=to).contains(&(d.line as usize))).take(50);
    html! {
        <ul class="diag-list">
            { for items.map(|d| html! {
                <li class={if d.is_error() { "error" } else { "warning" }}>
                    { format!("{}:{} ", d.line, d.column) }{ d.message(l) }
                </li>
            }) }
        </ul>
    }
}
