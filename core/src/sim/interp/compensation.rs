//! Tool radius compensation RL/RR and the approach and departure paths APPR/DEP, in the working
//! plane of the I-CS (so on a tilted plane too).
//!
//! Sources: TNC 620 / iTNC 530 Klartext user's manuals, "Tool radius compensation" (RL: the tool
//! moves to the left of the contour in the direction of travel, RR to the right, at the distance
//! R + DR; the compensation is modal, R0 ends it; at outside corners the tool centre runs on a
//! transition arc around the corner point, at inside corners to the intersection of the two
//! tool centre paths; between RL and RR a block with R0), "Approaching and departing a contour"
//! (TNC7 user's manual: APPR LT/LN/CT/LCT, DEP LT/LN/CT/LCT with the auxiliary point PH, the
//! direction table of APPR CT, DEP LCT moving the tool axis from PH to PN). The conventions the
//! manuals leave open are [`unconfirmed::COMP_CORNER_ARC_WITH_NEXT_BLOCK`],
//! [`unconfirmed::APPR_DEP_RADIUS_OF_CENTRE_PATH`] and `Decision::CompensationConventions`.

use super::*;
use crate::ast::{ApprDep, ApprKind};
use crate::sim::arc::{self, Elem, OffsetError, Shape, WorkPlane};
use crate::sim::error::ApprDepReason;

/// Tolerance (mm) for "the tool stands on this path": far below the display resolution, above
/// the roundoff of the offset and intersection formulas (derived).
const ON_PATH: f64 = 1e-6;

/// The active compensation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Comp {
    /// +1: RL (left of the contour in the direction of travel), −1: RR.
    pub side: f64,
    /// The programmed contour point the tool stands at (the tool centre is `pos_i`).
    pub at: DVec3,
    /// The tool centre when `at` was set: a block that moves the tool otherwise ends the
    /// compensation ([`unconfirmed::Decision::CompensationConventions`]).
    pub centre: DVec3,
}

fn side_of(c: RadiusComp) -> Option<f64> {
    match c {
        RadiusComp::R0 => None,
        RadiusComp::Rl => Some(1.0),
        RadiusComp::Rr => Some(-1.0),
    }
}

/// The compensation word of a contour block, `None` when it carries none (or is no contour block).
fn comp_word(body: &BlockBody) -> Option<RadiusComp> {
    match body {
        BlockBody::L(l) => l.comp,
        BlockBody::C(m) | BlockBody::Cr(m) | BlockBody::Ct(m) | BlockBody::Lp(m) | BlockBody::Cp(m) => m.comp,
        _ => None,
    }
}

/// The arc from `start` to `end` around `centre` turning by `sweep` (tool-axis coordinate of `start`).
fn arc_piece(plane: &WorkPlane, start: DVec3, end: DVec3, centre: DVec3, sweep: f64) -> Elem {
    let h = plane.axial(start);
    Elem {
        start,
        end: plane.with_axial(end, h),
        shape: Shape::Arc { centre: plane.with_axial(centre, h), sweep },
    }
}

impl Interp {
    /// The compensation, if the tool still stands where the last compensated block left it.
    pub(super) fn active_comp(&self) -> Option<Comp> {
        self.contour.comp.filter(|c| c.centre == self.pos_i)
    }

    /// The programmed position: the contour point while compensating, else the tool centre.
    pub(super) fn programmed(&self) -> DVec3 {
        self.active_comp().map_or(self.pos_i, |c| c.at)
    }

    /// The contour element run after block `idx`, from `start`, with its compensation word: the
    /// rounding the element prepared, or the next contour block (a `CC` between sets the pole).
    fn next_element(
        &self,
        cx: &Cx<'_>,
        idx: usize,
        start: DVec3,
        tangent: Option<DVec3>,
    ) -> Option<(Elem, Option<RadiusComp>)> {
        if let Some(Ok(p)) = &self.contour.corner {
            return Some((p.piece, None));
        }
        let mut pole = self.contour.pole;
        for b in cx.program.blocks.iter().skip(idx + 1) {
            match &*b.body() {
                // Blocks that do not move the tool are looked over.
                BlockBody::Empty | BlockBody::Structure { .. } | BlockBody::CycleDef(_) => {}
                BlockBody::MFunctions(m, _) if !m.contains(&99) => {}
                BlockBody::L(l) if l.axes.is_empty() && !l.m.contains(&99) => {}
                BlockBody::Cc(m) => pole = Some(self.pole_of(&m.axes, start).ok()?),
                body => {
                    let e = self.element(body, start, pole, tangent).ok().flatten()?;
                    return Some((e, comp_word(body)));
                }
            }
        }
        None
    }

