//! Labels, calls and Q parameters with a small formula language.
//!   lbl := LBL (n|"name")    call := CALL LBL (n|"name") [REP m[/m]] | CALL PGM path
//!   q   := [FN 0:] Q\<n> = expr      expr := term {(+|-) term}   term := unary {(*|/) unary}
//!   unary := (+|-|FUNC) unary | atom [^ unary]      atom := number | Q\<n> | PI | ( expr )
//!   fn  := FN (1|2|3|4|8): Q\<n> = value (+|-|*|DIV|LEN) value | FN (5|6|7): Q\<n> = (SQRT|SIN|COS) value
//!        | FN (9|10|11|12): IF value (EQU|NE|GT|LT) value GOTO LBL (n|"name")
//!        | FN 18: SYSREAD Q\<n> = ID n NR value [IDX value]
//!        | FN n: text    (every other FN function, kept verbatim)
//! (the TNC manuals' Q parameter chapter: `FN 4: Q4 = +8 DIV +Q2`,
//! `FN 12: IF +Q25 LT +Q35 GOTO LBL 2`; DOMAIN.md §8)

use nom::Parser;
use nom::bytes::complete::tag;
use nom::character::complete::{char, space1};
use nom::combinator::{cut, opt};
use nom::sequence::preceded;

use super::words::{
    Step, at_boundary, blanks, end_of_block, expected, failure, hard, invalid, keyword, kw, lex, number,
    or_expected, q_param, quoted, run, soft, sp, token, uint, whole, word_value,
};
use crate::ast::{BinOp, BlockBody, Expr, FnJump, FnMath, FnOp, Func, JumpIf, Label, SysRead};
use crate::diag::Expected;
use crate::plane::Value;

/// Formulas nest at most this deep: keeps the recursion (and the wasm stack) bounded.
const MAX_DEPTH: u32 = 64;

fn label(i: &str) -> Step<'_, Label> {
    if i.starts_with('"') {
        let (r, name) = quoted(i)?;
        return Ok((r, Label::Name(name.to_owned())));
    }
    if i.as_bytes().first().is_some_and(u8::is_ascii_digit) {
        let (r, n) = uint(i)?;
        return Ok((r, Label::Number(n)));
    }
    failure(i, Expected::LabelNumberOrName)
}

/// The keyword `LBL` before a label: `LBL 1` as the control writes it, `LBL1` and `LBL"name"`
/// as some programs do.
fn lbl(i: &str) -> Step<'_, ()> {
    let (r, _) = tag("LBL").parse(i)?;
    if at_boundary(r) {
        Ok((sp(r), ()))
    } else if r.starts_with(|c: char| c.is_ascii_digit() || c == '"') {
        Ok((r, ()))
    } else {
        expected(i, Expected::Nc("LBL"))
    }
}

/// `LBL …`, `CALL LBL …`, `CALL PGM …`; another `CALL …` is a recoverable stop.
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn label_or_call(body: &str) -> Step<'_, BlockBody> {
    if let Ok((r, ())) = lbl(body) {
        let (rest, l) = whole(label).parse(r)?;
        return Ok((rest, BlockBody::Lbl(l)));
    }
    let (r, _) = kw("CALL").parse(body)?;
    let r = sp(r);
    // `CALL PGM100`, a number run on as in `LBL1`: the same call as `CALL PGM 100`.
    if let Some(r) = r
        .strip_prefix("PGM")
        .filter(|p| at_boundary(p) || p.starts_with(|c: char| c.is_ascii_digit()))
        .map(sp)
    {
        let (rest, path) = cut(whole(token)).parse(r)?;
        return Ok((rest, BlockBody::CallPgm { path: path.to_owned() }));
    }
    let (r, ()) = lbl(r)?;
    let (r, l) = cut(label).parse(r)?;
    let (rest, rep) = cut(lex(opt(repeat))).parse(r)?;
    let (rest, ()) = end_of_block(rest)?;
    Ok((rest, BlockBody::CallLbl { label: l, rep: rep.flatten() }))
}

/// `REP n`, `REP n/n` (the control shows remaining/total after a run: the total is kept),
/// `REP Qn`; `REP` with no count is an old control's empty word (`words::empty_word`), no
/// repetition.
fn repeat(i: &str) -> Step<'_, Option<Value>> {
    let (after, _) = tag("REP").parse(i)?;
    if at_boundary(after) && sp(after).is_empty() {
        return Ok((sp(after), None));
    }
    let after = sp(after);
    let param = q_param(after).filter(|_| crate::unconfirmed::REP_FROM_PARAMETER);
    let (rest, n) = match param {
        Some(q) => q.map(|(r, index)| (r, Value::Param { index, negate: false })),
        None => uint(after).map(|(r, n)| (r, Value::Number(f64::from(n)))),
    }
    .map_err(hard)?;
    let (rest, _) = opt(preceded(char('/'), cut(uint))).parse(rest)?;
    Ok((rest, Some(n)))
}

