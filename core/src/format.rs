//! Writes a [`Program`] back in the control's canonical form: blocks renumbered from 0, signs
//! written on coordinates and angles, one word order per block kind, `~` continuation layout
//! for cycle parameters, every comment kept. Formatting is idempotent:
//! `format_program(&parse(&format_program(&p)).0) == format_program(&p)`.

use std::fmt::Write as _;

use crate::ast::{
    ApprDep, AxisWord, BinOp, BlkForm, Block, BlockBody, CycleDef, CycleValue, Expr, Label, Line, MWords,
    Motion, OldCycleData, OldCycleWord, PatternItem, PatternKey, PatternKind, PolarWord, Program, QName,
    RadiusComp, ToolCall, ToolRef, Unit,
};
use crate::plane::{
    Feed, MoveBack, PlaneBlock, PlaneDef, Positioning, RelAxis, RotaryAxis, Selection, Sign, TransformMode,
    Value,
};

mod expr;
mod plane;

use expr::expr;
use plane::plane;
pub use plane::{plane_angles, plane_rounded, plane_text};

/// The canonical text of a program, one block per line, ending with a line break.
#[must_use]
pub fn format_program(p: &Program) -> String {
    let mut out = String::with_capacity(p.blocks.len() * 40);
    for (n, b) in p.blocks.iter().enumerate() {
        block(&mut out, n, b);
    }
    out
}

fn block(out: &mut String, n: usize, b: &Block) {
    if b.skip() {
        out.push('/');
    }
    let _ = write!(out, "{n}");
    let start = out.len();
    out.push(' ');
    let said = b.body();
    match &*said {
        BlockBody::CycleDef(c) => return cycle_def(out, "CYCL DEF", c, b.comment()),
        BlockBody::TouchProbe(c) => return cycle_def(out, "TCH PROBE", c, b.comment()),
        _ => {}
    }
    body(out, &said);
    if out.len() == start + 1 {
        out.pop();
    }
    if let Some(c) = b.comment() {
        out.push_str(" ;");
        if !c.is_empty() {
            out.push(' ');
            out.push_str(c);
        }
    }
    out.push('\n');
}

/// A number with its sign always written (`+0`, `-40`, `+0.5`).
fn signed(out: &mut String, v: f64) {
    // `-0` is written `+0`: the control has no negative zero.
    let _ = if v < 0.0 { write!(out, "-{}", -v) } else { write!(out, "+{}", v.abs()) };
}

fn value(out: &mut String, v: Value) {
    match v {
        Value::Number(x) => signed(out, x),
        Value::Param { index, negate } => {
            let _ = write!(out, "{}{}", if negate { '-' } else { '+' }, QName(index));
        }
    }
}

/// Spindle speed and feed: written without `+` as the control does (`S5000`, `F1000`).
fn plain(out: &mut String, v: Value) {
    match v {
        Value::Number(x) if x < 0.0 => signed(out, x),
        Value::Number(x) => {
            let _ = write!(out, "{}", x.abs());
        }
        Value::Param { index, negate } => {
            let _ = write!(out, "{}{}", if negate { "-" } else { "" }, QName(index));
        }
    }
}

fn feed(out: &mut String, f: Feed) {
    match f {
        Feed::Max => out.push_str(" FMAX"),
        Feed::Auto => out.push_str(" F AUTO"),
        Feed::Value(v) => {
            out.push_str(" F");
            plain(out, v);
        }
    }
}

fn axis_word(out: &mut String, w: AxisWord) {
    if w.incremental {
        out.push('I');
    }
    out.push_str(w.axis.as_str());
    value(out, w.value);
}

fn axes(out: &mut String, words: &[AxisWord]) {
    for w in words {
        out.push(' ');
        axis_word(out, *w);
    }
}

fn tail(out: &mut String, comp: Option<RadiusComp>, f: Option<Feed>, m: &[u32]) {
    tail_with(out, comp, f, None, m, MWords::default());
}

/// The words after a path block's target: compensation, feed, a spindle speed read leniently
/// (after the feed, where CAM posts write it) and the M functions.
fn tail_with(
    out: &mut String,
    comp: Option<RadiusComp>,
    f: Option<Feed>,
    speed: Option<Value>,
    m: &[u32],
    w: MWords,
) {
    if let Some(c) = comp {
        out.push_str(match c {
            RadiusComp::R0 => " R0",
            RadiusComp::Rl => " RL",
            RadiusComp::Rr => " RR",
        });
    }
    if let Some(f) = f {
        feed(out, f);
    }
    if let Some(s) = speed {
        out.push_str(" S");
        plain(out, s);
    }
    ms(out, m, w);
}

