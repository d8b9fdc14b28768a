//! Pockets and slots: 251 RECHTECKTASCHE, 252 KREISTASCHE, 253 NUTENFRAESEN, 254 RUNDE NUT.
//!
//! Sequence (HEIDENHAIN cycle manual, cycles 251–254 "Cycle run"): the tool is pre-positioned at
//! FMAX to the set-up clearance Q200 above the surface Q203 over the plunge point; per infeed
//! (at most Q202, down to the depth Q201 less the floor allowance Q369) it plunges at Q206 —
//! vertically (Q366 = 0) or on a helix (Q366 = 1) — and roughs the pocket from the inside out at
//! the milling feed Q207, the stepover at most Q370 × tool radius, leaving the side allowance
//! Q368; it then rises by Q200 above the infeed and returns at FMAX to the plunge point. Q215 = 0
//! roughs and finishes, 1 only roughs, 2 only finishes: the walls (in infeeds of Q338, 0 = one)
//! along the finished contour, then the floor from the inside out, at the finishing feed Q385.
//! At the end FMAX to Q200, or to Q204 when larger. Climb milling (Q351 = +1 with M3) runs the
//! inside contours DR+ (counter-clockwise), up-cut (−1) DR−.
//!
//! Simplified, and named in [`crate::unconfirmed`] (`CycleConventions`): the roughing paths are
//! concentric offsets of the contour spaced evenly by at most the stepover, joined by straight
//! moves outward (the control's own path order is not published); approach and departure
//! are straight, not on the manual's tangential arcs; the helix has the tool radius and one turn
//! per infeed ([`unconfirmed::POCKET_HELIX`]); a reciprocating plunge (Q366 = 2) is simulated as
//! a vertical one; the slots 253/254, which have no Q370, step over by one tool radius
//! ([`unconfirmed::SLOT_STEPOVER`]). The tool's plunge angle (ANGLE) is not checked.

use std::f64::consts::{FRAC_PI_2, PI};

use glam::{DVec2, DVec3};

use super::{CycleMove, EPS, MAX_CYCLE_MOVES, Params, arc, depth, feed, levels, polar, rapid, turned};
use crate::sim::error::SimErrorCode;
use crate::unconfirmed;

type R<T> = Result<T, SimErrorCode>;

/// One piece of a closed path in the working plane.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Piece {
    Line(DVec2),
    Arc { to: DVec2, centre: DVec2, sweep: f64 },
}

/// A closed path: its start point and the pieces back to it.
#[derive(Debug, Clone, PartialEq)]
struct Loop {
    start: DVec2,
    pieces: Vec<Piece>,
}

impl Loop {
    /// The loop turned by `deg` about the origin and moved to `origin`.
    fn placed(self, origin: DVec2, deg: f64) -> Loop {
        let at = |v: DVec2| origin + turned(v, deg);
        Loop {
            start: at(self.start),
            pieces: self
                .pieces
                .into_iter()
                .map(|p| match p {
                    Piece::Line(to) => Piece::Line(at(to)),
                    Piece::Arc { to, centre, sweep } => Piece::Arc { to: at(to), centre: at(centre), sweep },
                })
                .collect(),
        }
    }
}

