//! The PLANE block as the softkey dialog writes it: the definition's words with their signs,
//! the positioning, SEQ/SYM and COORD ROT/TABLE ROT; and the same for computed angles, rounded.

use super::*;

/// The text of a PLANE block body (`PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX`), without
/// block number: what the softkey dialog inserts.
#[must_use]
pub fn plane_text(p: &PlaneBlock) -> String {
    let mut out = String::with_capacity(64);
    plane(&mut out, p);
    out
}

/// A PLANE block of computed values as the softkey dialog writes it, each number rounded to 4
/// decimals (`PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX`): the course's generated programs.
#[must_use]
pub fn plane_rounded(block: &PlaneBlock<f64>) -> String {
    match block.try_map(|&x| Ok::<_, std::convert::Infallible>(Value::Number(crate::number::tidy(x, 4)))) {
        Ok(p) => plane_text(&p),
        Err(never) => match never {},
    }
}

/// [`plane_rounded`] of a definition alone (`PLANE SPATIAL SPA+0 SPB+15 SPC+0`): the why
/// panel's equivalent blocks, the right-hand demo's block.
#[must_use]
pub fn plane_angles(def: PlaneDef<f64>) -> String {
    plane_rounded(&PlaneBlock { def, positioning: None, selection: None, transform: None })
}

fn three(out: &mut String, keys: [&str; 3], v: &[Value; 3]) {
    for (k, v) in keys.iter().zip(v) {
        out.push(' ');
        out.push_str(k);
        value(out, *v);
    }
}

pub(super) fn plane(out: &mut String, p: &PlaneBlock) {
    out.push_str("PLANE ");
    match &p.def {
        PlaneDef::Spatial { spa, spb, spc } => {
            out.push_str("SPATIAL");
            three(out, ["SPA", "SPB", "SPC"], &[*spa, *spb, *spc]);
        }
        PlaneDef::Projected { propr, promin, rot } => {
            out.push_str("PROJECTED");
            three(out, ["PROPR", "PROMIN", "ROT"], &[*propr, *promin, *rot]);
        }
        PlaneDef::Euler { eulpr, eulnu, eulrot } => {
            out.push_str("EULER");
            three(out, ["EULPR", "EULNU", "EULROT"], &[*eulpr, *eulnu, *eulrot]);
        }
        PlaneDef::Vector { base, normal } => {
            out.push_str("VECTOR");
            three(out, ["BX", "BY", "BZ"], base);
            three(out, ["NX", "NY", "NZ"], normal);
        }
        PlaneDef::Points { p1, p2, p3 } => {
            out.push_str("POINTS");
            three(out, ["P1X", "P1Y", "P1Z"], p1);
            three(out, ["P2X", "P2Y", "P2Z"], p2);
            three(out, ["P3X", "P3Y", "P3Z"], p3);
        }
        PlaneDef::Relativ { axis, angle } => {
            out.push_str(match axis {
                RelAxis::Spa => "RELATIV SPA",
                RelAxis::Spb => "RELATIV SPB",
                RelAxis::Spc => "RELATIV SPC",
            });
            value(out, *angle);
        }
        PlaneDef::Axial { axes } => {
            out.push_str("AXIAL");
            for a in axes {
                out.push(' ');
                if a.incremental {
                    out.push('I');
                }
                out.push(match a.axis {
                    RotaryAxis::A => 'A',
                    RotaryAxis::B => 'B',
                    RotaryAxis::C => 'C',
                });
                value(out, a.value);
            }
        }
        PlaneDef::Reset => out.push_str("RESET"),
    }
    match p.positioning {
        None => {}
        Some(Positioning::Stay) => out.push_str(" STAY"),
        Some(Positioning::Move { dist, feed: f }) => {
            out.push_str(" MOVE");
            if let Some(d) = dist {
                out.push_str(" DIST");
                value(out, d);
            }
            if let Some(f) = f {
                feed(out, f);
            }
        }
        Some(Positioning::Turn { move_back, feed: f }) => {
            out.push_str(" TURN");
            if let Some(mb) = move_back {
                mb_words(out, mb);
            }
            if let Some(f) = f {
                feed(out, f);
            }
        }
    }
    match p.selection {
        None => {}
        Some(Selection::Seq(s)) => {
            let _ = write!(out, " SEQ{}", sign(s));
        }
        Some(Selection::Sym(s)) => {
            let _ = write!(out, " SYM{}", sign(s));
        }
    }
    match p.transform {
        None => {}
        Some(TransformMode::CoordRot) => out.push_str(" COORD ROT"),
        Some(TransformMode::TableRot) => out.push_str(" TABLE ROT"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn computed_angles_are_written_as_the_dialog_writes_them() {
        let spatial = PlaneDef::Spatial { spa: 0.0, spb: 15.0, spc: -0.000_01 };
        assert_eq!(plane_angles(spatial), "PLANE SPATIAL SPA+0 SPB+15 SPC+0");
        let euler = PlaneDef::Euler { eulpr: 90.0, eulnu: 12.345_67, eulrot: -44.999_999_999 };
        assert_eq!(plane_angles(euler), "PLANE EULER EULPR+90 EULNU+12.3457 EULROT-45");
        // The rounded text reads back as the block it names.
        let text = plane_angles(PlaneDef::Spatial { spa: -30.0, spb: 7.5, spc: 90.0 });
        assert!(crate::parse::plane_block(&format!("{text} TURN FMAX")).is_ok(), "{text}");
    }
}
