//! Labels, subprogram calls and program section repeats: `CALL LBL n [REP m]`, `LBL 0` returns
//! (the jumps of `FN 9…12` find their label here too).

use super::*;

impl Interp {
    pub(super) fn label_index(&self, cx: &Cx<'_>, label: &Label) -> R<usize> {
        cx.labels.get(&LabelKey::from(label)).copied().ok_or_else(|| SimErrorCode::UndefinedLabel {
            label: match label {
                Label::Number(n) => n.to_string(),
                Label::Name(s) => format!("\"{s}\""),
            },
        })
    }

    /// The number of repeats of `REP`: a whole number 0…65534 (the dialog's range, iTNC 530
    /// user's manual "Program section repeats"), also when a parameter gives it.
    pub(super) fn repeats(&self, v: &Value) -> R<u32> {
        let n = self.value(v)?;
        match *v {
            Value::Param { index, .. } if !(0.0..=65_534.0).contains(&n) || n.fract() != 0.0 => {
                Err(SimErrorCode::RepCount { index, value: n })
            }
            _ => Ok(n as u32),
        }
    }

    #[inline(never)]
    pub(super) fn call_lbl(&mut self, cx: &Cx<'_>, idx: usize, label: &Label, rep: Option<u32>) -> R<()> {
        let target = self.label_index(cx, label)?;
        match rep {
            Some(m) if unconfirmed::REP_IS_SECTION_REPEAT => {
                if let Some(k) = self.labels.reps.iter().position(|(b, _)| *b == idx) {
                    if self.labels.reps[k].1 > 0 {
                        self.labels.reps[k].1 -= 1;
                        self.pc = target;
                    } else {
                        self.labels.reps.remove(k);
                    }
                } else if m > 0 {
                    self.labels.reps.push((idx, m - 1));
                    self.pc = target;
                }
            }
            _ => {
                if self.labels.calls.len() >= unconfirmed::MAX_CALL_DEPTH {
                    return Err(SimErrorCode::CallDepth { depth: unconfirmed::MAX_CALL_DEPTH });
                }
                self.labels.calls.push(idx + 1);
                self.pc = target;
            }
        }
        Ok(())
    }
}