/// The rounded rectangle of half sides `a`, `b` and corner radius `c` about the origin, from
/// `(a, 0)` counter-clockwise (`dir` > 0) or clockwise. `b = c` with `a = b` is a circle,
/// `b = c` alone a slot; `b = 0` is the line from `(a, 0)` to `(−a, 0)` and back.
fn rounded_rectangle(a: f64, b: f64, c: f64, dir: f64) -> Loop {
    let c = c.clamp(0.0, a.min(b).max(0.0));
    let mut pieces = Vec::with_capacity(9);
    let mut corner = |from_line: DVec2, centre: DVec2, to: DVec2| {
        pieces.push(Piece::Line(from_line));
        if c > EPS {
            pieces.push(Piece::Arc { to, centre, sweep: FRAC_PI_2 });
        }
    };
    corner(DVec2::new(a, b - c), DVec2::new(a - c, b - c), DVec2::new(a - c, b));
    corner(DVec2::new(-a + c, b), DVec2::new(-a + c, b - c), DVec2::new(-a, b - c));
    corner(DVec2::new(-a, -b + c), DVec2::new(-a + c, -b + c), DVec2::new(-a + c, -b));
    corner(DVec2::new(a - c, -b), DVec2::new(a - c, -b + c), DVec2::new(a, -b + c));
    pieces.push(Piece::Line(DVec2::new(a, 0.0)));
    let start = DVec2::new(a, 0.0);
    let mut l = Loop { start, pieces };
    if dir < 0.0 {
        // Clockwise: the same path mirrored in the reference axis.
        let m = |v: DVec2| DVec2::new(v.x, -v.y);
        l.pieces = l
            .pieces
            .into_iter()
            .map(|p| match p {
                Piece::Line(to) => Piece::Line(m(to)),
                Piece::Arc { to, centre, sweep } => {
                    Piece::Arc { to: m(to), centre: m(centre), sweep: -sweep }
                }
            })
            .collect();
    }
    l
}

/// The number of evenly spaced offsets that cover `width` with steps of at most `step`.
fn rings(width: f64, step: f64) -> usize {
    if width <= EPS || step <= EPS { 0 } else { ((width / step).ceil() as usize).min(MAX_CYCLE_MOVES / 16) }
}

/// Concentric rounded rectangles from the innermost (half side `min(a, b)` less) out to
/// `(a, b, c)`, spaced by at most `step`.
fn concentric(a: f64, b: f64, c: f64, step: f64, dir: f64) -> Vec<Loop> {
    let m = a.min(b).max(0.0);
    let n = rings(m, step);
    (0..=n)
        .map(|i| {
            let d = if n == 0 { 0.0 } else { m * (n - i) as f64 / n as f64 };
            rounded_rectangle(a - d, b - d, (c - d).max(0.0), dir)
        })
        .collect()
}

/// The circular slot about the origin on the radius `rc` from `from` over `span` degrees
/// (> 0), the tool centre `rho` off the centre line, from the outer start point on.
fn ring_slot(rc: f64, from: f64, span: f64, rho: f64, dir: f64) -> Loop {
    let (t0, t1) = (from, from + span);
    let sweep = span.to_radians();
    let outer = |t: f64| (rc + rho) * polar(t);
    let inner = |t: f64| (rc - rho) * polar(t);
    let mut pieces = Vec::with_capacity(4);
    let cap = rho > EPS;
    if dir >= 0.0 {
        pieces.push(Piece::Arc { to: outer(t1), centre: DVec2::ZERO, sweep });
        if cap {
            pieces.push(Piece::Arc { to: inner(t1), centre: rc * polar(t1), sweep: PI });
        }
        pieces.push(Piece::Arc { to: inner(t0), centre: DVec2::ZERO, sweep: -sweep });
        if cap {
            pieces.push(Piece::Arc { to: outer(t0), centre: rc * polar(t0), sweep: PI });
        }
    } else {
        if cap {
            pieces.push(Piece::Arc { to: inner(t0), centre: rc * polar(t0), sweep: -PI });
        }
        pieces.push(Piece::Arc { to: inner(t1), centre: DVec2::ZERO, sweep });
        if cap {
            pieces.push(Piece::Arc { to: outer(t1), centre: rc * polar(t1), sweep: -PI });
        }
        pieces.push(Piece::Arc { to: outer(t0), centre: DVec2::ZERO, sweep: -sweep });
    }
    Loop { start: outer(t0), pieces }
}

