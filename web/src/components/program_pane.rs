//! The NC program: a virtualised list of the whole program (only the lines in sight are in
//! the DOM, so a 1,000,000-block program scrolls), syntax colours, the parser's diagnostics at
//! their line, a click selects a block, the cursor block stays in sight. With "edit as text" on,
//! a text area holds the program (a window of it around the caret for a big one) and every
//! change is parsed (only where it changed).

use std::ops::Range;

use web_sys::HtmlTextAreaElement;
use yew::prelude::*;

use schwenkbar_app::document::{DocRef, Document, byte_of_utf16, utf16_of_byte};
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::syntax::highlight;

/// Lines drawn beyond the visible ones, above and below.
const OVERSCAN: usize = 4;
/// Lines drawn at most (a pane without its stylesheet is as tall as its content).
const MAX_ROWS: usize = 160;
/// Where lines wrap (projector mode), a program of up to this many lines is drawn whole, in the
/// page's flow, and the cursor is brought into sight by the lines' real positions; elsewhere,
/// and for a longer program, the list is virtualised, one line a row (drawing all lines cost a
/// keystroke 4× the time).
const WHOLE_LINES: usize = 400;
/// The list's tallest scroll height in px: browsers cap an element's height (Firefox near
/// 17.9 million px); beyond it the scroll position maps to lines in proportion.
const MAX_HEIGHT: f64 = 8_000_000.0;

#[derive(Properties, PartialEq)]
pub struct ProgramPaneProps {
    pub doc: DocRef,
    pub cursor: usize,
    pub lang: Lang,
    pub text_editing: bool,
    /// Long lines wrap (projector mode): a short program is drawn whole (`WHOLE_LINES`).
    #[prop_or_default]
    pub wrap: bool,
    pub on_select: Callback<usize>,
    /// The editor's window, bytes `.0` of the program, now reads `.1`.
    pub on_edit: Callback<(Range<usize>, String)>,
}

#[function_component(ProgramPane)]
pub fn program_pane(props: &ProgramPaneProps) -> Html {
    let l = props.lang;
    let doc = &props.doc;
    let title = l.t("NC-Programm", "NC program");
    let summary = doc.summary(l);
    let class = classes!("program-pane", props.text_editing.then_some("editing"));
    html! {
        <section {class} aria-label={title}>
            <div class="pane-title">{ title }<span class="summary">{ summary }</span></div>
            if props.text_editing {
                <ProgramText doc={doc.clone()} cursor={props.cursor} lang={l} on_edit={props.on_edit.clone()} />
                { diagnostics_list(doc, 0, usize::MAX, l) }
            } else {
                <ProgramList doc={doc.clone()} cursor={props.cursor} lang={l} wrap={props.wrap} on_select={props.on_select.clone()} />
            }
        </section>
    }
}

#[derive(Properties, PartialEq)]
struct TextProps {
    doc: DocRef,
    cursor: usize,
    lang: Lang,
    on_edit: Callback<(Range<usize>, String)>,
}

