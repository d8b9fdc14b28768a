//! The contour in the working plane: `CC`, the arcs `C`, `CR`, `CT`, the polar `LP`/`CP` (helix
//! with `IZ`), and the corners `RND`/`CHF`, which look ahead to the next element (the corner lies
//! between the element before and the one after, manual "Corner rounding RND"). Geometry in
//! [`crate::sim::arc`]; all of it in the I-CS, so it tilts with the plane.

use super::*;
use crate::ast::Motion;
use crate::plane::Sign;
use crate::sim::arc::{self, CornerKind, Elem, GeoError, Shape, WorkPlane};

/// The circle centre / pole of the last `CC` (I-CS) and the plane of its circles: the main plane
/// of the two axes `CC` names (`CC X… Z…`: the ZX plane), else the working plane
/// ([`unconfirmed::ARC_PLANE_OF_CC`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Pole {
    pub at: DVec3,
    pub plane: WorkPlane,
}

/// A rounding or chamfer prepared by the element before it: the piece itself and the corner
/// point (the geometric start of the element after it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct PendingCorner {
    pub piece: Elem,
    pub corner: DVec3,
}

fn sign_of(s: Sign) -> f64 {
    match s {
        Sign::Plus => 1.0,
        Sign::Minus => -1.0,
    }
}

/// The error of a geometry failure at a block of kind `word`.
fn geo_error(word: &'static str, e: GeoError, value: f64) -> SimErrorCode {
    match e {
        GeoError::EndNotOnCircle { start_radius, end_radius } => {
            SimErrorCode::CircleEnd { start_radius, end_radius }
        }
        GeoError::RadiusTooSmall { radius, chord } => SimErrorCode::RadiusTooSmall { radius, chord },
        GeoError::Degenerate => SimErrorCode::ArcDegenerate { word },
        GeoError::EndOnTangent => SimErrorCode::EndOnTangent,
        GeoError::NoCorner => SimErrorCode::NoCorner { word },
        GeoError::CornerTooLarge => SimErrorCode::CornerTooLarge { word, value },
        GeoError::ChamferNeedsLines => SimErrorCode::ChamferNeedsLines,
    }
}

/// The NC word of a contour block.
fn word_of(body: &BlockBody) -> &'static str {
    match body {
        BlockBody::C(_) => "C",
        BlockBody::Cr(_) => "CR",
        BlockBody::Ct(_) => "CT",
        BlockBody::Lp(_) => "LP",
        BlockBody::Cp(_) => "CP",
        BlockBody::Rnd { .. } => "RND",
        BlockBody::Chf { .. } => "CHF",
        _ => "L",
    }
}

impl Interp {
    /// The main plane of the active tool axis.
    pub(super) fn work_plane(&self) -> WorkPlane {
        WorkPlane::of_tool_axis(self.tool.axis)
    }

    /// `start` with the linear axis words applied (absolute or incremental to `start`).
    pub(super) fn target(&self, axes: &[AxisWord], start: DVec3) -> R<DVec3> {
        let mut p = start;
        for w in axes {
            if let Some(i) = linear_index(w.axis) {
                let v = self.length(&w.value)?;
                p[i] = if w.incremental { p[i] + v } else { v };
            }
        }
        Ok(p)
    }

    /// The pole after `CC` words, relative to the last programmed position `last` (incremental
    /// words; without coordinates the pole is that position, manual "Circle center CC").
    pub(super) fn pole_of(&self, axes: &[AxisWord], last: DVec3) -> R<Pole> {
        let mut named = [false; 3];
        for w in axes {
            if let Some(i) = linear_index(w.axis) {
                named[i] = true;
            }
        }
        let plane = match named {
            [true, false, true] if unconfirmed::ARC_PLANE_OF_CC => WorkPlane::of_tool_axis('Y'),
            [false, true, true] if unconfirmed::ARC_PLANE_OF_CC => WorkPlane::of_tool_axis('X'),
            [true, true, false] if unconfirmed::ARC_PLANE_OF_CC => WorkPlane::of_tool_axis('Z'),
            _ => self.work_plane(),
        };
        Ok(Pole { at: self.target(axes, last)?, plane })
    }

