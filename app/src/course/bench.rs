//! What lesson 5's bench draws besides the "why" texts, as plain data: the seed table rows'
//! names (what each row shows), the master axis gauge (limit switches, symmetry point, start,
//! both candidates on a dial) and the 3D view's state (chosen solution, the other as the ghost).

use glam::DMat3;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::course::SeedRow;
use schwenkbar_core::machine::{Limits, Machine};
use schwenkbar_core::plane::RotaryAxis;
use schwenkbar_core::solve::{
    Exclusion, Explanation, Rule, SolveError, SolveOptions, axis_word, axis_words, solve_block,
};

use super::lab::{Bench, LabForm, option_word};
use crate::i18n::Lang;
use crate::scene::SceneState;

/// Paths differ when they differ by more than this (degrees).
const PATH_TOL: f64 = 1e-6;

/// A seed table row named by what it shows, e.g. "SYM+ ab C-105: wählt A+45 statt A-45, obwohl
/// der Weg länger ist". Derived from the row's data and the solver's answer for it: the option,
/// what differs from the bench's default set-up (machine, start, limit switches), and which
/// candidate the control takes and why (or why it refuses).
#[must_use]
pub fn row_name(row: &SeedRow, l: Lang) -> String {
    let Ok(machine) = Machine::builtin(row.machine) else {
        return format!("{} {}", l.t("Zeile", "Row"), row.number);
    };
    let mut head = match option_word(row.block.selection) {
        "" => l.t("ohne SEQ/SYM", "no SEQ/SYM").to_owned(),
        word => word.to_owned(),
    };
    if row.machine != LabForm::default().machine {
        let [s, m] = machine.joints();
        let (s, m) = (s.axis.letter(), m.axis.letter());
        head.push_str(&match l {
            Lang::De => format!(" auf der {s}/{m}-Maschine"),
            Lang::En => format!(" on the {s}/{m} machine"),
        });
    }
    let moved: Vec<String> = machine
        .joints()
        .iter()
        .filter_map(|j| row.start.get(j.axis).filter(|v| v.abs() > PATH_TOL).map(|v| axis_word(j.axis, v)))
        .collect();
    if !moved.is_empty() {
        head.push_str(&format!(" {} {}", l.t("ab", "from"), moved.join(" ")));
    }
    for (axis, lim) in &row.limits {
        head.push_str(&format!(
            " {} {} … {}",
            l.t("mit Endschalter", "with limit switches"),
            axis_word(*axis, lim.min),
            axis_word(*axis, lim.max)
        ));
    }
    let opts = SolveOptions { start: row.start, limits: row.limits.clone(), ..SolveOptions::default() };
    let outcome = match solve_block(&machine, &row.block, DMat3::IDENTITY, &opts) {
        Ok(e) => outcome(&e, l),
        Err(e) => e.message().get(l).to_owned(),
    };
    format!("{head}: {outcome}")
}

/// Which candidate the control takes and why, in a few words.
fn outcome(e: &Explanation, l: Lang) -> String {
    let word = |i: usize| e.candidates.get(i).map_or_else(String::new, |c| axis_word(e.master, c.master));
    // One template per case, German and English: `{c}` the chosen (or refused) master value,
    // `{o}` the other, `{r}` the control's message.
    let (template, c, o) = match e.chosen {
        None => {
            let template = match e.error {
                Some(SolveError::AxisOutOfLimit { .. }) => {
                    ("{c} hinter dem Endschalter – {r}", "{c} beyond the limit switch – {r}")
                }
                Some(SolveError::NoSolutionOnSide { .. }) => {
                    ("keine Lösung auf dieser Seite – {r}", "no solution on that side – {r}")
                }
                _ => ("{r}", "{r}"),
            };
            let c = match e.error {
                Some(SolveError::AxisOutOfLimit { axis, value, .. }) => axis_word(axis, value),
                _ => String::new(),
            };
            (template, c, String::new())
        }
        Some(chosen) => match e.candidates.iter().enumerate().find(|(i, _)| *i != chosen) {
            None => (("nur eine Lösung: {c}", "only one solution: {c}"), word(chosen), String::new()),
            Some((other, o)) => {
                let longer = e.candidates[chosen].path > o.path + PATH_TOL;
                let template = match (e.rule, o.excluded) {
                    (Rule::SeqNearer { .. }, _) => (
                        "beide auf dieser Seite – die nähere {c} statt {o}",
                        "both on that side – the nearer {c} rather than {o}",
                    ),
                    (_, Some(Exclusion::OutOfLimits(_))) => {
                        ("nur {c} innerhalb der Endschalter", "only {c} within the limit switches")
                    }
                    (_, Some(Exclusion::LongerPath { .. })) => {
                        ("kürzerer Weg – {c} statt {o}", "shorter path – {c} rather than {o}")
                    }
                    (_, Some(Exclusion::LostTie { .. })) => (
                        "gleich weit – {c} statt {o} (Annahme)",
                        "equal paths – {c} rather than {o} (assumption)",
                    ),
                    _ if longer => (
                        "wählt {c} statt {o}, obwohl der Weg länger ist",
                        "chooses {c} rather than {o}, though the path is longer",
                    ),
                    _ => ("wählt {c} statt {o}", "chooses {c} rather than {o}"),
                };
                (template, word(chosen), word(other))
            }
        },
    };
    let refused = e.error_message.map(|m| m.0.message());
    let refused = refused.as_ref().map_or("", |m| m.get(l));
    l.t(template.0, template.1).replace("{c}", &c).replace("{o}", &o).replace("{r}", refused)
}

