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

use nom::bytes::complete::tag;
use nom::character::complete::{char, space0, space1};
use nom::combinator::opt;
use nom::sequence::preceded;

use super::Cx;
use super::words::{
    Step, at_boundary, failure, keyword, number, q_param, quoted, run, sp, token, uint, word_value,
};
use crate::ast::{BinOp, BlockBody, Expr, FnJump, FnMath, FnOp, Func, JumpIf, Label, SysRead};
use crate::diag::{DiagCode, Expected};
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
fn lbl(i: &str) -> Option<&str> {
    let r = i.strip_prefix("LBL")?;
    if at_boundary(r) {
        Some(sp(r))
    } else {
        r.starts_with(|c: char| c.is_ascii_digit() || c == '"').then_some(r)
    }
}

/// `LBL …`, `CALL LBL …`, `CALL PGM …`.
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn label_or_call(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    if let Some(r) = lbl(body) {
        return match label(r) {
            Ok((rest, l)) => end(cx, rest, BlockBody::Lbl(l)),
            Err(e) => cx.fail(e),
        };
    }
    let Some(r) = keyword(body, "CALL").map(sp) else { return super::unknown(cx, body) };
    if let Some(r) = keyword(r, "PGM").map(sp) {
        return match token(r) {
            Ok((rest, path)) => end(cx, rest, BlockBody::CallPgm { path: path.to_owned() }),
            Err(e) => cx.fail(e),
        };
    }
    let Some(r) = lbl(r) else { return super::unknown(cx, body) };
    let (r, l) = match label(r) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let r = sp(r);
    let mut rep = None;
    let mut rest = r;
    // `REP` with no count: an old control's empty word (`words::empty_word`), no repetition.
    if let Some(after) = keyword(r, "REP").filter(|a| sp(a).is_empty()) {
        rest = sp(after);
    } else if let Some(after) = r.strip_prefix("REP") {
        let param = q_param(sp(after)).filter(|_| crate::unconfirmed::REP_FROM_PARAMETER);
        let count = match param {
            Some(q) => q.map(|(r, index)| (r, Value::Param { index, negate: false })),
            None => uint(sp(after)).map(|(r, n)| (r, Value::Number(f64::from(n)))),
        };
        match count {
            Ok((after, n)) => {
                rep = Some(n);
                rest = after;
                // The control shows `REP 2/2` (remaining/total) after a run: keep the total.
                if let Some(total) = after.strip_prefix('/') {
                    match uint(total) {
                        Ok((after, _)) => rest = after,
                        Err(e) => return cx.fail(e),
                    }
                }
            }
            Err(e) => return cx.fail(e),
        }
    }
    end(cx, rest, BlockBody::CallLbl { label: l, rep })
}

/// `FN 0: Q1 = +5`, the arithmetic `FN 1..8` and the jumps `FN 9..12`; every other FN function
/// is kept with its text ([`BlockBody::FnOther`]).
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn fn_block(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    // `FN 0:` as the control writes it, `FN0:` as CAM systems do.
    let Some(r) = body.strip_prefix("FN").map(sp) else { return super::unknown(cx, body) };
    let Ok((rest, n)) = uint(r) else { return super::unknown(cx, body) };
    let Some(q) = sp(rest).strip_prefix(':').map(sp) else {
        return cx.invalid(sp(rest), Some(Expected::Nc(":")));
    };
    match n {
        0 => assign(cx, q, true),
        9..=12 => jump(cx, n, q),
        n if FnOp::of(n).is_some() => math(cx, n, q),
        18 if let Ok((rest, r)) = sysread(q)
            && sp(rest).is_empty() =>
        {
            Some(BlockBody::SysRead(Box::new(r)))
        }
        _ if q.is_empty() => cx.invalid(q, Some(Expected::Nc("FN n: …"))),
        _ => Some(BlockBody::FnOther { number: n, text: q.to_owned() }),
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
        (space0, char('='), space0, tag("ID")),
        uint,
        preceded((space1, tag("NR")), word_value),
        opt(preceded((space1, tag("IDX")), word_value)),
    );
    let (rest, (_, target, _, id, nr, idx)) = run(words, i)?;
    Ok((rest, SysRead { target, id, nr, idx }))
}