/// ` M…` for each M function, with the words that belong to it ([`MWords`]).
fn ms(out: &mut String, m: &[u32], w: MWords) {
    for &m in m {
        let _ = write!(out, " M{m}");
        match (m, w.mb, w.m128_feed, w.look_ahead) {
            (140, Some(mb), _, _) => {
                mb_words(out, mb);
                if let Some(f) = w.mb_feed {
                    feed(out, f);
                }
            }
            (128, _, Some(f), _) => {
                out.push_str(" F");
                plain(out, f);
            }
            (120, _, _, Some(la)) => {
                out.push_str(" LA");
                plain(out, la);
            }
            _ => {}
        }
    }
}

fn mb_words(out: &mut String, mb: MoveBack) {
    match mb {
        MoveBack::Max => out.push_str(" MB MAX"),
        MoveBack::Dist(d) => {
            out.push_str(" MB");
            value(out, d);
        }
    }
}

fn sign(s: Sign) -> char {
    match s {
        Sign::Plus => '+',
        Sign::Minus => '-',
    }
}

fn unit(u: Unit) -> &'static str {
    match u {
        Unit::Mm => "MM",
        Unit::Inch => "INCH",
    }
}

fn label(out: &mut String, l: &Label) {
    let _ = match l {
        Label::Number(n) => write!(out, "{n}"),
        Label::Name(s) => write!(out, "\"{s}\""),
    };
}