/// The gauge's dial: a circle in SVG coordinates (y down). The master axis angle θ sits at
/// `(cx + r·sin θ, cy − r·cos θ)`: 0° at the top, positive angles clockwise, so a value reads like
/// the axis' own turn, and the two candidates mirror about the symmetry point's radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dial {
    pub cx: f64,
    pub cy: f64,
    pub r: f64,
}

/// The bench's dial (the SVG's `viewBox` is [`GAUGE_VIEW`]).
pub const DIAL: Dial = Dial { cx: 150.0, cy: 112.0, r: 72.0 };
/// `viewBox` of the gauge's SVG.
pub const GAUGE_VIEW: &str = "0 0 300 224";

impl Dial {
    /// The point at angle `deg` on a circle of radius `radius` about the dial's centre.
    #[must_use]
    pub fn point(&self, deg: f64, radius: f64) -> (f64, f64) {
        let t = deg.to_radians();
        (self.cx + radius * t.sin(), self.cy - radius * t.cos())
    }

    /// An SVG path along the dial from `from` clockwise to `to` (degrees, `to ≥ from`); a span of
    /// 360° or more is the whole circle (two half arcs, SVG cannot draw one full arc).
    #[must_use]
    pub fn arc(&self, from: f64, to: f64) -> String {
        let span = (to - from).max(0.0);
        let (x0, y0) = self.point(from, self.r);
        if span >= 360.0 - 1e-9 {
            let (x1, y1) = self.point(from + 180.0, self.r);
            let r = self.r;
            return format!("M{x0:.2} {y0:.2}A{r} {r} 0 1 1 {x1:.2} {y1:.2}A{r} {r} 0 1 1 {x0:.2} {y0:.2}");
        }
        let (x1, y1) = self.point(from + span, self.r);
        let large = u8::from(span > 180.0);
        format!("M{x0:.2} {y0:.2}A{r} {r} 0 {large} 1 {x1:.2} {y1:.2}", r = self.r)
    }

    /// Where a label for `deg` goes (just outside the dial) and its `text-anchor`.
    #[must_use]
    pub fn label(&self, deg: f64, radius: f64) -> ((f64, f64), &'static str) {
        let (x, y) = self.point(deg, radius);
        let s = deg.to_radians().sin();
        let anchor = if s > 0.25 {
            "start"
        } else if s < -0.25 {
            "end"
        } else {
            "middle"
        };
        // Text hangs from its baseline: move labels below the centre down by a line's part.
        let dy = if y > self.cy { 10.0 } else { 0.0 };
        ((x, y + dy), anchor)
    }
}

/// One value on the gauge.
#[derive(Debug, Clone, PartialEq)]
pub struct GaugeMark {
    pub value: f64,
    /// The control's word for it, e.g. `A-45`.
    pub word: String,
    /// On the dial.
    pub at: (f64, f64),
    pub label_at: (f64, f64),
    pub anchor: &'static str,
}