/// What a pocket cycle mills: the roughing loops (inside out), the finishing loops (the last
/// one is the finished wall), the plunge point and the room for a helix around it.
struct Shape {
    rough: Vec<Loop>,
    finish: Vec<Loop>,
    plunge: DVec2,
    room: f64,
}

/// The parameters every pocket cycle shares.
struct Common {
    surface: f64,
    clear: f64,
    clear2: f64,
    depth: f64,
    step: f64,
    floor: f64,
    side: f64,
    operation: i64,
    plunge_feed: f64,
    mill_feed: f64,
    finish_feed: f64,
    finish_step: f64,
    helix: bool,
    dir: f64,
}

impl Common {
    fn of(p: &Params) -> R<Common> {
        Ok(Common {
            surface: p.get(203)?,
            clear: p.get(200)?,
            clear2: p.get(204)?,
            depth: depth(p)?,
            step: p.get(202)?,
            floor: p.get(369)?.max(0.0),
            side: p.get(368)?.max(0.0),
            operation: p.get(215)? as i64,
            plunge_feed: p.get(206)?,
            mill_feed: p.get(207)?,
            finish_feed: p.get(385)?,
            finish_step: p.get(338)?,
            helix: p.get(366)? == 1.0,
            dir: if p.get(351)? < 0.0 { -1.0 } else { 1.0 },
        })
    }
}

/// Appends `m` unless it is a straight move to where the tool already is (a loop of zero width
/// repeats its corner points).
fn put(out: &mut Vec<CycleMove>, m: CycleMove) {
    let there = out.last().is_some_and(|l| (l.target - m.target).length() <= EPS);
    if m.arc.is_some() || !there {
        out.push(m);
    }
}

/// One level: plunge at the plunge point from `above` to `z` (on a helix of radius `helix` when
/// it is > 0), mill `loops` at feed `f`, rise by Q200 and return to the plunge point at FMAX.
#[allow(clippy::too_many_arguments)]
fn level(
    out: &mut Vec<CycleMove>,
    c: &Common,
    shape: &Shape,
    above: &mut f64,
    z: f64,
    loops: &[Loop],
    f: f64,
    helix: f64,
) {
    plunge(out, shape, *above, z, helix, c);
    for l in loops {
        if out.len() >= MAX_CYCLE_MOVES {
            return;
        }
        put(out, feed(l.start.extend(z), f));
        for p in &l.pieces {
            put(
                out,
                match *p {
                    Piece::Line(to) => feed(to.extend(z), f),
                    Piece::Arc { to, centre, sweep } => arc(to.extend(z), centre, sweep, f),
                },
            );
        }
    }
    let last = out.last().map_or(shape.plunge, |m| m.target.truncate());
    put(out, rapid(last.extend(z + c.clear)));
    put(out, rapid(shape.plunge.extend(z + c.clear)));
    *above = z + c.clear;
}

/// Mills `shape` as the manual's sequence (module doc) from the tool position `pos`.
fn mill(c: &Common, shape: &Shape, pos: DVec3, r: f64, out: &mut Vec<CycleMove>) {
    let top = c.surface + c.clear;
    let high = c.surface + c.clear.max(c.clear2);
    if (pos.truncate() - shape.plunge).length() > EPS {
        if pos.z < high {
            put(out, rapid(pos.truncate().extend(high)));
        }
        put(out, rapid(shape.plunge.extend(pos.z.max(high))));
    }
    put(out, rapid(shape.plunge.extend(top)));
    if c.depth == 0.0 {
        return;
    }
    let bottom = c.surface - c.depth;
    let mut above = top;
    if c.operation != 2 {
        let helix = if c.helix { shape.room.min(unconfirmed::POCKET_HELIX * r) } else { 0.0 };
        let floor = (bottom + c.floor).min(c.surface);
        for z in levels(c.surface, floor, c.step) {
            if out.len() >= MAX_CYCLE_MOVES {
                return;
            }
            level(out, c, shape, &mut above, z, &shape.rough, c.mill_feed, helix);
        }
    }
    if c.operation != 1 {
        let wall: Vec<Loop> = shape.finish.last().cloned().into_iter().collect();
        if c.side > 0.0 || c.operation == 2 {
            let zs =
                if c.finish_step > 0.0 { levels(c.surface, bottom, c.finish_step) } else { vec![bottom] };
            for z in zs {
                if out.len() >= MAX_CYCLE_MOVES {
                    return;
                }
                level(out, c, shape, &mut above, z, &wall, c.finish_feed, 0.0);
            }
        }
        if c.floor > 0.0 {
            level(out, c, shape, &mut above, bottom, &shape.finish, c.finish_feed, 0.0);
        }
    }
    let here = out.last().map_or(shape.plunge, |m| m.target.truncate());
    put(out, rapid(here.extend(high)));
}