/// The text area, uncontrolled: its own typing is not written back into it; a document from
/// elsewhere (a sample, an import) is. It holds the window of the program around the caret
/// (all of it up to `WHOLE_UP_TO` lines, `app/src/document/window.rs`): a 4 MB text area costs
/// the browser seconds of layout per keystroke.
#[function_component(ProgramText)]
fn program_text(props: &TextProps) -> Html {
    let area = use_node_ref();
    let typed = use_mut_ref(|| false);
    // The bytes of the program the text area holds.
    let window = use_mut_ref(|| 0..0);
    let shown = use_state_eq(|| None::<(usize, usize)>);
    let follow = {
        let (area, window, shown) = (area.clone(), window.clone(), shown.clone());
        move |doc: &Document, fresh: Option<usize>| {
            let Some(area) = area.cast::<HtmlTextAreaElement>() else { return };
            let mut window = window.borrow_mut();
            let caret = |end: bool| {
                let units = if end { area.selection_end() } else { area.selection_start() };
                let value = area.value();
                window.start + byte_of_utf16(&value, units.ok().flatten().unwrap_or(0) as usize)
            };
            let (line, selection) = match fresh {
                Some(line) => (line, None),
                None => {
                    let (from, to) = (caret(false), caret(true));
                    if !doc.window_moves(&window, from) {
                        return;
                    }
                    (doc.line_of(from), Some((from, to)))
                }
            };
            let next = doc.window_at(line);
            let (old_first, new_first) = (doc.line_of(window.start), doc.line_of(next.start));
            // Reading the scroll position lays the text area out: with a pasted program in it,
            // 5 s for 100,000 lines. Then the caret's line is put near the top instead.
            let pasted = doc.window_oversized(&window);
            let top = if pasted { 0.0 } else { f64::from(area.scroll_top()) };
            let text = &doc.text[next.clone()];
            area.set_value(text);
            let lines = doc.line_of(next.end).saturating_sub(new_first).max(1);
            let line_px = f64::from(area.scroll_height()) / lines as f64;
            if let Some((from, to)) = selection {
                // The caret and the selection stay where they were in the program, and on screen.
                let unit =
                    |at: usize| utf16_of_byte(text, at.clamp(next.start, next.end) - next.start) as u32;
                let _ = area.set_selection_range(unit(from), unit(to));
                let at = if pasted {
                    doc.line_of(to).saturating_sub(new_first + 3) as f64 * line_px
                } else {
                    top + (old_first as f64 - new_first as f64) * line_px
                };
                area.set_scroll_top(at.max(0.0) as i32);
            } else if next.start > 0 {
                // Opened at the cursor block: the caret at its start, a few lines below the top.
                let unit = utf16_of_byte(text, doc.line_start(line) - next.start) as u32;
                let _ = area.set_selection_range(unit, unit);
                let above = (line - new_first).saturating_sub(3);
                area.set_scroll_top((above as f64 * line_px) as i32);
            }
            let whole = next.start == 0 && next.end == doc.text.len();
            shown.set((!whole).then(|| (new_first + 1, doc.line_of(next.end.saturating_sub(1)) + 1)));
            *window = next;
        }
    };
    {
        let (typed, follow) = (typed.clone(), follow.clone());
        let line = props.doc.block_lines(props.cursor).map_or(0, |(first, _)| first);
        use_effect_with(props.doc.clone(), move |doc| {
            let fresh = !std::mem::take(&mut *typed.borrow_mut());
            follow(doc, fresh.then_some(line));
        });
    }
    let oninput = {
        let (on_edit, typed, window) = (props.on_edit.clone(), typed.clone(), window.clone());
        Callback::from(move |e: InputEvent| {
            if let Some(area) = e.target_dyn_into::<HtmlTextAreaElement>() {
                *typed.borrow_mut() = true;
                let text = area.value();
                let at = window.borrow().clone();
                *window.borrow_mut() = at.start..at.start + text.len();
                on_edit.emit((at, text));
            }
        })
    };
    // The caret moved by a key or a click: the window follows it.
    let on_caret = {
        let doc = props.doc.clone();
        move || follow(&doc, None)
    };
    let onkeyup = {
        let on_caret = on_caret.clone();
        Callback::from(move |_: KeyboardEvent| on_caret())
    };
    let onmouseup = Callback::from(move |_: MouseEvent| on_caret());
    let l = props.lang;
    html! {
        <>
            if let Some((first, last)) = *shown {
                <div class="text-window">{ format!(
                    "{} {first}–{last} {} {} · {}",
                    l.t("Zeilen", "Lines"),
                    l.t("von", "of"),
                    props.doc.line_count(),
                    l.t("der Ausschnitt folgt dem Cursor", "the window follows the cursor"),
                ) }</div>
            }
            <textarea class="program-text" spellcheck="false" ref={area} {oninput} {onkeyup} {onmouseup}
                aria-label={l.t("Programmtext", "Program text")} />
        </>
    }
}

#[derive(Properties, PartialEq)]
struct ListProps {
    doc: DocRef,
    cursor: usize,
    lang: Lang,
    wrap: bool,
    on_select: Callback<usize>,
}

/// The scroller's size and position and the height of a line, px (measured after a render).
#[derive(Clone, Copy, PartialEq)]
struct View {
    top: f64,
    height: f64,
    line: f64,
}

impl View {
    /// Lines that fit.
    fn rows(&self) -> usize {
        ((self.height / self.line).ceil() as usize).min(MAX_ROWS)
    }

    /// The scroll height of `lines` lines.
    fn total(&self, lines: usize) -> f64 {
        (lines as f64 * self.line).min(MAX_HEIGHT)
    }

    /// The first line in sight at scroll position `top`.
    fn first(&self, lines: usize, top: f64) -> usize {
        let (total, room) = (self.total(lines), lines.saturating_sub(self.rows()) as f64);
        let at =
            if total < MAX_HEIGHT { top / self.line } else { top / (total - self.height).max(1.0) * room };
        (at.max(0.0) as usize).min(lines.saturating_sub(1))
    }

    /// The scroll position that shows line `line` first.
    fn top_of(&self, lines: usize, line: usize) -> f64 {
        let total = self.total(lines);
        if total < MAX_HEIGHT {
            line as f64 * self.line
        } else {
            line as f64 / lines.saturating_sub(self.rows()).max(1) as f64 * (total - self.height)
        }
    }
}

/// Marks the first moment the program's lines are in the page (`performance.mark`): the cold
/// load's "program shown" that scripts/cold_load.py measures (issue 29).
fn mark_program_shown(lines: usize) {
    thread_local!(static MARKED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) });
    if lines > 0
        && !MARKED.with(|m| m.replace(true))
        && let Some(p) = web_sys::window().and_then(|w| w.performance())
    {
        let _ = p.mark("schwenkbar:program-shown");
    }
}

