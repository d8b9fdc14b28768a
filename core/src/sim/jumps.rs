//! Conditional jumps `FN 9..12: IF a OP b GOTO LBL n` (DOMAIN.md §8, [G:klartext-tests]). The
//! parser keeps them as unknown blocks; the simulator reads their text here so loops built
//! with them run (and an endless one meets the block budget).
//!
//! Grammar sketch: `FN (9|10|11|12): IF value (EQU|NE|GT|LT) value GOTO LBL (n|"name")`,
//! `value := [+|-] (number | Q<n>)`. FN 9 jumps if equal, FN 10 if not equal, FN 11 if
//! greater, FN 12 if less.

use crate::ast::Label;
use crate::plane::Value;

/// A parsed conditional jump.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Jump {
    pub function: u32,
    pub a: Value,
    pub b: Value,
    pub label: Label,
}

impl Jump {
    /// Whether the condition holds for the values `a`, `b`.
    pub fn holds(&self, a: f64, b: f64) -> bool {
        match self.function {
            9 => a == b,
            10 => a != b,
            11 => a > b,
            _ => a < b,
        }
    }
}

fn value(word: &str) -> Option<Value> {
    let (negate, rest) = match word.as_bytes().first()? {
        b'-' => (true, &word[1..]),
        b'+' => (false, &word[1..]),
        _ => (false, word),
    };
    if let Some(q) = rest.strip_prefix('Q') {
        let index = q.parse().ok()?;
        return Some(Value::Param { index, negate });
    }
    let x = crate::number::parse_f64(rest)?;
    x.is_finite().then_some(Value::Number(if negate { -x } else { x }))
}

/// Reads the text of an unknown block; `None` if it is not a conditional jump.
pub(crate) fn parse_jump(text: &str) -> Option<Jump> {
    let rest = text.trim().strip_prefix("FN")?.trim_start();
    let (num, rest) = rest.split_once(':')?;
    let function: u32 = num.trim().parse().ok()?;
    if !(9..=12).contains(&function) {
        return None;
    }
    let words: Vec<&str> = rest.split_whitespace().collect();
    let [if_, a, op, b, goto, lbl, label] = words.as_slice() else { return None };
    let op_ok = matches!((function, *op), (9, "EQU") | (10, "NE") | (11, "GT") | (12, "LT"));
    if *if_ != "IF" || !op_ok || *goto != "GOTO" || *lbl != "LBL" {
        return None;
    }
    let label = if let Some(name) = label.strip_prefix('"').and_then(|l| l.strip_suffix('"')) {
        Label::Name(name.to_string())
    } else {
        Label::Number(label.parse().ok()?)
    };
    Some(Jump { function, a: value(a)?, b: value(b)?, label })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_four_jumps() {
        let j = parse_jump("FN 12: IF +Q25 LT +Q35 GOTO LBL 2").expect("jump");
        assert_eq!(j.function, 12);
        assert_eq!(j.a, Value::Param { index: 25, negate: false });
        assert_eq!(j.label, Label::Number(2));
        assert!(j.holds(1.0, 2.0) && !j.holds(2.0, 2.0));
        let j = parse_jump("FN 9: IF -Q1 EQU +0 GOTO LBL \"ENDE\"").expect("jump");
        assert_eq!(j.label, Label::Name("ENDE".into()));
        assert!(j.holds(0.0, 0.0));
        assert!(parse_jump("FN 10: IF +1 NE +2 GOTO LBL 3").is_some_and(|j| j.holds(1.0, 2.0)));
        assert!(parse_jump("FN 11: IF +3 GT +2 GOTO LBL 3").is_some_and(|j| j.holds(3.0, 2.0)));
        assert!(parse_jump("FN 9: IF +1 LT +2 GOTO LBL 3").is_none(), "FN 9 is EQU");
        assert!(parse_jump("FN 18: SYSREAD Q11 = ID240 NR1 IDX1").is_none());
        assert!(parse_jump("FN 12: IF +Q1 LT").is_none());
    }
}
