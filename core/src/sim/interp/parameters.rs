//! The Q parameters: their values, the formulas, the FN arithmetic, assignments, the FN jumps,
//! `FN 18: SYSREAD` of what the simulator knows, `FN 28: TABREAD` without its table, and the FN
//! functions the simulator only names.

use super::*;

impl Interp {
    /// A programmed value: a number, or a Q parameter's (negated if written `-Q…`).
    pub(super) fn value(&self, v: &Value) -> R<f64> {
        match *v {
            Value::Number(x) => Ok(x),
            Value::Param { index, negate } => match self.q.get(&index) {
                Some(&x) => Ok(if negate { -x } else { x }),
                None => Err(SimErrorCode::UndefinedQ { index }),
            },
        }
    }

    /// A Q formula's value.
    pub(super) fn eval(&self, e: &Expr) -> R<f64> {
        Ok(match e {
            Expr::Num(x) => *x,
            Expr::Param(i) => *self.q.get(i).ok_or(SimErrorCode::UndefinedQ { index: *i })?,
            Expr::Pi => std::f64::consts::PI,
            Expr::Neg(a) => -self.eval(a)?,
            // Angles of the Q formula functions are degrees (the control works in degrees,
            // DOMAIN.md §2).
            Expr::Func(f, a) => {
                let x = self.eval(a)?;
                match f {
                    Func::Sin => x.to_radians().sin(),
                    Func::Cos => x.to_radians().cos(),
                    Func::Tan => x.to_radians().tan(),
                    Func::Asin => x.asin().to_degrees(),
                    Func::Acos => x.acos().to_degrees(),
                    Func::Atan => x.atan().to_degrees(),
                    Func::Sqrt => x.sqrt(),
                    Func::Sq => x * x,
                    Func::Abs => x.abs(),
                    Func::Int => x.trunc(),
                    Func::Frac => x.fract(),
                    Func::Ln => x.ln(),
                    Func::Log => x.log10(),
                    Func::Exp => x.exp(),
                    Func::Sgn => {
                        if x == 0.0 {
                            0.0
                        } else {
                            x.signum()
                        }
                    }
                }
            }
            Expr::Bin(op, a, b) => {
                let (x, y) = (self.eval(a)?, self.eval(b)?);
                match op {
                    BinOp::Add => x + y,
                    BinOp::Sub => x - y,
                    BinOp::Mul => x * y,
                    BinOp::Div => x / y,
                    BinOp::Pow => x.powf(y),
                }
            }
        })
    }

    /// `FN 0`…`FN 8`: the arithmetic functions into their target parameter.
    #[inline(never)]
    pub(super) fn fn_math(&mut self, f: &FnMath) -> R<()> {
        let a = self.value(&f.a)?;
        let b = f.b.map(|b| self.value(&b)).transpose()?.unwrap_or(0.0);
        let v = match f.op {
            FnOp::Add => a + b,
            FnOp::Sub => a - b,
            FnOp::Mul => a * b,
            FnOp::Div => a / b,
            FnOp::Sqrt => a.sqrt(),
            FnOp::Sin => a.to_radians().sin(),
            FnOp::Cos => a.to_radians().cos(),
            FnOp::Len => a.hypot(b),
        };
        self.set_q(f.target, v)
    }

    /// `FN n` functions the simulator does not compute: `FN 14` stops with the program's own
    /// error; every other one is said on its block.
    #[inline(never)]
    pub(super) fn fn_other(&mut self, at: &mut At<'_, '_>, number: u32, text: &str) -> R<()> {
        if number == 14 {
            return Err(SimErrorCode::FnError { text: text.to_owned() });
        }
        if number == 28
            && unconfirmed::TABREAD_ASSUMES_ZERO
            && let Some((first, count)) = crate::parse::tabread_targets(text)
        {
            return self.tabread_assumed(at, first, count);
        }
        at.note(|| Note::FnNotSimulated { number, text: text.to_owned() });
        Ok(())
    }

    /// `FN 28: TABREAD` into `count` parameters from `first` without the table
    /// ([`unconfirmed::TABREAD_ASSUMES_ZERO`]): a parameter without a value gets 0.
    pub(super) fn tabread_assumed(&mut self, at: &mut At<'_, '_>, first: u32, count: u32) -> R<()> {
        let mut values = Vec::new();
        for index in first..first.saturating_add(count.min(100)) {
            let kept = self.q.get(&index).copied();
            if kept.is_none() {
                self.set_q(index, 0.0)?;
            }
            values.push((index, kept));
        }
        at.note(|| Note::Tabread { values });
        Ok(())
    }