    /// The plane a contour block moves in: its pole's for `C`, `LP` and `CP`, else the working
    /// plane.
    fn plane_of(&self, body: &BlockBody) -> WorkPlane {
        match (body, self.contour.pole) {
            (BlockBody::C(_) | BlockBody::Lp(_) | BlockBody::Cp(_), Some(p)) => p.plane,
            _ => self.work_plane(),
        }
    }

    /// The direction of an arc: DR if written, else the last one ([`unconfirmed::ARC_DIRECTION_WITHOUT_DR`]).
    fn direction(&self, dr: Option<Sign>) -> f64 {
        dr.map(sign_of).or(self.contour.last_dr).unwrap_or(unconfirmed::ARC_DIRECTION_WITHOUT_DR)
    }

    /// The element a contour block describes from the geometric start `start`, with the pole
    /// `pole` and the end tangent `tangent` of the element before. `Ok(None)`: not a contour
    /// element in the plane (an `L` with M91 or rotary axes, any other block).
    pub(super) fn element(
        &self,
        body: &BlockBody,
        start: DVec3,
        pole: Option<Pole>,
        tangent: Option<DVec3>,
    ) -> R<Option<Elem>> {
        let plane = self.work_plane();
        let word = word_of(body);
        let need_pole = || pole.ok_or(SimErrorCode::NoCircleCentre { word });
        let geo = |r: Result<Elem, GeoError>| r.map(Some).map_err(|e| geo_error(word, e, 0.0));
        // The tool-axis coordinate of a Cartesian arc ([`unconfirmed::ARC_TOOL_AXIS_LINEAR`]).
        let arc_end = |m: &Motion| -> R<DVec3> {
            let end = self.target(&m.axes, start)?;
            Ok(if unconfirmed::ARC_TOOL_AXIS_LINEAR {
                end
            } else {
                plane.with_axial(end, plane.axial(start))
            })
        };
        match body {
            BlockBody::L(line) => {
                if motion::in_machine_coordinates(line)
                    || line.axes.iter().any(|w| linear_index(w.axis).is_none())
                {
                    return Ok(None);
                }
                Ok(Some(Elem::line(start, self.target(&line.axes, start)?)))
            }
            BlockBody::C(m) => {
                let Pole { at: cc, plane } = need_pole()?;
                let end = arc_end(m)?;
                geo(arc::arc_c(
                    &plane,
                    start,
                    end,
                    cc,
                    self.direction(m.direction),
                    unconfirmed::CIRCLE_END_TOLERANCE,
                ))
            }
            BlockBody::Cr(m) => {
                let Some(r) = m.radius else { return Err(SimErrorCode::ArcDegenerate { word }) };
                let r = self.length(&r)?;
                let end = arc_end(m)?;
                geo(arc::arc_cr(
                    &plane,
                    start,
                    end,
                    r,
                    self.direction(m.direction),
                    unconfirmed::CIRCLE_END_TOLERANCE,
                ))
            }
            BlockBody::Ct(m) => {
                let t = tangent.ok_or(SimErrorCode::NoTangent)?;
                geo(arc::arc_ct(&plane, start, arc_end(m)?, t))
            }
            BlockBody::Lp(m) => {
                let Pole { at: pole, plane } = need_pole()?;
                let rel = plane.planar(start - pole);
                let (pr0, pa0) = (rel.length(), plane.polar_angle(rel));
                let pr = match m.polar_radius {
                    Some(w) => self.length(&w.value)? + if w.incremental { pr0 } else { 0.0 },
                    None => pr0,
                };
                let pa = match m.polar_angle {
                    Some(w) => self.value(&w.value)? + if w.incremental { pa0 } else { 0.0 },
                    None => pa0,
                };
                let axial = plane.axial(self.target(&m.axes, start)?);
                let end = plane.with_axial(plane.planar(pole) + pr * plane.direction(pa), axial);
                Ok(Some(Elem::line(start, end)))
            }
            BlockBody::Cp(m) => {
                let Pole { at: pole, plane } = need_pole()?;
                let rel = plane.planar(start - pole);
                let dir = self.direction(m.direction);
                let sweep = match m.polar_angle {
                    Some(w) if w.incremental => {
                        let ipa = self.value(&w.value)?.to_radians();
                        if m.direction.is_some() && unconfirmed::CP_IPA_DIRECTION_FROM_DR {
                            dir * ipa.abs()
                        } else {
                            ipa
                        }
                    }
                    Some(w) => {
                        let pa = self.value(&w.value)?;
                        arc::directed(&plane, rel, plane.direction(pa), dir)
                    }
                    // The parser refuses a CP without PA/IPA.
                    None => return Err(SimErrorCode::ArcDegenerate { word }),
                };
                let axial = plane.axial(self.target(&m.axes, start)?);
                geo(arc::arc_cp(&plane, start, pole, sweep, axial))
            }
            _ => Ok(None),
        }
    }