/// A candidate's master value on the gauge.
#[derive(Debug, Clone, PartialEq)]
pub struct CandidateMark {
    pub mark: GaugeMark,
    pub chosen: bool,
    /// Beyond a limit switch.
    pub out_of_limits: bool,
}

/// The master axis gauge, ready to draw.
#[derive(Debug, Clone, PartialEq)]
pub struct Gauge {
    pub axis: RotaryAxis,
    /// The traverse range along the dial (the whole circle without limit switches).
    pub allowed: String,
    /// The rest of the circle, beyond the limit switches (`None` without limits).
    pub forbidden: Option<String>,
    /// The two limit switches, min then max (`None` without limit switches).
    pub limits: Option<[GaugeMark; 2]>,
    /// The symmetry point (the diameter through it is drawn as the mirror line: the two
    /// candidates lie mirrored about it).
    pub symmetry: GaugeMark,
    pub start: GaugeMark,
    pub candidates: Vec<CandidateMark>,
}

impl Gauge {
    /// The gauge of a master axis with `limits` (the effective ones), symmetry point, start value
    /// and the candidates' `(master value, chosen)`.
    #[must_use]
    pub fn new(
        axis: RotaryAxis,
        limits: Option<Limits>,
        symmetry: f64,
        start: f64,
        candidates: &[(f64, bool)],
    ) -> Gauge {
        let d = DIAL;
        let mark = |value: f64, on: f64, label: f64| {
            let (label_at, anchor) = d.label(value, label);
            GaugeMark { value, word: axis_word(axis, value), at: d.point(value, on), label_at, anchor }
        };
        let limits = limits.filter(|l| l.min.is_finite() && l.max.is_finite() && l.min < l.max);
        let bounded = limits.filter(|l| l.max - l.min < 360.0);
        let near_limit = |value: f64| {
            let apart = |a: f64, b: f64| ((a - b).rem_euclid(360.0) + 180.0).rem_euclid(360.0) - 180.0;
            limits.is_some_and(|l| apart(value, l.min).abs() < 8.0 || apart(value, l.max).abs() < 8.0)
        };
        let (allowed, forbidden) = match bounded {
            Some(l) => (d.arc(l.min, l.max), Some(d.arc(l.max, l.min + 360.0))),
            None => (d.arc(0.0, 360.0), None),
        };
        Gauge {
            axis,
            allowed,
            forbidden,
            limits: limits.map(|l| {
                let (mut min, mut max) = (mark(l.min, d.r, d.r + 16.0), mark(l.max, d.r, d.r + 16.0));
                // Limit switches a whole turn apart (−180 … +180) meet on the dial: their labels
                // move apart, each away from the range it ends.
                if ((l.max - l.min) % 360.0).abs() < 1e-6 {
                    let apart = |value: f64| {
                        let (label_at, _) = d.label(value, d.r + 16.0);
                        (label_at, if label_at.0 > d.cx { "start" } else { "end" })
                    };
                    (min.label_at, min.anchor) = apart(l.min - 6.0);
                    (max.label_at, max.anchor) = apart(l.max + 6.0);
                }
                [min, max]
            }),
            symmetry: GaugeMark {
                // Its label sits inside, just below the mirror line's far half, clear of the
                // start's and of the dial.
                label_at: {
                    let (x, y) = d.point(symmetry + 180.0, d.r * 0.3);
                    (x, y + 12.0)
                },
                anchor: "middle",
                ..mark(symmetry, d.r, d.r)
            },
            start: mark(start, d.r - 10.0, d.r - 24.0),
            candidates: candidates
                .iter()
                .map(|&(value, chosen)| CandidateMark {
                    // A candidate on a limit switch: its label further out than the limit's.
                    mark: mark(value, d.r, if near_limit(value) { d.r + 30.0 } else { d.r + 16.0 }),
                    chosen,
                    out_of_limits: limits.is_some_and(|l| !l.contains(value)),
                })
                .collect(),
        }
    }