/// `Q<n> = a op b` (`FN 1..4`) or `Q<n> = SQRT a` (`FN 5`).
fn math(cx: &mut Cx, n: u32, i: &str) -> Option<BlockBody> {
    let Some(op) = FnOp::of(n) else { return cx.invalid(i, None) };
    let (r, target) = match q_param(i) {
        Some(Ok(ok)) => ok,
        Some(Err(e)) => return cx.fail(e),
        None => return cx.invalid(i, Some(Expected::Nc("Q|QL|QR"))),
    };
    let Some(r) = sp(r).strip_prefix('=').map(sp) else { return cx.invalid(sp(r), Some(Expected::Nc("="))) };
    if op.unary() {
        let Some(r) = keyword(r, op.word()).map(sp) else {
            return cx.invalid(r, Some(Expected::Nc(op.word())));
        };
        return match word_value(r) {
            Ok((rest, a)) => end(cx, rest, BlockBody::FnMath(Box::new(FnMath { op, target, a, b: None }))),
            Err(e) => cx.fail(e),
        };
    }
    let (r, a) = match word_value(r) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let r = sp(r);
    // `+ +90` as the control writes it; `+90` (the operand without its own sign) as older
    // programs and CAM systems do: the same operation.
    let Some(r) = r.strip_prefix(op.word()).map(sp) else {
        return cx.invalid(r, Some(Expected::Nc(op.word())));
    };
    match word_value(r) {
        Ok((rest, b)) => end(cx, rest, BlockBody::FnMath(Box::new(FnMath { op, target, a, b: Some(b) }))),
        Err(e) => cx.fail(e),
    }
}

/// `IF a OP b GOTO LBL label`, where OP must be the one of the FN number.
fn jump(cx: &mut Cx, n: u32, i: &str) -> Option<BlockBody> {
    let condition = match n {
        9 => JumpIf::Equ,
        10 => JumpIf::Ne,
        11 => JumpIf::Gt,
        _ => JumpIf::Lt,
    };
    let Some(r) = keyword(i, "IF").map(sp) else { return cx.invalid(i, Some(Expected::Nc("IF"))) };
    let (r, a) = match word_value(r) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let r = sp(r);
    let Some(r) = keyword(r, condition.word()).map(sp) else {
        return cx.invalid(r, Some(Expected::Nc(condition.word())));
    };
    let (r, b) = match word_value(r) {
        Ok(ok) => ok,
        Err(e) => return cx.fail(e),
    };
    let r = sp(r);
    let Some(r) = keyword(r, "GOTO").map(sp).and_then(lbl) else {
        return cx.invalid(r, Some(Expected::Nc("GOTO LBL")));
    };
    match label(r) {
        Ok((rest, label)) => end(cx, rest, BlockBody::FnJump(Box::new(FnJump { condition, a, b, label }))),
        Err(e) => cx.fail(e),
    }
}

/// `Q<n> = expr`.
// Out of line: the page split (scripts/split_pages.py) can leave this family's code to the
// wasm loaded after the first screen (whose program has no such block). Only in wasm: natively
// it cost 5-7 % of bench_parse.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn assign(cx: &mut Cx, body: &str, fn0: bool) -> Option<BlockBody> {
    let (r, target) = match q_param(body) {
        Some(Ok(ok)) => ok,
        Some(Err(e)) => return cx.fail(e),
        None => return cx.invalid(body, Some(Expected::Nc("Q|QL|QR"))),
    };
    let Some(r) = sp(r).strip_prefix('=') else { return cx.invalid(sp(r), Some(Expected::Nc("="))) };
    match expr(sp(r), 0) {
        Ok((rest, e)) => end(cx, rest, BlockBody::QAssign { target, expr: e, fn0 }),
        Err(e) => cx.fail(e),
    }
}

/// `QS<n> = …`: a string parameter, its right side kept as written.
#[cfg_attr(target_arch = "wasm32", inline(never))]
pub(super) fn qs_assign(cx: &mut Cx, body: &str) -> Option<BlockBody> {
    let (r, index) = match body.strip_prefix("QS").map(uint) {
        Some(Ok(ok)) => ok,
        Some(Err(e)) => return cx.fail(e),
        None => return cx.invalid(body, Some(Expected::Nc("QS"))),
    };
    let Some(r) = sp(r).strip_prefix('=') else { return cx.invalid(sp(r), Some(Expected::Nc("="))) };
    Some(BlockBody::QsAssign { index, text: r.trim().to_owned() })
}

fn end(cx: &mut Cx, rest: &str, body: BlockBody) -> Option<BlockBody> {
    let rest = sp(rest);
    if rest.is_empty() {
        Some(body)
    } else {
        let len = rest.find(' ').unwrap_or(rest.len());
        cx.error(rest, len, DiagCode::InvalidInput);
        None
    }
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