    /// Runs `C`, `CR`, `CT`, `LP`, `CP`.
    #[inline(never)]
    pub(super) fn contour(&mut self, at: &mut At<'_, '_>, body: &BlockBody, m: &Motion) -> R<()> {
        self.m_functions(at, &m.m);
        self.speed_word(m.speed.as_ref())?;
        let rate = self.rate(m.feed.as_ref())?;
        let here = self.programmed();
        let geometric = self.contour.geom_start.take().unwrap_or(here);
        let tangent = self.contour.tangent.map(Travel::unit);
        let Some(elem) = self.element(body, geometric, self.contour.pole, tangent)? else {
            return Ok(());
        };
        if let Some(d) = m.direction {
            self.contour.last_dr = Some(sign_of(d));
        }
        let plane = self.plane_of(body);
        if plane != self.work_plane() {
            return self.contour_off_plane(at, elem, m, rate, plane);
        }
        // After a rounding the element starts at the tangent point, not at the corner.
        let elem = if geometric == here {
            elem
        } else {
            elem.tail_from(&plane, elem.fraction_of(&plane, here), here)
        };
        let elem = self.before_corner(at.cx, at.block, elem)?;
        if m.axes.iter().any(|w| linear_index(w.axis).is_none()) {
            at.note(|| Note::ArcRotaryAxis);
        }
        self.run_element(at, elem, m.comp, rate)?;
        if m.m.contains(&99) {
            self.call_cycle(at)?;
        }
        self.end_m(&m.m);
        Ok(())
    }

    /// An arc or polar line in the plane of a `CC` that is not the working plane (the ramps CAM
    /// systems write, `CC X… Z…` + `CP IPA… DR…`): the tool centre on the programmed path, no
    /// radius compensation (the control compensates in the working plane only) and no tangent
    /// for a following `CT` or corner.
    fn contour_off_plane(
        &mut self,
        at: &mut At<'_, '_>,

        elem: Elem,
        m: &Motion,
        rate: Rate,
        plane: WorkPlane,
    ) -> R<()> {
        if self.active_comp().is_some() || matches!(m.comp, Some(RadiusComp::Rl | RadiusComp::Rr)) {
            return Err(SimErrorCode::CompensationOffPlane);
        }
        self.follow_in(at, &elem, rate, plane)?;
        self.contour.tangent = None;
        if m.m.contains(&99) {
            self.call_cycle(at)?;
        }
        self.end_m(&m.m);
        Ok(())
    }