fn body(out: &mut String, b: &BlockBody) {
    match b {
        BlockBody::BeginPgm { name, unit: u } => {
            let _ = write!(out, "BEGIN PGM {name} {}", unit(*u));
        }
        BlockBody::EndPgm { name, unit: u } => {
            let _ = write!(out, "END PGM {name} {}", unit(*u));
        }
        BlockBody::Empty => {}
        BlockBody::Structure { text } => {
            out.push('*');
            if !text.is_empty() {
                out.push(' ');
                out.push_str(text);
            }
        }
        BlockBody::BlkForm(f) => blk_form(out, f),
        BlockBody::ToolCall(t) => tool_call(out, t),
        BlockBody::L(Line { axes: a, comp, feed: f, speed: s, m, m_words }) => {
            out.push('L');
            axes(out, a);
            tail_with(out, *comp, *f, *s, m, *m_words);
        }
        BlockBody::Cc(m) => motion(out, "CC", m),
        BlockBody::C(m) => motion(out, "C", m),
        BlockBody::Cr(m) => motion(out, "CR", m),
        BlockBody::Ct(m) => motion(out, "CT", m),
        BlockBody::Lp(m) => motion(out, "LP", m),
        BlockBody::Cp(m) => motion(out, "CP", m),
        BlockBody::Rnd { radius, feed: f } => {
            out.push_str("RND R");
            value(out, *radius);
            if let Some(f) = f {
                feed(out, *f);
            }
        }
        BlockBody::Chf { length, feed: f } => {
            out.push_str("CHF ");
            value(out, *length);
            if let Some(f) = f {
                feed(out, *f);
            }
        }
        BlockBody::MFunctions(m, w) => {
            let start = out.len();
            ms(out, m, *w);
            // Without the blank `ms` writes before the first one.
            if out[start..].starts_with(' ') {
                out.remove(start);
            }
        }
        BlockBody::CycleDef(c) => cycle_def(out, "CYCL DEF", c, None),
        BlockBody::TouchProbe(c) => cycle_def(out, "TCH PROBE", c, None),
        BlockBody::ToolDef { tool, length, radius } => {
            out.push_str("TOOL DEF ");
            tool_ref(out, tool);
            if let Some(l) = length {
                out.push_str(" L");
                value(out, *l);
            }
            if let Some(r) = radius {
                out.push_str(" R");
                value(out, *r);
            }
        }
        BlockBody::Stop { m } => {
            out.push_str("STOP");
            ms(out, m, MWords::default());
        }
        BlockBody::QsAssign { index, text } => {
            let _ = write!(out, "QS{index} = {text}");
        }
        BlockBody::Header { text } => out.push_str(text),
        BlockBody::CycleDefOld(c) => {
            let _ = write!(out, "CYCL DEF {}.{}", c.number, c.sub);
            match &c.data {
                OldCycleData::Name(s) | OldCycleData::Text(s) => {
                    if !s.is_empty() {
                        out.push(' ');
                        out.push_str(s);
                    }
                }
                OldCycleData::Words(words) => {
                    for w in words {
                        out.push(' ');
                        match *w {
                            OldCycleWord::Axis(a) => axis_word(out, a),
                            OldCycleWord::MirrorAxis(a) => out.push_str(a.as_str()),
                            OldCycleWord::Rot { value: v, incremental } => {
                                out.push_str(if incremental { "IROT" } else { "ROT" });
                                value(out, v);
                            }
                            OldCycleWord::Scl(v) => {
                                out.push_str("SCL ");
                                plain(out, v);
                            }
                            OldCycleWord::Feed(v) => {
                                out.push('F');
                                plain(out, v);
                            }
                        }
                    }
                }
            }
        }
        BlockBody::CyclCall { m } => {
            out.push_str("CYCL CALL");
            ms(out, m, MWords::default());
        }
        BlockBody::CyclCallPat { feed: f, m } => {
            out.push_str("CYCL CALL PAT");
            tail(out, None, *f, m);
        }
        BlockBody::CyclCallPos(l) => {
            out.push_str("CYCL CALL POS");
            axes(out, &l.axes);
            tail(out, None, l.feed, &l.m);
        }
        BlockBody::PatternDef(items) => {
            out.push_str("PATTERN DEF");
            for item in items.iter() {
                pattern_item(out, item);
            }
        }
        BlockBody::Appr(a) => appr_dep(out, "APPR", a),
        BlockBody::Dep(a) => appr_dep(out, "DEP", a),
        BlockBody::FnMath(f) => {
            let _ = write!(out, "FN {}: {} = ", f.op.number(), QName(f.target));
            match f.b {
                None => {
                    out.push_str(f.op.word());
                    out.push(' ');
                    value(out, f.a);
                }
                Some(b) => {
                    value(out, f.a);
                    let _ = write!(out, " {} ", f.op.word());
                    value(out, b);
                }
            }
        }
        BlockBody::FnJump(j) => {
            let _ = write!(out, "FN {}: IF ", j.condition.number());
            value(out, j.a);
            let _ = write!(out, " {} ", j.condition.word());
            value(out, j.b);
            out.push_str(" GOTO LBL ");
            label(out, &j.label);
        }
        BlockBody::Plane(p) => plane(out, p),
        BlockBody::TransDatum { axes: a } => {
            out.push_str("TRANS DATUM AXIS");
            axes(out, a);
        }
        BlockBody::TransDatumReset => out.push_str("TRANS DATUM RESET"),
        BlockBody::TransMirror { axes: a } => {
            out.push_str("TRANS MIRROR AXIS");
            for a in a.iter() {
                out.push(' ');
                out.push_str(a.as_str());
            }
        }
        BlockBody::TransMirrorReset => out.push_str("TRANS MIRROR RESET"),
        BlockBody::TransRotation { rot, incremental } => {
            out.push_str(if *incremental { "TRANS ROTATION IROT" } else { "TRANS ROTATION ROT" });
            value(out, *rot);
        }
        BlockBody::TransRotationReset => out.push_str("TRANS ROTATION RESET"),
        BlockBody::FunctionTcpm(t) => {
            out.push_str("FUNCTION TCPM");
            for w in t.words() {
                out.push(' ');
                out.push_str(w);
            }
        }
        BlockBody::FunctionResetTcpm => out.push_str("FUNCTION RESET TCPM"),
        BlockBody::Lbl(l) => {
            out.push_str("LBL ");
            label(out, l);
        }
        BlockBody::CallLbl { label: l, rep } => {
            out.push_str("CALL LBL ");
            label(out, l);
            match rep {
                Some(Value::Number(n)) => {
                    let _ = write!(out, " REP {n}");
                }
                Some(Value::Param { index, .. }) => {
                    let _ = write!(out, " REP {}", crate::ast::QName(*index));
                }
                None => {}
            }
        }
        BlockBody::CallPgm { path } => {
            let _ = write!(out, "CALL PGM {path}");
        }
        BlockBody::QAssign { target, expr: e, fn0 } => {
            let _ = write!(out, "{}{} = ", if *fn0 { "FN 0: " } else { "" }, QName(*target));
            match e {
                Expr::Num(v) => signed(out, *v),
                e => expr(out, e),
            }
        }
        BlockBody::SysRead(r) => {
            let _ = write!(out, "FN 18: SYSREAD {} = ID{} NR", QName(r.target), r.id);
            plain(out, r.nr);
            if let Some(idx) = r.idx {
                out.push_str(" IDX");
                plain(out, idx);
            }
        }
        BlockBody::FnOther { number, text } => {
            let _ = write!(out, "FN {number}: {text}");
        }
        BlockBody::Unknown { text } | BlockBody::Invalid { text } => out.push_str(text),
    }
}

fn blk_form(out: &mut String, f: &BlkForm) {
    let _ = write!(out, "BLK FORM 0.{}", f.part);
    if let Some(a) = f.tool_axis {
        out.push(' ');
        out.push_str(a.as_str());
    }
    axes(out, &f.axes);
}