/// Down from `from` to `z` at the plunge point: on a helix of radius `helix` (one turn,
/// [`unconfirmed::POCKET_HELIX`]) or, with no room for it, vertically.
fn plunge(out: &mut Vec<CycleMove>, shape: &Shape, from: f64, z: f64, helix: f64, c: &Common) {
    let f = c.plunge_feed;
    if helix > EPS {
        let start = shape.plunge + DVec2::new(helix, 0.0);
        put(out, feed(start.extend(from), f));
        put(out, arc(start.extend(z), shape.plunge, c.dir * std::f64::consts::TAU, f));
    } else {
        put(out, feed(shape.plunge.extend(z), f));
    }
}

/// The tool is larger than the contour: the control's error.
fn too_large(cycle: u32, r: f64, size: f64) -> SimErrorCode {
    SimErrorCode::ToolTooLarge { cycle, tool_diameter: 2.0 * r, size }
}

/// Cycle 251 RECHTECKTASCHE: Q218 × Q219 with corner radius Q220, turned by Q224 about the tool
/// position, which is the pocket centre (Q367 = 0) or its lower left, lower right, upper right,
/// upper left corner (1–4).
#[inline(never)]
pub(super) fn rectangular_251(p: &Params, pos: DVec3, r: f64) -> R<Vec<CycleMove>> {
    let c = Common::of(p)?;
    let (l, w, corner, rot) = (p.get(218)?, p.get(219)?, p.get(220)?, p.get(224)?);
    let (h1, h2) = (0.5 * l, 0.5 * w);
    let offset = match p.get(367)? as i64 {
        1 => DVec2::new(h1, h2),
        2 => DVec2::new(-h1, h2),
        3 => DVec2::new(-h1, -h2),
        4 => DVec2::new(h1, -h2),
        _ => DVec2::ZERO,
    };
    let centre = pos.truncate() + turned(offset, rot);
    let outline = |allow: f64| (h1 - allow - r, h2 - allow - r, corner - allow - r);
    let (a, b, k) = outline(0.0);
    if a < -EPS || b < -EPS {
        return Err(too_large(251, r, l.min(w)));
    }
    let (ra, rb, rk) = outline(c.side);
    if ra < -EPS || rb < -EPS {
        return Err(too_large(251, r, l.min(w) - 2.0 * c.side));
    }
    let step = p.get(370)? * r;
    let place = |v: Vec<Loop>| v.into_iter().map(|l| l.placed(centre, rot)).collect();
    let shape = Shape {
        rough: place(concentric(ra.max(0.0), rb.max(0.0), rk, step, c.dir)),
        finish: place(concentric(a.max(0.0), b.max(0.0), k, step, c.dir)),
        plunge: centre,
        room: ra.min(rb).max(0.0),
    };
    let mut out = Vec::new();
    mill(&c, &shape, pos, r, &mut out);
    Ok(out)
}