    /// Shortens `elem` to the tangent point when a RND/CHF block follows, and prepares the
    /// rounding for it (an impossible one is the RND/CHF block's error, the element then runs
    /// to the corner).
    pub(super) fn before_corner(&mut self, cx: &Cx<'_>, idx: usize, elem: Elem) -> R<Elem> {
        let blocks = &cx.program.blocks;
        let (word, kind) = match blocks.get(idx + 1).and_then(crate::Block::stored_body) {
            Some(BlockBody::Rnd { radius, .. }) => ("RND", CornerKind::Round(self.length(radius)?)),
            Some(BlockBody::Chf { length, .. }) => ("CHF", CornerKind::Chamfer(self.length(length)?)),
            _ => return Ok(elem),
        };
        let value = match kind {
            CornerKind::Round(v) | CornerKind::Chamfer(v) => v,
        };
        let plane = self.work_plane();
        let corner = elem.end;
        // The next contour element, from the corner; a CC in between sets its pole.
        let (mut pole, mut next) = (self.contour.pole, None);
        for b in blocks.iter().skip(idx + 2) {
            match &*b.body() {
                BlockBody::Empty | BlockBody::Structure { .. } => {}
                BlockBody::Cc(m) => pole = Some(self.pole_of(&m.axes, corner)?),
                // An arc in the plane of its CC is no element of the working plane's contour: the
                // rounding has nothing to meet there.
                BlockBody::C(_) | BlockBody::Lp(_) | BlockBody::Cp(_)
                    if pole.is_some_and(|p| p.plane != plane) =>
                {
                    break;
                }
                body => {
                    // Errors of the next element are its own block's, when it runs.
                    next = self.element(body, corner, pole, elem.tangent(&plane, true)).ok().flatten();
                    break;
                }
            }
        }
        let Some(next) = next else {
            self.contour.corner = Some(Err(SimErrorCode::CornerWithoutContour { word }));
            return Ok(elem);
        };
        match arc::corner(&plane, &elem, &next, kind) {
            Ok((head, piece, _)) => {
                self.contour.corner = Some(Ok(PendingCorner { piece, corner }));
                Ok(head)
            }
            Err(e) => {
                self.contour.corner = Some(Err(geo_error(word, e, value)));
                Ok(elem)
            }
        }
    }

    /// Runs `RND`/`CHF`: the piece the element before prepared. Its F acts in this block only
    /// (manual: "Feed rate F (effective only in RND block)").
    #[inline(never)]
    pub(super) fn corner_block(
        &mut self,
        at: &mut At<'_, '_>,

        word: &'static str,
        feed: Option<&Feed<Value>>,
        pending: Option<Result<PendingCorner, SimErrorCode>>,
    ) -> R<()> {
        let p = match pending {
            Some(Ok(p)) => p,
            Some(Err(e)) => return Err(e),
            None => return Err(SimErrorCode::CornerWithoutContour { word }),
        };
        let rate = match feed {
            Some(Feed::Value(v)) => Rate::Feed(self.feed_rate(v)?),
            Some(Feed::Max) => Rate::Rapid,
            Some(Feed::Auto) if self.tool.feed > 0.0 => Rate::Feed(self.tool.feed),
            _ if self.feed > 0.0 => Rate::Feed(self.feed),
            _ => Rate::Rapid,
        };
        if !self.compensated_piece(at, &p.piece, p.corner, rate)? {
            self.follow(at, &p.piece, rate)?;
        }
        self.contour.geom_start = Some(p.corner);
        Ok(())
    }

    /// Moves along `elem` (I-CS) with the rotary axes standing, recording the exact path.
    pub(super) fn follow(&mut self, at: &mut At<'_, '_>, elem: &Elem, rate: Rate) -> R<()> {
        self.follow_in(at, elem, rate, self.work_plane())
    }

    /// [`Self::follow`] for an element in `plane`.
    fn follow_in(&mut self, at: &mut At<'_, '_>, elem: &Elem, rate: Rate, plane: WorkPlane) -> R<()> {
        let target = self.map.apply(elem.end);
        self.check_linear(at.cx, target)?;
        let kind = if rate == Rate::Rapid { SegmentKind::Rapid } else { SegmentKind::Feed };
        let to = MachineAxes { linear: target, ..self.axes };
        let length = elem.length(&plane);
        let path = match elem.shape {
            Shape::Line => SegmentPath::Linear,
            Shape::Arc { centre, sweep } => {
                let m = self.map.m;
                let u = plane.planar(elem.start - centre);
                let rise = plane.axial(elem.end) - plane.axial(elem.start);
                SegmentPath::Arc(Box::new(ArcPath {
                    centre: self.map.apply(centre),
                    u: m * u,
                    v: m * plane.normal.cross(u),
                    sweep,
                    lead: m * (rise * plane.normal),
                }))
            }
        };
        self.go_along(at, kind, to, rate, length, path)?;
        self.pos_i = elem.end;
        if let Some(t) = elem.tangent(&plane, true) {
            self.contour.tangent = Some(Travel::Unit(t));
        }
        Ok(())
    }
}