/// `FN 0: Q1 = +5`, the arithmetic `FN 1..8` and the jumps `FN 9..12`; every other FN function
/// is kept with its text ([`BlockBody::FnOther`]).
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn fn_block(body: &str) -> Step<'_, BlockBody> {
    // `FN 0:` as the control writes it, `FN0:` as CAM systems do.
    let (rest, n) = preceded(tag("FN"), lex(|i| uint(i).map_err(soft))).parse(body)?;
    let (q, _) = cut(lex(or_expected(char(':'), Expected::Nc(":")))).parse(rest)?;
    let q = sp(q);
    match n {
        0 => assign_target(q, true),
        9..=12 => jump(n, q),
        n if FnOp::of(n).is_some() => math(n, q),
        18 if let Ok((rest, r)) = sysread(q)
            && sp(rest).is_empty() =>
        {
            Ok((rest, BlockBody::SysRead(Box::new(r))))
        }
        _ if q.is_empty() => invalid(q, Some(Expected::Nc("FN n: …"))),
        _ => Ok((&q[q.len()..], BlockBody::FnOther { number: n, text: q.to_owned() })),
    }
}

/// The parameters `FN 28: TABREAD Q10 = 5 / "X,Y,Z"` (its text after the colon) fills: the
/// first, and how many (one per column named, in consecutive parameters).
pub(crate) fn tabread_targets(text: &str) -> Option<(u32, u32)> {
    let (rest, first) = q_param(sp(text.strip_prefix("TABREAD")?))?.ok()?;
    let columns = rest.split('"').nth(1)?;
    Some((first, columns.split(',').count() as u32))
}

/// `SYSREAD Q… = ID… NR… [IDX…]` (after `FN 18:`); a spelling it does not know stays an
/// `FN 18` kept as written.
fn sysread(i: &str) -> Step<'_, SysRead> {
    let q = |i| q_param(i).unwrap_or_else(|| failure(i, Expected::Nc("Q|QL|QR")));
    let words = (
        (tag("SYSREAD"), space1),
        q,
        (blanks, char('='), blanks, tag("ID")),
        uint,
        preceded((space1, tag("NR")), word_value),
        opt(preceded((space1, tag("IDX")), word_value)),
    );
    let (rest, (_, target, _, id, nr, idx)) = run(words, i)?;
    Ok((rest, SysRead { target, id, nr, idx }))
}

/// `Q<n> = a op b` (`FN 1..4`) or `Q<n> = SQRT a` (`FN 5`).
fn math(n: u32, i: &str) -> Step<'_, BlockBody> {
    let Some(op) = FnOp::of(n) else { return invalid(i, None) };
    let (r, target) = target_eq(i)?;
    if op.unary() {
        let (rest, a) = whole(preceded(cut(kw(op.word())), cut(lex(word_value)))).parse(r)?;
        return Ok((rest, BlockBody::FnMath(Box::new(FnMath { op, target, a, b: None }))));
    }
    // `+ +90` as the control writes it; `+90` (the operand without its own sign) as older
    // programs and CAM systems do: the same operation.
    let op_word = cut(lex(or_expected(tag(op.word()), Expected::Nc(op.word()))));
    let (rest, (a, _, b)) = whole((cut(word_value), op_word, cut(lex(word_value)))).parse(r)?;
    Ok((rest, BlockBody::FnMath(Box::new(FnMath { op, target, a, b: Some(b) }))))
}

/// `GOTO LBL`, which must be there.
fn goto(i: &str) -> Step<'_, ()> {
    let at = sp(i);
    match keyword(at, "GOTO").map(sp).map(lbl) {
        Some(Ok(found)) => Ok(found),
        _ => invalid(at, Some(Expected::Nc("GOTO LBL"))),
    }
}

/// `IF a OP b GOTO LBL label`, where OP must be the one of the FN number.
fn jump(n: u32, i: &str) -> Step<'_, BlockBody> {
    let condition = match n {
        9 => JumpIf::Equ,
        10 => JumpIf::Ne,
        11 => JumpIf::Gt,
        _ => JumpIf::Lt,
    };
    let (rest, (_, a, _, b, _, label)) = whole((
        cut(kw("IF")),
        cut(lex(word_value)),
        cut(kw(condition.word())),
        cut(lex(word_value)),
        goto,
        cut(label),
    ))
    .parse(i)?;
    Ok((rest, BlockBody::FnJump(Box::new(FnJump { condition, a, b, label }))))
}

/// `Q<n> =` (`Q`, `QL` or `QR`) and the rest after the sign.
fn target_eq(i: &str) -> Step<'_, u32> {
    let (r, target) = match q_param(i) {
        Some(q) => q?,
        None => return invalid(i, Some(Expected::Nc("Q|QL|QR"))),
    };
    let (r, _) = cut(lex(or_expected(char('='), Expected::Nc("=")))).parse(r)?;
    Ok((sp(r), target))
}

/// `Q<n> = expr` (`fn0`: written `FN 0: Q<n> = …`).
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn assign_target(body: &str, fn0: bool) -> Step<'_, BlockBody> {
    let (r, target) = target_eq(body)?;
    let (rest, e) = whole(|i| expr(i, 0)).parse(r).map_err(hard)?;
    Ok((rest, BlockBody::QAssign { target, expr: e, fn0 }))
}