    /// Runs the contour element `elem` (programmed, I-CS) of block `idx` whose compensation word
    /// is `word`: plain, switching the compensation on (straight to the point perpendicular to
    /// the start of the next element), compensated, or switching it off (straight to the
    /// programmed point).
    pub(super) fn run_element(
        &mut self,
        at: &mut At<'_, '_>,

        elem: Elem,
        word: Option<RadiusComp>,
        rate: Rate,
    ) -> R<()> {
        let before = self.active_comp();
        let side = match word {
            Some(w) => side_of(w),
            None => before.map(|c| c.side),
        };
        let plane = self.work_plane();
        match (before, side) {
            (None, None) => self.follow(at, &elem, rate)?,
            (None, Some(s)) => {
                let t = match self.next_element(at.cx, at.block, elem.end, elem.tangent(&plane, true)) {
                    Some((n, w)) if w.is_none_or(|w| side_of(w) == Some(s)) => n.tangent(&plane, false),
                    _ => None,
                }
                .or_else(|| elem.tangent(&plane, true));
                let shift = t.map_or(DVec3::ZERO, |t| s * self.tool.radius * plane.normal.cross(t));
                self.follow(at, &Elem::line(self.pos_i, elem.end + shift), rate)?;
            }
            (Some(_), None) => {
                if let Shape::Arc { .. } = elem.shape {
                    self.follow(at, &Elem::line(self.pos_i, elem.start), rate)?;
                    self.follow(at, &elem, rate)?;
                } else {
                    self.follow(at, &Elem::line(self.pos_i, elem.end), rate)?;
                }
            }
            (Some(c), Some(s)) if c.side != s => return Err(SimErrorCode::CompensationChange),
            (Some(_), Some(s)) => {
                let next = self
                    .next_element(at.cx, at.block, elem.end, elem.tangent(&plane, true))
                    .filter(|(_, w)| w.is_none_or(|w| side_of(w) == Some(s)))
                    .map(|(n, _)| n);
                self.compensated(at, &elem, s, next.as_ref(), rate)?;
            }
        }
        self.contour.comp = side.map(|s| Comp { side: s, at: elem.end, centre: self.pos_i });
        // A CT after it continues the contour, not the tool centre path (which may end before
        // the contour's end, at an inside corner).
        if let Some(t) = elem.tangent(&plane, true) {
            self.contour.tangent = Some(Travel::Unit(t));
        }
        Ok(())
    }

    /// Moves the tool centre along `elem` offset to side `s`: from where the corner before left
    /// it (on the offset path after an inside corner, else around the corner point on the
    /// transition arc), to the intersection with `next`'s offset path at an inside corner or
    /// perpendicular to the element's end.
    pub(super) fn compensated(
        &mut self,
        at: &mut At<'_, '_>,

        elem: &Elem,
        s: f64,
        next: Option<&Elem>,
        rate: Rate,
    ) -> R<()> {
        let plane = self.work_plane();
        let r = self.tool.radius;
        let here = self.pos_i;
        let off = match arc::offset(&plane, elem, s, r) {
            Ok(e) => e,
            // Along the tool axis only: the tool keeps its side offset.
            Err(OffsetError::NoDirection) => {
                let shifted = elem.end + plane.planar(here - elem.start);
                return self.follow(at, &Elem::line(here, shifted), rate);
            }
            Err(OffsetError::RadiusGone { radius }) => {
                return Err(SimErrorCode::ToolRadiusTooLarge { radius: r, contour_radius: radius });
            }
        };
        let too_small = SimErrorCode::ContourElementTooSmall { radius: r };
        let mut pieces = Vec::with_capacity(3);
        let mut off = off;
        if plane.planar(here - off.start).length() > ON_PATH {
            let corner = elem.start;
            let from_corner = plane.planar(here - corner);
            let turn = plane.angle(from_corner, plane.planar(off.start - corner));
            if let Some(f) = arc::on_curve(&plane, &off, here, ON_PATH) {
                // After an inside corner: the path starts at the intersection, which must lie on it.
                if !(-1e-9..=1.0 + 1e-9).contains(&f) {
                    return Err(too_small);
                }
                off = off.tail_from(&plane, f.clamp(0.0, 1.0), here);
            } else if (from_corner.length() - r).abs() <= ON_PATH
                && (turn * s < 0.0 || turn.abs() > std::f64::consts::PI - 1e-9)
            {
                // An outside corner (a reversal too): around the corner point, turning against
                // the side.
                let sweep = arc::directed(&plane, from_corner, off.start - corner, -s);
                pieces.push(arc_piece(&plane, here, off.start, corner, sweep));
            } else {
                pieces.push(Elem::line(here, off.start));
            }
        }
        let mut after = None;
        if let Some(n) = next
            && let (Some(t1), Some(t2)) = (elem.tangent(&plane, true), n.tangent(&plane, false))
        {
            let turn = t1.cross(t2).dot(plane.normal);
            let tangent = turn.abs() < 1e-9 && t1.dot(t2) > 0.0;
            if !tangent && let Ok(n_off) = arc::offset(&plane, n, s, r) {
                // A reversal (turn 0, opposite directions) is an outside corner.
                if s * turn > 1e-9 {
                    // Inside corner: end at the intersection of the two tool centre paths.
                    let x = arc::meet(&plane, &off, &n_off, off.end).ok_or(too_small.clone())?;
                    let f = off.fraction_of(&plane, x);
                    if !(-1e-9..=1.0 + 1e-9).contains(&f) {
                        return Err(too_small);
                    }
                    off = off.head_to(f.clamp(0.0, 1.0), x);
                } else if !unconfirmed::COMP_CORNER_ARC_WITH_NEXT_BLOCK {
                    let corner = elem.end;
                    let sweep = arc::directed(&plane, off.end - corner, n_off.start - corner, -s);
                    after = Some(arc_piece(&plane, off.end, n_off.start, corner, sweep));
                }
            }
        }
        pieces.push(off);
        pieces.extend(after);
        for p in &pieces {
            self.follow(at, p, rate)?;
        }
        Ok(())
    }