    /// `FN 18: SYSREAD` of the data the simulator knows (iTNC 530 technical manual, "FN18:
    /// SYSREAD"): ID10 NR1 mm/inch; ID20 NR1 tool number, NR3 tool axis, NR4 spindle speed;
    /// ID240 NR1 IDX1…9 nominal position of axis X, Y, Z, A, B, C, U, V, W in the REF system
    /// (the machine axes); ID270 NR1 IDX1…9 position in the active coordinate system (the
    /// I-CS for X, Y, Z); ID50 NR1…5 IDX tool number: L, R, R2, DL, DR of the tool as a TOOL CALL
    /// would load it (the tool table's group 50, same page), of the active tool without IDX;
    /// ID60 NR1…3 tool number, tool axis and spindle speed of the TOOL CALL; ID200 NR1 the
    /// active radius and NR2 the active length, oversizes included (the values the TOOL CALL
    /// gave Q108 and Q114) (iTNC 530 HSCI and TNC 426/430 technical manuals, data transfer NC →
    /// PLC: "Values programmed in TOOL CALL", "Tool compensation").
    /// Anything else is said on the block and leaves the parameter as it was.
    #[inline(never)]
    pub(super) fn sysread(&mut self, at: &mut At<'_, '_>, r: &SysRead) -> R<()> {
        let nr = self.value(&r.nr)?;
        let idx = r.idx.map(|v| self.value(&v)).transpose()?;
        let axis = |i: f64, linear: DVec3| -> Option<f64> {
            let i = i as usize;
            let rotary =
                |a: RotaryAxis| self.axes.letters.iter().position(|&l| l == a).map(|k| self.axes.rotary[k]);
            match i {
                1..=3 => Some(self.in_program_unit(linear[i - 1])),
                4 => rotary(RotaryAxis::A),
                5 => rotary(RotaryAxis::B),
                6 => rotary(RotaryAxis::C),
                _ => None,
            }
        };
        let mut assumed = None;
        let v = match (r.id, nr, idx) {
            (10, 1.0, _) => self.q.get(&113).copied(),
            (20 | 60, 1.0, _) => Some(f64::from(self.tool.number)),
            (20, 3.0, _) | (60, 2.0, _) => Some(match self.tool.axis {
                'X' => 0.0,
                'Y' => 1.0,
                _ => 2.0,
            }),
            (20, 4.0, _) | (60, 3.0, _) => Some(self.spindle.speed),
            (200, 1.0, _) => self.q.get(&108).copied(),
            (200, 2.0, _) => self.q.get(&114).copied(),
            (240, 1.0, Some(i)) => axis(i, self.axes.linear),
            (270, 1.0, Some(i)) => axis(i, self.programmed()),
            (50, 1.0..=5.0, _) if nr.fract() == 0.0 => {
                let number = idx.map_or(self.tool.number, |i| i.max(0.0) as u32);
                let (entry, known) = self.tool_entry(at.cx, &ToolRef::Number(number));
                assumed = (!known).then_some(number);
                let corner = entry.corner_radius.unwrap_or(0.0);
                let mm = [entry.length, entry.radius, corner, entry.dl, entry.dr][nr as usize - 1];
                Some(self.in_program_unit(mm))
            }
            _ => None,
        };
        let (id, target) = (r.id, r.target);
        match v {
            Some(value) => {
                self.set_q(target, value)?;
                at.note(|| Note::SysRead { id, target, value, default_tool: assumed });
            }
            None => at.note(|| Note::SysReadNotSimulated { id, target }),
        }
        Ok(())
    }

    #[inline(never)]
    pub(super) fn fn_jump(&mut self, cx: &Cx<'_>, j: &FnJump) -> R<()> {
        let (a, b) = (self.value(&j.a)?, self.value(&j.b)?);
        if j.condition.holds(a, b) {
            self.pc = self.label_index(cx, &j.label)?;
        }
        Ok(())
    }

    #[inline(never)]
    pub(super) fn q_assign(&mut self, target: u32, expr: &Expr) -> R<()> {
        let v = self.eval(expr)?;
        self.set_q(target, v)
    }

    pub(super) fn set_q(&mut self, target: u32, v: f64) -> R<()> {
        if !v.is_finite() {
            return Err(SimErrorCode::Arithmetic { index: target });
        }
        self.q.insert(target, v);
        Ok(())
    }
}