fn tool_ref(out: &mut String, t: &ToolRef) {
    let _ = match t {
        ToolRef::Number(n) => write!(out, "{n}"),
        ToolRef::Name(s) => write!(out, "\"{s}\""),
        ToolRef::Param(q) => write!(out, "{}", crate::ast::QName(*q)),
        ToolRef::StringParam(n) => write!(out, "QS{n}"),
    };
}

fn tool_call(out: &mut String, t: &ToolCall) {
    out.push_str("TOOL CALL");
    if let Some(tool) = &t.tool {
        out.push(' ');
        tool_ref(out, tool);
    }
    if let Some(a) = t.axis {
        out.push(' ');
        out.push_str(a.as_str());
    }
    for (key, v, signed_word) in [
        ("S", t.speed, false),
        ("F", t.feed, false),
        ("DL", t.dl, true),
        ("DR", t.dr, true),
        ("DR2", t.dr2, true),
    ] {
        if let Some(v) = v {
            out.push(' ');
            out.push_str(key);
            if signed_word { value(out, v) } else { plain(out, v) }
        }
    }
}

fn polar(out: &mut String, key: &str, p: Option<PolarWord>) {
    if let Some(p) = p {
        out.push(' ');
        if p.incremental {
            out.push('I');
        }
        out.push_str(key);
        value(out, p.value);
    }
}

fn motion(out: &mut String, kw: &str, m: &Motion) {
    out.push_str(kw);
    polar(out, "PR", m.polar_radius);
    polar(out, "PA", m.polar_angle);
    axes(out, &m.axes);
    if let Some(r) = m.radius {
        out.push_str(" R");
        value(out, r);
    }
    if let Some(d) = m.direction {
        let _ = write!(out, " DR{}", sign(d));
    }
    tail_with(out, m.comp, m.feed, m.speed, &m.m, MWords::default());
}

fn appr_dep(out: &mut String, kw: &str, a: &ApprDep) {
    let _ = write!(out, "{kw} {}", a.kind.as_str());
    axes(out, &a.axes);
    if let Some(v) = a.len {
        out.push_str(" LEN");
        value(out, v);
    }
    if let Some(v) = a.cca {
        out.push_str(" CCA");
        plain(out, v);
    }
    if let Some(v) = a.radius {
        out.push_str(" R");
        value(out, v);
    }
    tail(out, a.comp, a.feed, &a.m);
}

fn pattern_item(out: &mut String, item: &PatternItem) {
    let _ = write!(out, " {}{} (", item.kind.as_str(), item.index);
    for (k, (key, v)) in item.words.iter().enumerate() {
        if k > 0 {
            out.push(' ');
        }
        out.push_str(key.as_str());
        // Counts, the pitch-circle step and a circle's diameter are written without sign, as in
        // the manual's examples (`NUM8`, `STEP30`, `D80`); positions and angles with it.
        let unsigned =
            matches!(key, PatternKey::Num | PatternKey::NumX | PatternKey::NumY | PatternKey::Step)
                || (*key == PatternKey::D && matches!(item.kind, PatternKind::Circ | PatternKind::PitchCirc));
        if unsigned { plain(out, *v) } else { value(out, *v) }
    }
    out.push(')');
}

fn cycle_def(out: &mut String, key: &str, c: &CycleDef, comment: Option<&str>) {
    let _ = write!(out, "{key} {}", c.number);
    if !c.name.is_empty() {
        out.push(' ');
        out.push_str(&c.name);
    }
    if let Some(cm) = comment {
        out.push_str(" ;");
        if !cm.is_empty() {
            out.push(' ');
            out.push_str(cm);
        }
    }
    if !c.params.is_empty() {
        out.push_str(" ~");
    }
    out.push('\n');
    for (k, p) in c.params.iter().enumerate() {
        let start = out.len();
        match &p.value {
            CycleValue::Value(v) => {
                let _ = write!(out, "  Q{}=", p.index);
                value(out, *v);
            }
            CycleValue::Text(text) => {
                let _ = write!(out, "  QS{}=\"{text}\"", p.index);
            }
            CycleValue::TextOf(n) => {
                let _ = write!(out, "  QS{}=QS{n}", p.index);
            }
            w => {
                let _ = write!(out, "  Q{}={}", p.index, w.word().unwrap_or_default());
            }
        }
        if let Some(l) = &p.label {
            // Labels start in one column, like on the control's screen.
            while out.len() - start < 16 {
                out.push(' ');
            }
            out.push_str(" ;");
            out.push_str(l);
        }
        if k + 1 < c.params.len() {
            out.push_str(" ~");
        }
        out.push('\n');
    }
}