    /// The rounding/chamfer piece of a RND/CHF block under compensation: compensated like any
    /// element; after it comes the element after the corner, from the piece's end.
    pub(super) fn compensated_piece(
        &mut self,
        at: &mut At<'_, '_>,

        piece: &Elem,
        corner: DVec3,
        rate: Rate,
    ) -> R<bool> {
        let Some(c) = self.active_comp() else { return Ok(false) };
        let plane = self.work_plane();
        let next =
            self.next_element(at.cx, at.block, corner, piece.tangent(&plane, true)).and_then(|(n, w)| {
                w.is_none_or(|w| side_of(w) == Some(c.side))
                    .then(|| n.tail_from(&plane, n.fraction_of(&plane, piece.end), piece.end))
            });
        self.compensated(at, piece, c.side, next.as_ref(), rate)?;
        self.contour.comp = Some(Comp { side: c.side, at: piece.end, centre: self.pos_i });
        if let Some(t) = piece.tangent(&plane, true) {
            self.contour.tangent = Some(Travel::Unit(t));
        }
        Ok(true)
    }

    /// The centre of an APPR/DEP arc of programmed radius `r` turning `dir` on side `s`, beside
    /// the contour point `p` (`left`: left of the contour's direction in the working plane), and
    /// the radius of its tool centre path ([`unconfirmed::APPR_DEP_RADIUS_OF_CENTRE_PATH`]); a
    /// radius of zero is the control's error.
    fn approach_arc(
        &self,
        r: f64,
        s: f64,
        dir: f64,
        p: DVec3,
        left: DVec3,
    ) -> Result<(DVec3, f64), ApprDepReason> {
        let rho = if unconfirmed::APPR_DEP_RADIUS_OF_CENTRE_PATH {
            r.abs()
        } else {
            r.abs() - dir * s * self.tool.radius
        };
        if r == 0.0 || rho <= 0.0 {
            return Err(ApprDepReason::ZeroRadius);
        }
        Ok((p + dir * rho * left, rho))
    }