/// Cycle 252 KREISTASCHE: the circle of diameter Q223 about the tool position.
#[inline(never)]
pub(super) fn circular_252(p: &Params, pos: DVec3, r: f64) -> R<Vec<CycleMove>> {
    let c = Common::of(p)?;
    let d = p.get(223)?;
    let (rho, rough) = (0.5 * d - r, 0.5 * d - c.side - r);
    if rho < -EPS || rough < -EPS {
        return Err(too_large(252, r, d - 2.0 * c.side));
    }
    let step = p.get(370)? * r;
    let centre = pos.truncate();
    let circles = |rho: f64| {
        let rho = rho.max(0.0);
        concentric(rho, rho, rho, step, c.dir).into_iter().map(|l| l.placed(centre, 0.0)).collect()
    };
    let shape = Shape { rough: circles(rough), finish: circles(rho), plunge: centre, room: rough.max(0.0) };
    let mut out = Vec::new();
    mill(&c, &shape, pos, r, &mut out);
    Ok(out)
}

/// Cycle 253 NUTENFRAESEN: the slot Q218 long and Q219 wide, turned by Q374 about the tool
/// position, which is the slot centre (Q367 = 0), its left end (1), the centre of its left arc
/// (2), of its right arc (3) or its right end (4).
#[inline(never)]
pub(super) fn slot_253(p: &Params, pos: DVec3, r: f64) -> R<Vec<CycleMove>> {
    let c = Common::of(p)?;
    let (l, w, rot) = (p.get(218)?, p.get(219)?, p.get(374)?);
    let h = (0.5 * (l - w)).max(0.0);
    let offset = match p.get(367)? as i64 {
        1 => 0.5 * l,
        2 => h,
        3 => -h,
        4 => -0.5 * l,
        _ => 0.0,
    };
    let centre = pos.truncate() + turned(DVec2::new(offset, 0.0), rot);
    let (rho, rough) = (0.5 * w - r, 0.5 * w - c.side - r);
    if rho < -EPS || rough < -EPS {
        return Err(too_large(253, r, w - 2.0 * c.side));
    }
    let step = unconfirmed::SLOT_STEPOVER * r;
    let slots = |rho: f64| {
        let rho = rho.max(0.0);
        concentric(h + rho, rho, rho, step, c.dir).into_iter().map(|l| l.placed(centre, rot)).collect()
    };
    let shape = Shape { rough: slots(rough), finish: slots(rho), plunge: centre, room: rough.max(0.0) };
    let mut out = Vec::new();
    mill(&c, &shape, pos, r, &mut out);
    Ok(out)
}

