//! The machining cycles the simulator moves, as tool paths in the I-CS: the tool axis is the
//! I-CS Z axis, so every cycle runs in the tilted plane. The drilling family 200, 201, 203, 205,
//! 208 ([`drill`]), face milling 232 and 233 ([`face`]), the pockets and slots 251–254
//! ([`pocket`]) and the point patterns of `PATTERN DEF`, 220 and 221 ([`pattern`]). Other cycles
//! are reported as not simulated by the caller.
//!
//! Each cycle is a pure function of its parameters ([`Params`]), the tool position where it is
//! called and the tool radius, returning the moves in order ([`CycleMove`]: end point, feed or
//! FMAX, optionally an arc or helix about the tool axis). The sequences follow the "Cycle run"
//! sections of the HEIDENHAIN cycle manuals (named per cycle); what the manuals leave open is in
//! [`crate::unconfirmed`] (`CycleConventions`, `PatternConventions`). Dwell times (Q210, Q211)
//! move no axis and are not part of the animation.

mod drill;
mod face;
mod pattern;
mod pocket;

use glam::{DVec2, DVec3};

use crate::unconfirmed;

use super::error::SimErrorCode;
use super::note::Note;

pub(crate) use pattern::{PatternValues, circle_220, grid_221, pattern_points};

/// An arc or helix about the tool axis from the previous position to [`CycleMove::target`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ArcTo {
    /// The centre in the working plane (I-CS X, Y).
    pub centre: DVec2,
    /// Turned angle, radians; positive = DR+ (counter-clockwise seen against the tool axis).
    pub sweep: f64,
}

/// One move of a cycle: I-CS target and feed (`None` = FMAX); straight unless `arc`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CycleMove {
    pub target: DVec3,
    pub feed: Option<f64>,
    pub arc: Option<ArcTo>,
}

/// What a cycle call moves, with a note when the simulation simplifies a parameter.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct CycleRun {
    pub moves: Vec<CycleMove>,
    pub note: Option<Note>,
}

/// Upper bound of moves one cycle call may produce (a tiny stepover must not exhaust memory).
pub(crate) const MAX_CYCLE_MOVES: usize = 100_000;

/// Distances below this are one point (mm).
const EPS: f64 = 1e-9;

pub(crate) fn rapid(target: DVec3) -> CycleMove {
    CycleMove { target, feed: None, arc: None }
}

pub(crate) fn feed(target: DVec3, f: f64) -> CycleMove {
    CycleMove { target, feed: Some(f), arc: None }
}

fn arc(target: DVec3, centre: DVec2, sweep: f64, f: f64) -> CycleMove {
    CycleMove { target, feed: Some(f), arc: Some(ArcTo { centre, sweep }) }
}

/// What a cycle parameter measures, for the unit of an `INCH` program: lengths convert by 25.4,
/// feeds like F ([`crate::ast::Unit`]), the rest (angles, counts, dwell times, factors, modes)
/// stays as written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Quantity {
    Length,
    Feed,
    Other,
}

/// The quantity of each parameter the simulated cycles read, as the cycle manuals describe the
/// parameter (Q200 set-up clearance, Q206 feed rate for plunging, Q224 angle of rotation, …);
/// `None` for a parameter no simulated cycle reads.
pub(crate) fn quantity(q: u32) -> Option<Quantity> {
    match q {
        // Clearances, depths, infeeds, surface and positions, side lengths, corner radius,
        // diameters, allowances, pitch, retraction and chip-breaking distances.
        200..=205
        | 212
        | 216..=220
        | 223
        | 225..=227
        | 237
        | 238
        | 244
        | 256..=259
        | 334
        | 335
        | 338
        | 342
        | 357
        | 368
        | 369
        | 375
        | 379
        | 386 => Some(Quantity::Length),
        // Plunging, milling, retraction, pre-positioning and finishing feed rates.
        206..=208 | 253 | 385 => Some(Quantity::Feed),
        // Dwell times, counts, angles, machining operation, strategies, directions, factors.
        210
        | 211
        | 213
        | 215
        | 224
        | 241..=243
        | 245..=248
        | 301
        | 350
        | 351
        | 365..=367
        | 370
        | 374
        | 376..=378
        | 389
        | 395 => Some(Quantity::Other),
        _ => None,
    }
}

/// The evaluated parameters of one cycle definition; the last line of a number wins, as the
/// control reads a definition top to bottom. Cycles 220/221, `PATTERN DEF` and `CYCL CALL POS`
/// override some of them for the cycle they call ([`Params::set`]).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Params {
    pub cycle: u32,
    values: Vec<(u32, f64)>,
}

impl Params {
    pub fn new(cycle: u32, values: Vec<(u32, f64)>) -> Params {
        Params { cycle, values }
    }

    /// A parameter the cycle needs: missing is the control's "parameter missing" error.
    pub fn get(&self, index: u32) -> Result<f64, SimErrorCode> {
        self.values
            .iter()
            .rev()
            .find(|(i, _)| *i == index)
            .map(|(_, v)| *v)
            .ok_or(SimErrorCode::CycleParamMissing { cycle: self.cycle, param: index })
    }

    /// A parameter that later software versions added, with the value that keeps the older
    /// behaviour when a program does not write it.
    pub fn or(&self, index: u32, default: f64) -> f64 {
        self.get(index).unwrap_or(default)
    }

