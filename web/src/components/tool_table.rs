//! The shop's tool table on the machine editor page: one row per tool with the control's
//! columns (T, NAME, L, R, R2, DL, DR, TYP, T-ANGLE), each cell's problem under its row, and
//! the table's commands (new row, import and export of `TOOL.T`, back to the shipped table).
//! State and checks in [`schwenkbar_app::tool_table::ToolTableState`]; this only renders and dispatches.

use web_sys::HtmlInputElement;
use yew::prelude::*;

use super::machine_editor::{Editor, on_file};
use schwenkbar_app::editor::EditorAction;
use schwenkbar_app::i18n::Lang;
use schwenkbar_app::tool_table::{COLUMNS, ToolAction, heading};

#[derive(Properties, PartialEq)]
pub struct Props {
    pub state: UseReducerHandle<Editor>,
    pub lang: Lang,
}

#[function_component(ToolTable)]
pub fn tool_table(props: &Props) -> Html {
    let (state, l) = (&props.state, props.lang);
    let tools = &state.tools;
    let send = |a: ToolAction| {
        let state = state.clone();
        Callback::from(move |_: MouseEvent| state.dispatch(EditorAction::Tools(a.clone())))
    };
    let on_import = on_file(state, |bytes| EditorAction::Tools(ToolAction::Import(bytes)));
    let cell = |row: usize, column: usize, value: &str| {
        let oninput = {
            let state = state.clone();
            Callback::from(move |e: InputEvent| {
                if let Some(i) = e.target_dyn_into::<HtmlInputElement>() {
                    state.dispatch(EditorAction::Tools(ToolAction::Set { row, column, text: i.value() }));
                }
            })
        };
        let bad = tools.issue_at(row, column).is_some();
        let label = format!("{} {}", COLUMNS[column], row + 1);
        html! {
            <td class={classes!(bad.then_some("bad"))}>
                <input type="text" value={value.to_owned()} {oninput} spellcheck="false"
                    aria-label={label} aria-invalid={bad.to_string()} data-cell={format!("{row}:{column}")} />
            </td>
        }
    };
    let rows = tools.rows.iter().enumerate().map(|(i, row)| {
        let issues: Vec<Html> = (0..COLUMNS.len())
            .filter_map(|c| tools.issue_at(i, c).map(|m| (c, m)))
            .map(|(c, m)| html! { <p class="ed-issue" role="alert">{ format!("{}: {}", COLUMNS[c], m.get(l)) }</p> })
            .collect();
        html! {
            <>
                <tr data-row={i.to_string()}>
                    { for row.iter().enumerate().map(|(c, v)| cell(i, c, v)) }
                    <td><button type="button" data-action="remove-tool" onclick={send(ToolAction::RemoveRow(i))}
                        aria-label={format!("{} {}", l.t("Zeile entfernen", "Remove row"), i + 1)}>{ "✕" }</button></td>
                </tr>
                if !issues.is_empty() { <tr class="issues"><td colspan="10">{ for issues }</td></tr> }
            </>
        }
    });
    let status = if tools.own {
        l.t("Eigene Werkzeugtabelle: der Trainer rechnet mit ihr", "Own tool table: the trainer uses it")
    } else {
        l.t(
            "Mitgelieferte Werkzeugtabelle: eine Änderung oder ein Import macht sie zur eigenen",
            "Shipped tool table: an edit or an import makes it your own",
        )
    };
    html! {
        <section class="tools" aria-label={l.t("Werkzeugtabelle", "Tool table")}>
            <h2>{ l.t("Werkzeugtabelle (TOOL.T)", "Tool table (TOOL.T)") }</h2>
            <p class="status" data-own={tools.own.to_string()}>{ status }</p>
            if let Some(m) = &tools.message { <p class="message" role="status">{ m.get(l).to_owned() }</p> }
            <div class="tool-commands">
                <button type="button" data-action="add-tool" onclick={send(ToolAction::AddRow)}>{ l.t("NEUE ZEILE", "NEW ROW") }</button>
                <label class="button" data-action="import-tools">{ l.t("IMPORT TOOL.T", "IMPORT TOOL.T") }
                    <input type="file" accept=".t,.T,text/plain" class="file-input" onchange={on_import} />
                </label>
                <button type="button" data-action="export-tools" onclick={send(ToolAction::Export)}>{ l.t("EXPORT TOOL.T", "EXPORT TOOL.T") }</button>
                <button type="button" data-action="shipped-tools" onclick={send(ToolAction::UseShipped)}>{ l.t("MITGELIEFERTE TABELLE", "SHIPPED TABLE") }</button>
            </div>
            <table>
                <thead><tr>
                    { for (0..COLUMNS.len()).map(|c| html! { <th title={heading(c).get(l).to_owned()}>{ COLUMNS[c] }</th> }) }
                    <th></th>
                </tr></thead>
                <tbody>{ for rows }</tbody>
            </table>
        </section>
    }
}