/// Cycle 254 RUNDE NUT: the slot Q219 wide along the arc of diameter Q375 from the starting
/// angle Q376 over Q248; its circle centre is Q216/Q217 (Q367 = 0), or the tool position is the
/// slot's start (1), middle (2) or end (3) on the centre line ([`unconfirmed::CIRCULAR_SLOT_REFERENCE`]).
/// Q377 slots, each turned by Q378 from the one before.
#[inline(never)]
pub(super) fn circular_slot_254(p: &Params, pos: DVec3, r: f64) -> R<Vec<CycleMove>> {
    let c = Common::of(p)?;
    let (w, rc, from, span) = (p.get(219)?, 0.5 * p.get(375)?, p.get(376)?, p.get(248)?);
    let (rho, rough) = (0.5 * w - r, 0.5 * w - c.side - r);
    if rho < -EPS || rough < -EPS {
        return Err(too_large(254, r, w - 2.0 * c.side));
    }
    let reference = match p.get(367)? as i64 {
        n @ 1..=3 if unconfirmed::CIRCULAR_SLOT_REFERENCE => Some(from + 0.5 * span * (n - 1) as f64),
        _ => None,
    };
    let centre = match reference {
        Some(t) => pos.truncate() - rc * polar(t),
        None => DVec2::new(p.get(216)?, p.get(217)?),
    };
    let count = (p.get(377)?.max(1.0) as usize).min(1000);
    let stepping = p.get(378)?;
    let step = unconfirmed::SLOT_STEPOVER * r;
    let (lo, len) = if span < 0.0 { (from + span, -span) } else { (from, span) };
    let mut out = Vec::new();
    let mut here = pos;
    for k in 0..count {
        let t0 = lo + stepping * k as f64;
        let band = |rho: f64| -> Vec<Loop> {
            let rho = rho.max(0.0);
            let n = rings(rho, step);
            (0..=n)
                .map(|i| {
                    let d = if n == 0 { rho } else { rho * i as f64 / n as f64 };
                    ring_slot(rc, t0, len, d, c.dir).placed(centre, 0.0)
                })
                .collect()
        };
        let shape = Shape {
            rough: band(rough),
            finish: band(rho),
            plunge: centre + rc * polar(t0),
            room: rough.max(0.0),
        };
        mill(&c, &shape, here, r, &mut out);
        here = out.last().map_or(here, |m| m.target);
        if out.len() >= MAX_CYCLE_MOVES {
            break;
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{params, path};
    use super::*;

    const FMAX: Option<f64> = None;
    const PLUNGE: Option<f64> = Some(150.0);
    const MILL: Option<f64> = Some(500.0);

    fn pocket(cycle: u32, extra: &[(u32, f64)]) -> Params {
        let mut p = params(
            cycle,
            &[
                (215, 1.0),
                (368, 0.0),
                (224, 0.0),
                (367, 0.0),
                (207, 500.0),
                (351, 1.0),
                (201, -4.0),
                (202, 2.0),
                (369, 0.0),
                (206, 150.0),
                (338, 0.0),
                (200, 2.0),
                (203, 0.0),
                (204, 20.0),
                (370, 1.0),
                (366, 0.0),
                (385, 300.0),
            ],
        );
        for &(i, v) in extra {
            p.set(i, v);
        }
        p
    }

    #[test]
    fn cycle_251_roughs_concentric_rectangles_from_the_centre_out_at_each_infeed() {
        // Pocket 40 × 30 about (50, 50), corner radius 10, tool radius 5 (Ø 10), stepover 5:
        // the tool centre stays within 15 × 10 (corner radius 5); three rectangles spaced 5:
        // half sides (5, 0), (10, 5), (15, 10) with corner radii 0, 0, 5. Two infeeds of 2 to −4,
        // plunged vertically at F150, milled DR+ at F500.
        let p = pocket(251, &[(218, 40.0), (219, 30.0), (220, 10.0)]);
        let moves = rectangular_251(&p, DVec3::new(50.0, 50.0, 30.0), 5.0).expect("cycle");
        let at = |x: f64, y: f64, z: f64, f| (x + 50.0, y + 50.0, z, f);
        let level = |z: f64| {
            #[rustfmt::skip]
            let v = vec![
                at(0.0, 0.0, z, PLUNGE),
                // (5, 0): out to (5, 0), along the line to (−5, 0) and back.
                at(5.0, 0.0, z, MILL), at(-5.0, 0.0, z, MILL), at(5.0, 0.0, z, MILL),
                // (10, 5), sharp corners.
                at(10.0, 0.0, z, MILL), at(10.0, 5.0, z, MILL), at(-10.0, 5.0, z, MILL),
                at(-10.0, -5.0, z, MILL), at(10.0, -5.0, z, MILL), at(10.0, 0.0, z, MILL),
                // (15, 10) with quarter arcs of radius 5.
                at(15.0, 0.0, z, MILL), at(15.0, 5.0, z, MILL), at(10.0, 10.0, z, MILL),
                at(-10.0, 10.0, z, MILL), at(-15.0, 5.0, z, MILL), at(-15.0, -5.0, z, MILL),
                at(-10.0, -10.0, z, MILL), at(10.0, -10.0, z, MILL), at(15.0, -5.0, z, MILL),
                at(15.0, 0.0, z, MILL),
                // Up by Q200 and back to the centre.
                at(15.0, 0.0, z + 2.0, FMAX), at(0.0, 0.0, z + 2.0, FMAX),
            ];
            v
        };
        let mut want = vec![at(0.0, 0.0, 2.0, FMAX)];
        want.extend(level(-2.0));
        want.extend(level(-4.0));
        want.push(at(0.0, 0.0, 20.0, FMAX));
        assert_eq!(path(&moves), want);
        let arcs: Vec<_> = moves.iter().filter_map(|m| m.arc).collect();
        assert_eq!(arcs.len(), 8);
        assert!(arcs.iter().all(|a| (a.sweep - FRAC_PI_2).abs() < 1e-12));
        assert_eq!(arcs[0].centre, DVec2::new(60.0, 55.0));
    }

    #[test]
    fn cycle_251_position_rotation_finishing_and_the_too_large_tool() {
        // Q367 = 1: the tool at the lower left corner of a 40 × 30 pocket turned by 90°: the
        // centre is (0, 0) + turned((20, 15), 90°) = (−15, 20).
        let p = pocket(251, &[(218, 40.0), (219, 30.0), (220, 5.0), (367, 1.0), (224, 90.0)]);
        let moves = rectangular_251(&p, DVec3::new(0.0, 0.0, 30.0), 5.0).expect("cycle");
        let want_first = [(-15.0, 20.0, 30.0, FMAX), (-15.0, 20.0, 2.0, FMAX), (-15.0, 20.0, -2.0, PLUNGE)];
        assert_eq!(path(&moves)[..3], want_first[..]);
        // Finishing (Q215 = 0) with Q368 = 1: roughing stays 1 mm off the walls (x ≤ 14 along
        // the turned pocket: |Δy| ≤ 14 of the centre); the wall pass goes to 15 at F300.
        let p = pocket(251, &[(218, 40.0), (219, 30.0), (220, 5.0), (215, 0.0), (368, 1.0)]);
        let moves = rectangular_251(&p, DVec3::ZERO, 5.0).expect("cycle");
        let rough_x = moves.iter().filter(|m| m.feed == MILL).map(|m| m.target.x.abs()).fold(0.0, f64::max);
        let finish_x =
            moves.iter().filter(|m| m.feed == Some(300.0)).map(|m| m.target.x.abs()).fold(0.0, f64::max);
        assert!((rough_x - 14.0).abs() < 1e-9 && (finish_x - 15.0).abs() < 1e-9, "{rough_x} {finish_x}");
        let p = pocket(251, &[(218, 8.0), (219, 30.0), (220, 0.0)]);
        assert_eq!(
            rectangular_251(&p, DVec3::ZERO, 5.0),
            Err(SimErrorCode::ToolTooLarge { cycle: 251, tool_diameter: 10.0, size: 8.0 })
        );
    }

    #[test]
    fn cycle_252_circles_and_the_helical_plunge() {
        // Ø 30, tool radius 5: tool-centre circles of radius 5 and 10 (stepover 5), full circles
        // of four quarters each, DR−; Q366 = 1: one helix turn of radius 5 (the tool radius)
        // from 2 above down to −2.
        let p = pocket(252, &[(223, 30.0), (351, -1.0), (366, 1.0), (201, -2.0)]);
        let moves = circular_252(&p, DVec3::new(10.0, 0.0, 5.0), 5.0).expect("cycle");
        let got = path(&moves);
        assert_eq!(
            got[..4],
            [
                (10.0, 0.0, 2.0, FMAX),
                (15.0, 0.0, 2.0, PLUNGE),
                (15.0, 0.0, -2.0, PLUNGE),
                (10.0, 0.0, -2.0, MILL)
            ]
        );
        let helix = moves[2].arc.expect("helix");
        assert_eq!((helix.centre, helix.sweep), (DVec2::new(10.0, 0.0), -std::f64::consts::TAU));
        let radii: Vec<f64> = moves
            .iter()
            .filter(|m| m.arc.is_some() && m.feed == MILL)
            .map(|m| (m.target.truncate() - DVec2::new(10.0, 0.0)).length())
            .collect();
        let r = |x: f64| (x * 1e9).round() / 1e9;
        assert_eq!(
            radii.into_iter().map(r).collect::<Vec<_>>(),
            vec![5.0; 4].into_iter().chain(vec![10.0; 4]).collect::<Vec<_>>()
        );
        assert!(moves.iter().filter_map(|m| m.arc).all(|a| a.sweep < 0.0));
    }

    #[test]
    fn cycle_253_slot_along_its_turned_centre_line() {
        // Slot 50 × 20 turned by 90° about its left end (Q367 = 1) at the origin: centre (0, 25),
        // arc centres (0, 10) and (0, 40); tool radius 5: the centre line from (0, 10) to (0, 40)
        // first, then the stadium of radius 5 about it.
        let p = pocket(253, &[(218, 50.0), (219, 20.0), (374, 90.0), (367, 1.0), (201, -2.0)]);
        let moves = slot_253(&p, DVec3::new(0.0, 0.0, 5.0), 5.0).expect("cycle");
        let got = path(&moves);
        #[rustfmt::skip]
        let want = vec![
            (0.0, 0.0, 20.0, FMAX), (0.0, 25.0, 20.0, FMAX), (0.0, 25.0, 2.0, FMAX),
            (0.0, 25.0, -2.0, PLUNGE),
            (0.0, 40.0, -2.0, MILL), (0.0, 10.0, -2.0, MILL), (0.0, 40.0, -2.0, MILL),
            (0.0, 45.0, -2.0, MILL), (-5.0, 40.0, -2.0, MILL), (-5.0, 10.0, -2.0, MILL),
            (0.0, 5.0, -2.0, MILL), (5.0, 10.0, -2.0, MILL), (5.0, 40.0, -2.0, MILL),
            (0.0, 45.0, -2.0, MILL),
            (0.0, 45.0, 0.0, FMAX), (0.0, 25.0, 0.0, FMAX), (0.0, 25.0, 20.0, FMAX),
        ];
        assert_eq!(got, want);
    }

    #[test]
    fn cycle_254_circular_slot_about_its_centre() {
        // Centre (0, 0), pitch circle Ø 60, from 0° over 90°, width 10 with a tool of radius 5:
        // the tool runs the centre arc from (30, 0) to (0, 30) and back; two slots 180° apart.
        let p = pocket(
            254,
            &[
                (219, 10.0),
                (375, 60.0),
                (376, 0.0),
                (248, 90.0),
                (216, 0.0),
                (217, 0.0),
                (377, 2.0),
                (378, 180.0),
                (201, -2.0),
            ],
        );
        let moves = circular_slot_254(&p, DVec3::new(0.0, 0.0, 30.0), 5.0).expect("cycle");
        let got = path(&moves);
        #[rustfmt::skip]
        let want = vec![
            (30.0, 0.0, 30.0, FMAX), (30.0, 0.0, 2.0, FMAX), (30.0, 0.0, -2.0, PLUNGE),
            (0.0, 30.0, -2.0, MILL), (30.0, 0.0, -2.0, MILL), (30.0, 0.0, 0.0, FMAX), (30.0, 0.0, 20.0, FMAX),
            (-30.0, 0.0, 20.0, FMAX), (-30.0, 0.0, 2.0, FMAX), (-30.0, 0.0, -2.0, PLUNGE),
            (0.0, -30.0, -2.0, MILL), (-30.0, 0.0, -2.0, MILL), (-30.0, 0.0, 0.0, FMAX), (-30.0, 0.0, 20.0, FMAX),
        ];
        assert_eq!(got, want);
    }
}