    /// The gauge of a bench set-up: the machine's master axis, its limit switches (the bench's
    /// override or the machine's own), the symmetry point, start and the solver's candidates.
    #[must_use]
    pub fn of_bench(b: &Bench) -> Gauge {
        let master = b.machine.master().axis;
        let limits = b.machine.limits_of(master, &b.opts.limits);
        let start = b.opts.start.get(master).unwrap_or(0.0);
        let (symmetry, candidates) = match &b.explanation {
            Some(e) => (
                e.symmetry_point,
                e.candidates.iter().enumerate().map(|(i, c)| (c.master, e.chosen == Some(i))).collect(),
            ),
            None => (b.machine.symmetry_positions()[0], Vec::new()),
        };
        Gauge::new(master, limits, symmetry, start, &candidates)
    }
}

/// A number in the SVG (one decimal is a tenth of a pixel).
fn num(v: f64) -> String {
    format!("{v:.1}")
}

impl GaugeMark {
    /// The mark's label as SVG text (`text` is the trainer's own: NC words and fixed words).
    fn label(&self, text: &str, class: &str) -> String {
        let (x, y) = self.label_at;
        format!(
            r#"<text class="{class}" x="{}" y="{}" text-anchor="{}">{text}</text>"#,
            num(x),
            num(y),
            self.anchor
        )
    }

    /// A radial tick across the dial at the mark, from radius `inner` to `outer`.
    fn tick(&self, inner: f64, outer: f64, class: &str) -> String {
        line(DIAL.point(self.value, inner), DIAL.point(self.value, outer), class)
    }
}

fn line(a: (f64, f64), b: (f64, f64), class: &str) -> String {
    format!(
        r#"<line class="{class}" x1="{}" y1="{}" x2="{}" y2="{}"/>"#,
        num(a.0),
        num(a.1),
        num(b.0),
        num(b.1)
    )
}

impl Gauge {
    /// The limit switches under the gauge: `Endschalter A: A-120 … A+120`.
    #[must_use]
    pub fn limits_text(&self, l: Lang) -> String {
        let axis = self.axis;
        self.limits.as_ref().map_or_else(
            || format!("{} {axis}", l.t("Keine Endschalter an", "No limit switches on")),
            |[min, max]| {
                format!("{} {axis}: {} … {}", l.t("Endschalter", "Limit switches"), min.word, max.word)
            },
        )
    }