    /// `APPR LT/LN/CT/LCT`: from the start point PS (where the tool stands) via the auxiliary
    /// point PH to the first contour point PA, switching the compensation on there.
    #[inline(never)]
    pub(super) fn approach(&mut self, at: &mut At<'_, '_>, a: &ApprDep) -> R<()> {
        self.m_functions(at, &a.m);
        let rate = self.rate(a.feed.as_ref())?;
        let kind = a.kind.as_str();
        let fail = |reason| SimErrorCode::ApprDep { word: "APPR", kind, reason };
        let s = a.comp.and_then(side_of).ok_or(fail(ApprDepReason::NoCompensation))?;
        let plane = self.work_plane();
        self.contour.geom_start = None;
        let pa = self.target(&a.axes, self.programmed())?;
        let t = self
            .next_element(at.cx, at.block, pa, None)
            .and_then(|(e, _)| e.tangent(&plane, false))
            .ok_or(fail(ApprDepReason::NoContourAfter))?;
        let left = plane.normal.cross(t);
        // PA of the tool centre: perpendicular to the first element's start.
        let pa_c = pa + s * self.tool.radius * left;
        let ps = self.pos_i;
        let length = |v: Option<Value>| v.map(|v| self.length(&v)).transpose().map(Option::unwrap_or_default);
        let angle = |v: Option<Value>| v.map(|v| self.value(&v)).transpose().map(Option::unwrap_or_default);
        let pieces = match a.kind {
            // PH on the first element's tangent, LEN before PA.
            ApprKind::Lt => {
                let ph = pa_c - length(a.len)?.abs() * t;
                vec![Elem::line(ps, ph), Elem::line(ph, pa_c)]
            }
            // PH perpendicular to the contour, LEN + tool radius from PA.
            ApprKind::Ln => {
                let ph = pa_c + length(a.len)?.abs() * s * left;
                vec![Elem::line(ps, ph), Elem::line(ph, pa_c)]
            }
            // The arc of central angle CCA ending tangentially at PA; direction from the table
            // (RL with R+ counter-clockwise, R− clockwise; RR the other way).
            ApprKind::Ct => {
                let r = length(a.radius)?;
                let dir = s * r.signum();
                let (m, _) = self.approach_arc(r, s, dir, pa_c, left).map_err(fail)?;
                let sweep = dir * angle(a.cca)?.to_radians();
                let ph = m + plane.rotate(plane.planar(pa_c - m), -sweep);
                vec![
                    Elem::line(ps, ph),
                    Elem { start: ph, end: pa_c, shape: Shape::Arc { centre: m, sweep } },
                ]
            }
            // The arc tangent to the line from PS and to the first element, on the side of the
            // compensation.
            ApprKind::Lct => {
                let r = length(a.radius)?;
                let (m, rho) = self.approach_arc(r, s, s, pa_c, left).map_err(fail)?;
                let ph = arc::tangent_point(&plane, m, rho, s, ps, true)
                    .ok_or(fail(ApprDepReason::PointInsideArc))?;
                let sweep = arc::directed(&plane, ph - m, pa_c - m, s);
                vec![
                    Elem::line(ps, ph),
                    Elem { start: ph, end: pa_c, shape: Shape::Arc { centre: m, sweep } },
                ]
            }
        };
        for p in &pieces {
            self.follow(at, p, rate)?;
        }
        self.contour.comp = Some(Comp { side: s, at: pa, centre: self.pos_i });
        self.end_m(&a.m);
        Ok(())
    }

    /// `DEP LT/LN/CT/LCT`: from the last contour point PE away from the contour to the end point
    /// PN; the compensation ends.
    #[inline(never)]
    pub(super) fn depart(&mut self, at: &mut At<'_, '_>, a: &ApprDep) -> R<()> {
        self.m_functions(at, &a.m);
        let rate = self.rate(a.feed.as_ref())?;
        let kind = a.kind.as_str();
        let fail = |reason| SimErrorCode::ApprDep { word: "DEP", kind, reason };
        let c = self.active_comp().ok_or(fail(ApprDepReason::NoCompensation))?;
        let t = self.contour.tangent.ok_or(fail(ApprDepReason::NoContourBefore))?.unit();
        let plane = self.work_plane();
        let s = c.side;
        let left = plane.normal.cross(t);
        let pe_c = self.pos_i;
        let length = |v: Option<Value>| v.map(|v| self.length(&v)).transpose().map(Option::unwrap_or_default);
        let angle = |v: Option<Value>| v.map(|v| self.value(&v)).transpose().map(Option::unwrap_or_default);
        let pieces = match a.kind {
            // Straight on in the direction of the last element, LEN long.
            ApprKind::Lt => vec![Elem::line(pe_c, pe_c + length(a.len)?.abs() * t)],
            // Perpendicular away from the contour, PN LEN + tool radius from PE.
            ApprKind::Ln => vec![Elem::line(pe_c, pe_c + length(a.len)?.abs() * s * left)],
            ApprKind::Ct => {
                let r = length(a.radius)?;
                let dir = s * r.signum();
                let (m, _) = self.approach_arc(r, s, dir, pe_c, left).map_err(fail)?;
                let sweep = dir * angle(a.cca)?.to_radians();
                let pn = m + plane.rotate(plane.planar(pe_c - m), sweep);
                vec![Elem { start: pe_c, end: pn, shape: Shape::Arc { centre: m, sweep } }]
            }
            // The arc tangent to the last element and to the line to PN; the tool axis moves
            // on that line (TNC7 manual, DEP LCT).
            ApprKind::Lct => {
                let pn = self.target(&a.axes, c.at)?;
                let r = length(a.radius)?;
                let (m, rho) = self.approach_arc(r, s, s, pe_c, left).map_err(fail)?;
                let ph = arc::tangent_point(&plane, m, rho, s, pn, false)
                    .ok_or(fail(ApprDepReason::PointInsideArc))?;
                let sweep = arc::directed(&plane, pe_c - m, ph - m, s);
                vec![
                    arc_piece(&plane, pe_c, ph, m, sweep),
                    Elem::line(plane.with_axial(ph, plane.axial(pe_c)), pn),
                ]
            }
        };
        for p in &pieces {
            self.follow(at, p, rate)?;
        }
        self.contour.comp = None;
        self.end_m(&a.m);
        Ok(())
    }
}