/// `Q<n> = expr`, `QL<n> = …`, `QR<n> = …`: the whole block `body`.
// Out of line in wasm, like the other families (the page split defers the ones a first screen
// does not read: ARCHITECTURE.md).
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn assign(body: &str) -> Step<'_, BlockBody> {
    assign_target(body, false)
}

/// `QS<n> = …`: a string parameter, its right side kept as written.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn qs_assign(body: &str) -> Step<'_, BlockBody> {
    let (r, index) =
        preceded(or_expected(tag("QS"), Expected::Nc("QS")), cut(uint)).parse(body).map_err(hard)?;
    let (r, _) = cut(lex(or_expected(char('='), Expected::Nc("=")))).parse(r)?;
    Ok((&r[r.len()..], BlockBody::QsAssign { index, text: r.trim().to_owned() }))
}

/// Bounds both the nesting depth and the number of operators of one formula, so recursion in
/// parsing, formatting and dropping the tree stays small (a wasm stack is only about 1 MB).
struct Budget {
    ops: u32,
}

const MAX_OPS: u32 = 256;

impl Budget {
    fn bin<'a>(&mut self, at: &'a str, op: BinOp, a: Expr, b: Expr) -> Step<'a, Expr> {
        self.ops += 1;
        if self.ops > MAX_OPS {
            return failure(at, Expected::ShorterFormula);
        }
        Ok((at, Expr::Bin(op, Box::new(a), Box::new(b))))
    }
}

fn expr(i: &str, depth: u32) -> Step<'_, Expr> {
    expr_in(i, depth, &mut Budget { ops: 0 })
}

fn expr_in<'a>(i: &'a str, depth: u32, b: &mut Budget) -> Step<'a, Expr> {
    let (mut i, mut acc) = term(i, depth, b)?;
    loop {
        let s = sp(i);
        let op = match s.as_bytes().first() {
            Some(b'+') => BinOp::Add,
            Some(b'-') => BinOp::Sub,
            _ => return Ok((i, acc)),
        };
        let (r, rhs) = term(sp(&s[1..]), depth, b)?;
        acc = b.bin(r, op, acc, rhs)?.1;
        i = r;
    }
}

fn term<'a>(i: &'a str, depth: u32, b: &mut Budget) -> Step<'a, Expr> {
    let (mut i, mut acc) = unary(i, depth, b)?;
    loop {
        let s = sp(i);
        let op = match s.as_bytes().first() {
            Some(b'*') => BinOp::Mul,
            Some(b'/') => BinOp::Div,
            _ => return Ok((i, acc)),
        };
        let (r, rhs) = unary(sp(&s[1..]), depth, b)?;
        acc = b.bin(r, op, acc, rhs)?.1;
        i = r;
    }
}

fn unary<'a>(i: &'a str, depth: u32, b: &mut Budget) -> Step<'a, Expr> {
    if depth > MAX_DEPTH {
        return failure(i, Expected::LessNesting);
    }
    match i.as_bytes().first() {
        Some(b'+') => return unary(sp(&i[1..]), depth + 1, b),
        Some(b'-') => {
            let (r, e) = unary(sp(&i[1..]), depth + 1, b)?;
            let e = match e {
                Expr::Num(v) => Expr::Num(-v),
                other => Expr::Neg(Box::new(other)),
            };
            return Ok((r, e));
        }
        _ => {}
    }
    if let Some((f, r)) = Func::ALL.iter().find_map(|&f| i.strip_prefix(f.as_str()).map(|r| (f, r))) {
        let (r, e) = unary(sp(r), depth + 1, b)?;
        return Ok((r, Expr::Func(f, Box::new(e))));
    }
    let (r, base) = atom(i, depth, b)?;
    let s = sp(r);
    if let Some(after) = s.strip_prefix('^') {
        let (r, exp) = unary(sp(after), depth + 1, b)?;
        return b.bin(r, BinOp::Pow, base, exp);
    }
    Ok((r, base))
}

fn atom<'a>(i: &'a str, depth: u32, b: &mut Budget) -> Step<'a, Expr> {
    match i.as_bytes().first() {
        Some(b'0'..=b'9' | b'.') => {
            let (r, v) = number(i)?;
            Ok((r, Expr::Num(v)))
        }
        Some(b'Q') => match q_param(i) {
            Some(q) => q.map(|(r, n)| (r, Expr::Param(n))),
            None => failure(i, Expected::Operand),
        },
        Some(b'(') => {
            let (r, e) = expr_in(sp(&i[1..]), depth + 1, b)?;
            match sp(r).strip_prefix(')') {
                Some(r) => Ok((r, e)),
                None => failure(sp(r), Expected::Nc(")")),
            }
        }
        _ => match i.strip_prefix("PI") {
            Some(r) => Ok((r, Expr::Pi)),
            None => failure(i, Expected::Operand),
        },
    }
}