    /// The gauge as one SVG element: the traverse range along the dial (beyond the limit
    /// switches dashed red), the limit switches as ticks, the mirror line through the symmetry
    /// point, the start, and the candidates (`data-chosen`, `data-out`, `data-word` for the
    /// tests; the chosen one filled, one beyond a limit switch crossed out). Every text in it is
    /// the trainer's own (NC words, numbers, fixed words), so it needs no escaping.
    #[must_use]
    pub fn svg(&self, l: Lang) -> String {
        let r = DIAL.r;
        let mut s = format!(
            r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="{GAUGE_VIEW}" role="img" aria-label="{} {}">"#,
            l.t("Verfahrbereich der Master-Achse", "Traverse range of the master axis"),
            self.axis
        );
        s += &format!(r#"<path class="allowed" d="{}"/>"#, self.allowed);
        if let Some(f) = &self.forbidden {
            s += &format!(r#"<path class="forbidden" d="{f}"/>"#);
        }
        let sym = self.symmetry.value;
        s += &line(DIAL.point(sym, r), DIAL.point(sym + 180.0, r), "symmetry");
        s += &self
            .symmetry
            .label(&format!("{} {}", l.t("Symmetrie", "Symmetry"), self.symmetry.word), "symmetry-label");
        for m in self.limits.iter().flatten() {
            s += &format!(
                r#"<g class="limit" data-testid="gauge-limit">{}{}</g>"#,
                m.tick(r - 9.0, r + 9.0, "limit-tick"),
                m.label(&m.word, "limit-label")
            );
        }
        s += &format!(
            r#"<g class="start" data-testid="gauge-start">{}{}</g>"#,
            self.start.tick(r - 16.0, r - 4.0, "start-tick"),
            self.start.label(&format!("{} {}", l.t("Start", "Start"), self.start.word), "start-label")
        );
        for c in &self.candidates {
            let (x, y) = c.mark.at;
            let class = match (c.chosen, c.out_of_limits) {
                (true, true) => "candidate chosen out",
                (true, false) => "candidate chosen",
                (false, true) => "candidate out",
                (false, false) => "candidate",
            };
            let cross = if c.out_of_limits {
                format!(r#"<path class="cross" d="M{} {}l10 10m0 -10l-10 10"/>"#, num(x - 5.0), num(y - 5.0))
            } else {
                String::new()
            };
            s += &format!(
                r#"<g class="{class}" data-testid="gauge-candidate" data-chosen="{}" data-out="{}" data-word="{}"><circle cx="{}" cy="{}" r="{}"/>{cross}{}</g>"#,
                c.chosen,
                c.out_of_limits,
                c.mark.word,
                num(x),
                num(y),
                if c.chosen { 8 } else { 6 },
                c.mark.label(&c.mark.word, "candidate-label")
            );
        }
        s + "</svg>"
    }
}

/// The caption under the bench's 3D view (`scene` from [`bench_scene`]): the chosen solution
/// and the other one shown translucent, or why the machine stays at its start position.
#[must_use]
pub fn bench_caption(b: &Bench, scene: &SceneState, l: Lang) -> String {
    match (b.explanation.as_ref().and_then(Explanation::chosen_axes), &scene.ghost) {
        (Some(axes), Some(ghost)) => format!(
            "{} {} · {} {}",
            l.t("Gewählt:", "Chosen:"),
            axis_words(&axes),
            l.t("durchscheinend die andere Lösung", "translucent: the other solution"),
            axis_words(ghost)
        ),
        (Some(axes), None) => format!("{} {}", l.t("Gewählt:", "Chosen:"), axis_words(&axes)),
        (None, _) => format!(
            "{} {}",
            match b.explanation {
                Some(_) => l.t(
                    "Die Steuerung verweigert den Satz – die Maschine bleibt in der Startstellung",
                    "The control refuses the block – the machine stays at the start position"
                ),
                // Q parameters or an orientation the solver cannot take: the message above says.
                None => l.t(
                    "Keine Achsstellung berechnet – die Maschine steht in der Startstellung",
                    "No axis position computed – the machine stands at the start position"
                ),
            },
            axis_words(&scene.axes.rotary)
        ),
    }
}

/// The 3D view's state for a bench set-up: the machine with the chosen solution's rotary axes,
/// the other candidate as the ghost and the working plane the block defines; when the control
/// refuses (or nothing could be solved), the start position and no ghost.
#[must_use]
pub fn bench_scene(machine: &Machine, explanation: Option<&Explanation>, start: &AxisValues) -> SceneState {
    let mut s = SceneState::for_machine(machine);
    let solved = explanation.and_then(|e| Some((e, e.chosen?, e.chosen_axes()?)));
    match solved {
        Some((e, chosen, axes)) => {
            s.axes.rotary = axes;
            s.ghost = e.candidates.iter().enumerate().find(|(i, _)| *i != chosen).map(|(_, c)| c.axes);
            s.wpl.rot = DMat3::from_cols_array_2d(&e.orientation).transpose();
        }
        None => {
            for j in machine.joints() {
                s.axes.rotary.set(j.axis, start.get(j.axis).unwrap_or(0.0));
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use glam::{DAffine3, DVec3};
    use schwenkbar_core::course::seed_rows;

    use super::*;
    use crate::scene::pose::poses;

    #[test]
    fn every_seed_row_has_its_own_name_that_says_its_option() {
        for l in [Lang::De, Lang::En] {
            let rows = seed_rows();
            let names: Vec<String> = rows.iter().map(|r| row_name(r, l)).collect();
            for (row, name) in rows.iter().zip(&names) {
                let option = match option_word(row.block.selection) {
                    "" => l.t("ohne SEQ/SYM", "no SEQ/SYM"),
                    o => o,
                };
                assert!(name.starts_with(option), "row {}: {name}", row.number);
                assert!(!name.contains("Zeile") && !name.contains("Row"), "{name}");
                let twins = names.iter().filter(|n| *n == name).count();
                assert_eq!(twins, 1, "row {}'s name is not distinct: {name}", row.number);
            }
        }
    }

    #[test]
    fn row_names_say_what_the_rows_show() {
        let name = |n: u8| {
            let row = seed_rows().into_iter().find(|r| r.number == n).expect("row");
            row_name(&row, Lang::De)
        };
        assert_eq!(name(15), "SYM-: wählt A-45 statt A+45");
        assert_eq!(name(17), "SYM+ ab C-105: wählt A+45 statt A-45, obwohl der Weg länger ist");
        assert_eq!(name(16), "ohne SEQ/SYM ab C-105: kürzerer Weg – A-45 statt A+45");
        assert_eq!(name(19), "ohne SEQ/SYM mit Endschalter A-90 … A+10: nur A-45 innerhalb der Endschalter");
        assert_eq!(
            name(20),
            "SYM+ mit Endschalter A-90 … A+10: A+45 hinter dem Endschalter – Winkel nicht erlaubt"
        );
        assert_eq!(name(23), "SYM+ auf der B/A-Maschine: wählt A-45 statt A-135");
        assert!(name(25).contains("keine Lösung auf dieser Seite – Winkel nicht erlaubt"));
        assert_eq!(
            name(26),
            "SEQ- auf der B/A-Maschine: beide auf dieser Seite – die nähere A-45 statt A-135"
        );
        let row = seed_rows().into_iter().find(|r| r.number == 14).expect("row");
        assert_eq!(row_name(&row, Lang::En), "SYM+: chooses A+45 rather than A-45");
    }

    #[test]
    fn the_dial_puts_zero_on_top_and_turns_positive_clockwise() {
        let d = Dial { cx: 100.0, cy: 100.0, r: 50.0 };
        let near = |(x, y): (f64, f64), (ex, ey): (f64, f64)| (x - ex).abs() < 1e-9 && (y - ey).abs() < 1e-9;
        assert!(near(d.point(0.0, 50.0), (100.0, 50.0)), "0° at the top");
        assert!(near(d.point(90.0, 50.0), (150.0, 100.0)), "+90° right");
        assert!(near(d.point(-90.0, 50.0), (50.0, 100.0)), "-90° left");
        assert!(near(d.point(180.0, 50.0), (100.0, 150.0)), "180° at the bottom");
        assert!(near(d.point(-180.0, 50.0), d.point(180.0, 50.0)));
        assert!(near(d.point(45.0, 10.0), (100.0 + 10.0 * 0.5f64.sqrt(), 100.0 - 10.0 * 0.5f64.sqrt())));
        // −90 … +10: a short arc clockwise; its rest the long way round.
        assert_eq!(d.arc(-90.0, 10.0), "M50.00 100.00A50 50 0 0 1 108.68 50.76");
        assert!(d.arc(10.0, 270.0).contains(" 0 1 1 "), "the rest is the large arc");
        assert_eq!(d.arc(0.0, 360.0).matches('A').count(), 2, "a full circle as two arcs");
        assert_eq!(d.label(90.0, 60.0).1, "start");
        assert_eq!(d.label(-90.0, 60.0).1, "end");
        assert_eq!(d.label(0.0, 60.0).1, "middle");
    }

    /// The A gauge of a table turning −90…+10 with the candidates A+45 and A−45 (chosen).
    fn a_table_gauge() -> Gauge {
        Gauge::new(
            RotaryAxis::A,
            Some(Limits { min: -90.0, max: 10.0 }),
            0.0,
            0.0,
            &[(45.0, false), (-45.0, true)],
        )
    }

    #[test]
    fn the_gauge_marks_limits_symmetry_start_and_both_candidates() {
        let g = a_table_gauge();
        let [min, max] = g.limits.clone().expect("limit switches");
        assert_eq!((min.word.as_str(), max.word.as_str()), ("A-90", "A+10"));
        assert_eq!(min.at, DIAL.point(-90.0, DIAL.r));
        assert!(g.forbidden.is_some());
        assert_eq!(g.symmetry.word, "A+0");
        let c: Vec<_> =
            g.candidates.iter().map(|c| (c.mark.word.as_str(), c.chosen, c.out_of_limits)).collect();
        assert_eq!(c, [("A+45", false, true), ("A-45", true, false)]);
        // A whole turn (−180 … +180): both limit switches, nothing beyond them.
        let g =
            Gauge::new(RotaryAxis::B, Some(Limits { min: -180.0, max: 180.0 }), 0.0, 0.0, &[(90.0, true)]);
        let [min, max] = g.limits.clone().expect("limit switches");
        assert!(g.forbidden.is_none() && min.at.0.round() == max.at.0.round());
        assert!(
            min.label_at.0 > max.label_at.0 && (min.anchor, max.anchor) == ("start", "end"),
            "labels apart"
        );
        // Without limit switches: the whole circle is allowed, nothing is out.
        let g = Gauge::new(RotaryAxis::A, None, 0.0, 0.0, &[(45.0, true), (-45.0, false)]);
        assert!(g.limits.is_none() && g.forbidden.is_none());
        assert!(g.candidates.iter().all(|c| !c.out_of_limits));
        // A candidate on a limit switch (A+180 on the B/A table): its label clear of the limit's.
        let g = Gauge::new(
            RotaryAxis::A,
            Some(Limits { min: -100.0, max: 180.0 }),
            -90.0,
            0.0,
            &[(180.0, false)],
        );
        let [_, max] = g.limits.clone().expect("limit switches");
        assert!(g.candidates[0].mark.label_at.1 > max.label_at.1 + 10.0);
    }

    #[test]
    fn the_gauge_svg_carries_every_mark_and_marks_the_chosen_candidate() {
        let g = a_table_gauge();
        let limits = g.limits_text(Lang::De);
        assert!(limits.starts_with("Endschalter A: A-") && limits.contains(" … A+"), "{limits}");
        let svg = g.svg(Lang::De);
        assert!(svg.starts_with("<svg ") && svg.ends_with("</svg>"));
        assert_eq!(svg.matches("data-testid=\"gauge-limit\"").count(), 2);
        assert!(svg.contains(r#"class="candidate chosen" data-testid="gauge-candidate" data-chosen="true" data-out="false" data-word="A-45""#));
        assert!(svg.contains(r#"class="candidate out" data-testid="gauge-candidate" data-chosen="false" data-out="true" data-word="A+45""#));
        assert!(svg.contains(">Start A+0</text>") && svg.contains(">Symmetrie A+0</text>"));
        assert_eq!(svg.matches('<').count(), svg.matches('>').count(), "every tag closed");
    }

    #[test]
    fn the_bench_scene_shows_the_chosen_solution_with_the_plane_flat_and_the_other_as_ghost() {
        let form = LabForm { option: "SYM-".into(), ..LabForm::default() };
        let b = form.bench(Lang::De).expect("bench");
        let s = bench_scene(&b.machine, b.explanation.as_ref(), &b.opts.start);
        let near = |v: Option<f64>, want: f64| v.is_some_and(|x| (x - want).abs() < 1e-9);
        assert!(near(s.axes.rotary.a, -45.0) && near(s.axes.rotary.c, -90.0), "{:?}", s.axes.rotary);
        let g = s.ghost.expect("the other candidate");
        assert!(near(g.a, 45.0) && near(g.c, 90.0), "{g:?}");
        let caption = bench_caption(&b, &s, Lang::De);
        assert!(
            caption.starts_with("Gewählt: A-45")
                && caption.contains(" · durchscheinend die andere Lösung A+45"),
            "{caption}"
        );
        // The working plane, carried by the table, lies flat under the vertical tool.
        let p = poses(&b.machine, &s.axes.rotary, s.axes.linear, s.tool.length);
        let wcs = p.workpiece * DAffine3::from_mat3_translation(s.wcs.rot, s.wcs.origin);
        let z = wcs.matrix3 * s.wpl.rot.col(2);
        assert!((z - DVec3::Z).length() < 1e-9, "{z}");
        // Refused (row 20: SYM+ with −90 < A < +10): the start position, no ghost.
        let row = seed_rows().into_iter().find(|r| r.number == 20).expect("row");
        let b = LabForm::from_row(&row).bench(Lang::De).expect("bench");
        assert!(b.explanation.as_ref().is_some_and(|e| e.chosen.is_none()));
        let s = bench_scene(&b.machine, b.explanation.as_ref(), &b.opts.start);
        assert!(near(s.axes.rotary.a, 0.0) && near(s.axes.rotary.c, 0.0) && s.ghost.is_none());
        let caption = bench_caption(&b, &s, Lang::En);
        assert!(
            caption
                .starts_with("The control refuses the block – the machine stays at the start position A+0"),
            "{caption}"
        );
        let g = Gauge::of_bench(&b);
        assert!(g.candidates.iter().any(|c| c.out_of_limits && c.mark.word == "A+45"));
        assert!(g.candidates.iter().all(|c| !c.chosen));
    }
}