#[function_component(ProgramList)]
fn program_list(props: &ListProps) -> Html {
    let scroller = use_node_ref();
    let view = use_state_eq(|| View { top: 0.0, height: 600.0, line: 21.0 });
    let doc = &props.doc;
    let lines = doc.line_count();
    let whole = props.wrap && lines <= WHOLE_LINES;
    let (cur_first, cur_last) = doc.block_lines(props.cursor).unwrap_or((0, 0));
    {
        // Measures the scroller and a line, and brings the cursor block into sight (a third of
        // the way down) when it moved out of it.
        let (scroller, view) = (scroller.clone(), view.clone());
        use_effect_with((props.cursor, doc.clone(), whole), move |_| {
            let Some(el) = scroller.cast::<web_sys::Element>() else { return };
            mark_program_shown(lines);
            if whole {
                reveal_drawn(&el, cur_first, cur_last);
                return;
            }
            // The line's real height, fractions kept (22.5 px at 15 px type): a rounded one
            // drifted the drawn lines off the spacer by half a pixel a line.
            let line = el
                .query_selector(".line")
                .ok()
                .flatten()
                .map_or(0.0, |l| l.get_bounding_client_rect().height());
            let mut v =
                View { top: f64::from(el.scroll_top()), height: f64::from(el.client_height()), ..*view };
            if line > 0.0 {
                v.line = line;
            }
            let first = v.first(lines, v.top);
            if cur_first < first || cur_last + 1 > first + v.rows().saturating_sub(1) {
                el.set_scroll_top(v.top_of(lines, cur_first.saturating_sub(v.rows() / 3)).round() as i32);
                // What the browser took: near the end it stops at the last full page, and lines
                // drawn for the asked position left the page's upper part blank.
                v.top = f64::from(el.scroll_top());
            }
            view.set(v);
        });
    }
    let onscroll = {
        let view = view.clone();
        // A whole-drawn list has nothing to redraw when it scrolls.
        let virtual_list = !whole;
        Callback::from(move |e: Event| {
            if let Some(el) = e.target_dyn_into::<web_sys::Element>().filter(|_| virtual_list) {
                view.set(View {
                    top: f64::from(el.scroll_top()),
                    height: f64::from(el.client_height()),
                    ..*view
                });
            }
        })
    };
    let v = *view;
    let (first, last) = if whole {
        (0, lines)
    } else {
        (
            v.first(lines, v.top).saturating_sub(OVERSCAN),
            (v.first(lines, v.top) + v.rows() + OVERSCAN).min(lines),
        )
    };
    // The list stands where its first line belongs (in proportion: at the scroll position).
    let offset = if v.total(lines) < MAX_HEIGHT {
        first as f64 * v.line
    } else {
        v.top - (v.first(lines, v.top) - first) as f64 * v.line
    };
    // Diagnostics come in line order: those of the drawn lines by binary search.
    let diags = &doc.diagnostics;
    let shown = &diags[diags.partition_point(|d| (d.line as usize) < first + 1)..];
    let shown = &shown[..shown.partition_point(|d| (d.line as usize) <= last)];
    let l = props.lang;
    let rows = (first..last).map(|i| {
        let block = doc.block_at_line(i);
        let current = (cur_first..=cur_last).contains(&i) && block == Some(props.cursor);
        // An error outranks a warning on the same line (a missing block number must not hide
        // why the control refuses the block).
        let on_line = || shown.iter().filter(|d| d.line as usize == i + 1);
        let diag = on_line().find(|d| d.is_error()).or_else(|| on_line().next());
        let mut class = classes!("line");
        if current {
            class.push("cursor");
        }
        if let Some(d) = diag {
            class.push(if d.is_error() { "has-error" } else { "has-warning" });
        }
        let onclick = block.map(|b| props.on_select.reform(move |_: MouseEvent| b));
        let pieces = highlight(doc.line(i), doc.comment_continues(i));
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
        <div class="lines" ref={scroller} {onscroll}>
            if whole {
                <ol class="blocks whole">{ for rows }</ol>
            } else {
                <div class="spacer" style={format!("height:{}px", v.total(lines))} />
                <ol class="blocks" style={format!("top:{offset}px")} start={(first + 1).to_string()}>{ for rows }</ol>
            }
        </div>
    }
}

/// Scrolls the scroller `el` of a whole-drawn list so that the lines `first..=last` (0-based)
/// are in sight, a third of the way down when they were not, by their drawn positions.
fn reveal_drawn(el: &web_sys::Element, first: usize, last: usize) {
    let line = |i: usize| el.query_selector(&format!(".line[data-line='{}']", i + 1)).ok().flatten();
    let (Some(a), Some(b)) = (line(first), line(last)) else { return };
    let pane = el.get_bounding_client_rect();
    let height = f64::from(el.client_height());
    let (top, bottom) =
        (a.get_bounding_client_rect().top() - pane.top(), b.get_bounding_client_rect().bottom() - pane.top());
    if top < 0.0 || bottom > height {
        el.set_scroll_top((f64::from(el.scroll_top()) + top - height / 3.0).round() as i32);
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
                    { doc.where_label(d.line, l) }{ d.message(l) }
                </li>
            }) }
        </ul>
    }
}
