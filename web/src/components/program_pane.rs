//! The NC program: the lines around the cursor block (like the control's program display, and
//! fast for programs of 100,000 blocks), syntax colours, the parser's diagnostics at their line,
//! a click selects a block. With "edit as text" on, a text area holds the whole program and
//! every change is parsed at once.

use std::rc::Rc;

use web_sys::HtmlTextAreaElement;
use yew::prelude::*;

use schwenkbar_app::document::Document;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::syntax::highlight;

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
    let pane = use_node_ref();
    {
        // The cursor block stays in sight however the lines wrap (large type on a projector).
        let pane = pane.clone();
        use_effect(move || {
            if let Some(pane) = pane.cast::<web_sys::Element>() {
                keep_cursor_in_sight(&pane);
            }
        });
    }
    let l = props.lang;
    let doc = &props.doc;
    let title = l.t("NC-Programm", "NC program");
    let summary = summary(doc.error_count(), doc.diagnostics.len() - doc.error_count(), l);
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
        // An error outranks a warning on the same line (a missing block number must not hide
        // why the control refuses the block).
        let on_line = || doc.diagnostics.iter().filter(|d| d.line as usize == i + 1);
        let diag = on_line().find(|d| d.is_error()).or_else(|| on_line().next());
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
        <section class="program-pane" aria-label={title} ref={pane}>
            <div class="pane-title">{ title }<span class="summary">{ summary }</span></div>
            <ol class="blocks">{ for rows }</ol>
        </section>
    }
}

/// Scrolls the pane (only the pane, never the page around it) so that the cursor block's
/// lines are inside it, a third of the way down if they were not.
fn keep_cursor_in_sight(pane: &web_sys::Element) {
    let Ok(Some(first)) = pane.query_selector(".line.cursor") else { return };
    let mut last = first.clone();
    while let Some(next) = last.next_element_sibling().filter(|n| n.matches(".cursor").unwrap_or(false)) {
        last = next;
    }
    let (view, top, bottom) =
        (pane.get_bounding_client_rect(), first.get_bounding_client_rect(), last.get_bounding_client_rect());
    if top.top() < view.top() || bottom.bottom() > view.bottom() {
        let offset = top.top() - view.top() - view.height() / 3.0;
        pane.set_scroll_top(pane.scroll_top() + offset as i32);
    }
}

/// "2 Fehler · 1 Warnung": counts with the word in the right number.
fn summary(errors: usize, warnings: usize, l: Lang) -> String {
    let count = |n: usize, one: (&str, &str), many: (&str, &str)| {
        let (de, en) = if n == 1 { one } else { many };
        format!("{n} {}", l.t(de, en))
    };
    match (errors, warnings) {
        (0, 0) => l.t("keine Fehler", "no errors").to_owned(),
        (e, 0) => count(e, ("Fehler", "error"), ("Fehler", "errors")),
        (0, w) => count(w, ("Warnung", "warning"), ("Warnungen", "warnings")),
        (e, w) => format!(
            "{} · {}",
            count(e, ("Fehler", "error"), ("Fehler", "errors")),
            count(w, ("Warnung", "warning"), ("Warnungen", "warnings"))
        ),
    }
}

/// Where a diagnostic is, as the control names it: the block number written in the program
/// ("Satz 1: "), else the line of a block without a number ("Zeile 3: ").
fn where_label(doc: &Document, line: u32, l: Lang) -> String {
    let number = doc
        .block_at_line((line as usize).saturating_sub(1))
        .and_then(|b| doc.program.blocks.get(b))
        .and_then(|b| b.number());
    match number {
        Some(n) => format!("{} {n}: ", l.t("Satz", "Block")),
        None => format!("{} {line}: ", l.t("Zeile", "Line")),
    }
}

/// The diagnostics of lines `from..to` (1-based) as a list under the text area.
fn diagnostics_list(doc: &Document, from: usize, to: usize, l: Lang) -> Html {
    let items = doc.diagnostics.iter().filter(|d| (from..=to).contains(&(d.line as usize))).take(50);
    html! {
        <ul class="diag-list">
            { for items.map(|d| html! {
                <li class={if d.is_error() { "error" } else { "warning" }}
                    title={format!("{} {}, {} {}", l.t("Zeile", "line"), d.line, l.t("Spalte", "column"), d.column)}>
                    { where_label(doc, d.line, l) }{ d.message(l) }
                </li>
            }) }
        </ul>
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_agree_with_their_number() {
        assert_eq!(summary(0, 0, Lang::De), "keine Fehler");
        assert_eq!(summary(0, 1, Lang::De), "1 Warnung");
        assert_eq!(summary(1, 2, Lang::De), "1 Fehler · 2 Warnungen");
        assert_eq!(summary(2, 1, Lang::En), "2 errors · 1 warning");
        assert_eq!(summary(1, 0, Lang::En), "1 error");
    }

    #[test]
    fn a_diagnostic_is_placed_by_its_block_number() {
        let doc = Document::new("0 BEGIN PGM T MM\n1 PLANE SPATIAL SPA+400 SPB+0 SPC+0 STAY\nL X+1\n".into());
        let error = doc.diagnostics.iter().find(|d| d.is_error()).expect("SPA+400 is refused");
        assert_eq!(where_label(&doc, error.line, Lang::De), "Satz 1: ");
        assert_eq!(where_label(&doc, 3, Lang::En), "Line 3: ", "a block without a number");
    }
}
