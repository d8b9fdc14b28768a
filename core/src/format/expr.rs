//! Q-parameter formulas written with the parentheses their tree needs.

use super::*;

/// Binding strength: sums 1, products 2, powers 3, operands of unary operators 4.
fn prec(e: &Expr) -> u8 {
    match e {
        Expr::Bin(BinOp::Add | BinOp::Sub, ..) => 1,
        Expr::Bin(BinOp::Mul | BinOp::Div, ..) => 2,
        Expr::Bin(BinOp::Pow, ..) | Expr::Neg(_) | Expr::Func(..) => 3,
        Expr::Num(v) if *v < 0.0 => 3,
        _ => 4,
    }
}

fn paren(out: &mut String, e: &Expr, needed: bool) {
    if needed {
        out.push('(');
        expr(out, e);
        out.push(')');
    } else {
        expr(out, e);
    }
}

/// Writes a formula with the parentheses its tree needs (operators are left-associative,
/// `^` right-associative; a unary operator takes a power as its operand).
pub(super) fn expr(out: &mut String, e: &Expr) {
    match e {
        Expr::Num(v) => {
            let _ = write!(out, "{}", if *v == 0.0 { 0.0 } else { *v });
        }
        Expr::Param(n) => {
            let _ = write!(out, "{}", QName(*n));
        }
        Expr::Pi => out.push_str("PI"),
        Expr::Neg(x) => {
            out.push('-');
            paren(out, x, prec(x) < 3);
        }
        Expr::Func(f, x) => {
            out.push_str(f.as_str());
            out.push(' ');
            paren(out, x, prec(x) < 3);
        }
        Expr::Bin(op, a, b) => {
            let (sym, p) = match op {
                BinOp::Add => (" + ", 1),
                BinOp::Sub => (" - ", 1),
                BinOp::Mul => (" * ", 2),
                BinOp::Div => (" / ", 2),
                BinOp::Pow => (" ^ ", 3),
            };
            let left_paren = if *op == BinOp::Pow { prec(a) < 4 } else { prec(a) < p };
            let right_paren = if *op == BinOp::Pow { prec(b) < 3 } else { prec(b) <= p && prec(b) < 3 };
            paren(out, a, left_paren);
            out.push_str(sym);
            paren(out, b, right_paren);
        }
    }
}