    pub fn set(&mut self, index: u32, value: f64) {
        self.values.push((index, value));
    }
}

/// The moves of cycle `p.cycle` called at `pos` (I-CS) with a tool of radius `tool_radius`;
/// `Ok(None)` when the cycle is not simulated.
pub(crate) fn run(p: &Params, pos: DVec3, tool_radius: f64) -> Result<Option<CycleRun>, SimErrorCode> {
    let r = tool_radius.max(0.0);
    let moves = match p.cycle {
        200 => drill::drill_200(p, pos)?,
        201 => drill::ream_201(p, pos)?,
        203 => drill::drill_203(p, pos)?,
        205 => drill::peck_205(p, pos)?,
        208 => drill::bore_mill_208(p, pos, r)?,
        232 => return face::face_mill_232(p, pos, r).map(Some),
        233 => return face::face_mill_233(p, pos, r).map(Some),
        251 => pocket::rectangular_251(p, pos, r)?,
        252 => pocket::circular_252(p, pos, r)?,
        253 => pocket::slot_253(p, pos, r)?,
        254 => pocket::circular_slot_254(p, pos, r)?,
        _ => return Ok(None),
    };
    let reciprocating = matches!(p.cycle, 251..=254) && p.or(366, 0.0) == 2.0;
    let note = (reciprocating && unconfirmed::POCKET_RECIPROCATING_AS_VERTICAL)
        .then_some(Note::ReciprocatingPlunge { cycle: p.cycle });
    Ok(Some(CycleRun { moves, note }))
}

/// Q201 as the control checks it: the depth below the surface (≥ 0); a positive Q201 is the
/// control's error ([`unconfirmed::CYCLE_POSITIVE_DEPTH_IS_ERROR`]).
fn depth(p: &Params) -> Result<f64, SimErrorCode> {
    let depth = p.get(201)?;
    if depth > 0.0 && unconfirmed::CYCLE_POSITIVE_DEPTH_IS_ERROR {
        return Err(SimErrorCode::DepthSign { cycle: p.cycle, value: depth });
    }
    Ok(depth.abs())
}

/// The levels from `top` down to `bottom` in cuts of at most `step`: full cuts, the last one the
/// rest ("the depth does not have to be a multiple of the plunging depth"; a plunging depth of 0
/// or more than the depth goes to depth in one cut).
fn levels(top: f64, bottom: f64, step: f64) -> Vec<f64> {
    let total = top - bottom;
    if total <= EPS {
        return vec![bottom];
    }
    let step = if step > 0.0 && step < total { step } else { total };
    let mut out = Vec::new();
    let mut z = top;
    while z - bottom > EPS && out.len() < MAX_CYCLE_MOVES {
        z = (z - step).max(bottom);
        if z - bottom <= EPS {
            z = bottom;
        }
        out.push(z);
    }
    out
}

/// `v` turned by `deg` degrees about the tool axis.
fn turned(v: DVec2, deg: f64) -> DVec2 {
    DVec2::from_angle(deg.to_radians()).rotate(v)
}

/// The unit vector at `deg` degrees from the reference axis.
fn polar(deg: f64) -> DVec2 {
    DVec2::from_angle(deg.to_radians())
}

#[cfg(test)]
pub(crate) mod test_support {
    use super::*;

    /// Parameters of cycle `cycle` from a list.
    pub fn params(cycle: u32, list: &[(u32, f64)]) -> Params {
        Params::new(cycle, list.to_vec())
    }

    /// `(x, y, z, feed)` of each move, rounded to µm, for comparing with hand-written lists.
    pub fn path(moves: &[CycleMove]) -> Vec<(f64, f64, f64, Option<f64>)> {
        let r = |x: f64| (x * 1000.0).round() / 1000.0 + 0.0;
        moves.iter().map(|m| (r(m.target.x), r(m.target.y), r(m.target.z), m.feed)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every parameter a simulated cycle reads has its quantity, so an `INCH` program converts
    /// it: a new `p.get(n)` without an entry in [`quantity`] fails here.
    #[test]
    fn every_parameter_read_has_a_quantity() {
        let sources = [
            include_str!("cycles.rs"),
            include_str!("cycles/drill.rs"),
            include_str!("cycles/face.rs"),
            include_str!("cycles/pattern.rs"),
            include_str!("cycles/pocket.rs"),
            include_str!("interp/cycle_calls.rs"),
        ];
        let mut read = Vec::new();
        for src in sources {
            for pat in ["get(", "or(", "set("] {
                for (at, _) in src.match_indices(pat) {
                    let digits: String =
                        src[at + pat.len()..].chars().take_while(char::is_ascii_digit).collect();
                    if let Ok(q) = digits.parse::<u32>()
                        && q >= 200
                    {
                        read.push(q);
                    }
                }
            }
        }
        assert!(read.len() > 60, "the scan finds the reads: {read:?}");
        let missing: Vec<u32> = read.into_iter().filter(|&q| quantity(q).is_none()).collect();
        assert!(missing.is_empty(), "parameters without a quantity: {missing:?}");
        assert_eq!(quantity(201), Some(Quantity::Length));
        assert_eq!(quantity(206), Some(Quantity::Feed));
        assert_eq!(quantity(224), Some(Quantity::Other));
    }
}
