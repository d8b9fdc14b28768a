//! Every convention the sources do NOT confirm, decided once, here.
//!
//! DOMAIN.md marks these points **UNCONFIRMED**: no seed and no public manual states them. The
//! rest of the core calls the constants and functions below instead of repeating a choice, so a
//! correction after checking a real control (or the HEIDENHAIN programming station) is a one-line
//! change in this file. The UI cites a decision through [`Decision`] (stable id, German and English
//! text); the solver lists the decisions that influenced a result in its explanation.
//!
//! A leaf of data: it imports nothing of the crate above the angle helpers and the bilingual
//! text (`scripts/core_layers.py` checks that core has no import circle).

use glam::DVec3;

mod decision;
pub use decision::Decision;

/// PLANE PROJECTED: the two plane traces `u1` (in the Z/X plane, from PROPR) and `u2` (in the
/// Y/Z plane, from PROMIN), angles in degrees.
///
/// Source: DOMAIN.md §2.3; the sign is **UNCONFIRMED**, chosen so that a single nonzero angle
/// matches SPATIAL (PROPR ≙ SPB, PROMIN ≙ SPA, oracle 12). Flip the sign of the `sin` terms here
/// if a real control disagrees.
#[must_use]
pub fn projected_traces(propr_deg: f64, promin_deg: f64) -> (DVec3, DVec3) {
    let (s1, c1) = propr_deg.to_radians().sin_cos();
    let (s2, c2) = promin_deg.to_radians().sin_cos();
    (DVec3::new(c1, 0.0, -s1), DVec3::new(0.0, c2, s2))
}

/// PLANE VECTOR: tilted X from the base vector `b` once the tool axis `z` (unit) is fixed.
/// Returns `None` when `b` is parallel to `z` (nothing left after the projection).
///
/// Source: DOMAIN.md §2.4, Gram–Schmidt keeping N (**UNCONFIRMED**, but the manual's own example
/// has B·N ≈ −0.349, so the control must correct one of them).
#[must_use]
pub fn vector_frame(b: DVec3, z: DVec3) -> Option<DVec3> {
    let x = b - b.dot(z) * z;
    let len = x.length();
    (len > crate::angle::PARALLEL_EPS * b.length()).then(|| x / len)
}

/// PLANE RELATIV with nothing tilted refers to the untilted W-CS (identity).
/// DOMAIN.md §2.6: **UNCONFIRMED** wording, consistent with seed S1.
pub const RELATIV_UNTILTED_REFERENCE: glam::DMat3 = glam::DMat3::IDENTITY;

/// Path from the current rotary positions to a candidate: the **sum** of the axis travels in
/// degrees (each already the short way round for an endless axis).
///
/// DOMAIN.md §3.3: the metric (sum vs max) is **UNCONFIRMED**; the sum reproduces every seed row
/// ("both need 45+90", "C travel 15 vs 195").
#[must_use]
pub fn path_length(travels: impl IntoIterator<Item = f64>) -> f64 {
    travels.into_iter().map(f64::abs).sum()
}

/// Two paths closer than this (degrees) count as equal and go to [`tie_prefers`].
/// Numerical choice (derived), so that 45+90 from two different atan2 calls ties.
pub const TIE_TOLERANCE_DEG: f64 = 1e-6;

/// Tie rule for equal paths: `true` if the candidate with master value `a` wins over `b`.
///
/// DOMAIN.md §3.3: **UNCONFIRMED** guess that fits seed S2 row 1 (from A0 C0 the control takes
/// A+45 C+90): prefer the master axis on the positive side, i.e. the larger master value.
#[must_use]
pub fn tie_prefers(master_a: f64, master_b: f64) -> bool {
    master_a >= master_b
}

/// COORD ROT in the singular case: value of the free axis, given its current value.
/// DOMAIN.md §3.4: "the table is not moved" \[S0\]; whether TNC7 sends it to 0 is **UNCONFIRMED**.
#[must_use]
pub fn coord_rot_free_axis(current_deg: f64) -> f64 {
    current_deg
}

/// TABLE ROT in the singular case: the free table axis takes `TABLE_ROT_SIGN · γ₀`, where γ₀ is
/// the rotation about the tool axis still missing with the free axis at 0 (DOMAIN.md §3.4).
/// With +1, `SPA0 SPB0 SPC+45 TABLE ROT` on A/C gives `C+45`, γ = 0 (sign **UNCONFIRMED**);
/// with −1 the table would turn the other way and γ = 90° would remain as a coordinate rotation.
pub const TABLE_ROT_SIGN: f64 = 1.0;

/// TABLE ROT when the free axis is a head axis (e.g. C of a C/A fork head at A0): the seed
/// says TABLE ROT "turns the C rotary axis" \[S0\], i.e. a table. **UNCONFIRMED**: a free head
/// axis is not turned; the rotation is done mathematically as with COORD ROT.
pub const TABLE_ROT_ON_HEAD_AXIS: bool = false;

/// Neither COORD ROT nor TABLE ROT programmed. **UNCONFIRMED**: COORD ROT (`false`: the table
/// is not moved); `plane::TransformMode::unprogrammed` reads it.
pub const DEFAULT_TABLE_ROT: bool = false;

/// SEQ± / SYM±: a master value exactly on the reference (0° for SEQ, the symmetry point for
/// SYM) counts as the `+` side. **UNCONFIRMED** (DOMAIN.md §3.3 only says "positive range").
pub const ZERO_COUNTS_AS_PLUS: bool = true;

/// SEQ± with both solutions on the requested side: the control "takes the nearer one" \[S2\].
/// **UNCONFIRMED** order: `true` = pick the nearer one among all on that side and then check
/// its limits (an out-of-limit pick is "Winkel nicht erlaubt", like any selected solution \[S2\]);
/// `false` would drop out-of-limit ones first.
pub const SEQ_NEAREST_BEFORE_LIMITS: bool = true;

/// Every master axis has two symmetry positions 180° apart \[S2\]; the seed's B/A example calls
/// A = −90 "the" symmetry point. **UNCONFIRMED** rule that gives −90 (and 0 for A/C): the
/// position where the tool axis points along the **+** direction of the slave axis.
pub const SYMMETRY_POINT_CODIRECTIONAL: bool = true;

/// How a non-endless axis writes a solution angle `deg` (known modulo 360): `true` if the
/// canonical value in (−180, +180] is used whenever it lies inside the limits; otherwise the
/// in-limit value ±360 nearest to the current position. **UNCONFIRMED**; it reproduces the
/// seed's "C travel 15 vs 195" (C+90 from C−105, not C−270).
pub const PREFER_CANONICAL_VALUE: bool = true;

/// PLANE AXIAL: a rotary axis not written in the block keeps its current position.
/// **UNCONFIRMED** (DOMAIN.md §2.7 is silent).
pub const AXIAL_MISSING_AXIS_KEEPS_POSITION: bool = true;

/// PLANE RESET MOVE/TURN: "the rotary axes also return" \[S0\] — to 0° (**UNCONFIRMED**).
pub const RESET_TARGET_DEG: f64 = 0.0;

/// A tool axis the kinematics cannot reach: the iTNC says "Angle cannot be calculated"
/// [M:iTNC-tech-p761]; the German wording "Winkel nicht berechenbar" is **UNCONFIRMED** (our
/// translation). `false` would report it as "Winkel nicht erlaubt" instead.
pub const UNREACHABLE_IS_SEPARATE_ERROR: bool = true;

/// EULPR range: seed S1's syntax table and the manual say −180…+180 \[S1\]\[M:iTNC-p498\], but
/// S1's chamfer tip programs `EULPR+270`. **UNCONFIRMED** how the control treats 270: we follow
/// the stated input range, so `EULPR+270` is refused ("Winkel nicht erlaubt") and the shipped
/// chamfer sample writes the same orientation as `EULPR-90`.
pub const EULPR_LIMIT: f64 = 180.0;

/// PLANE VECTOR component limit: ±9.9999999 (TNC 320/620/640) or ±99.9999999 (later iTNC 530)
/// [M:320-p352]\[M:iTNC-p500\]. **UNCONFIRMED** which control we mimic: the larger one.
pub const VECTOR_COMPONENT_LIMIT: f64 = 99.9999999;

/// PLANE POINTS coordinate limit in mm. **UNCONFIRMED** (DOMAIN.md §5): the usual Klartext
/// coordinate range ±99999.9999.
pub const POINTS_COORD_LIMIT: f64 = 99_999.999_9;

/// `DIST` (MOVE) and `MB` (TURN): 0…99999.9999 mm. The manuals call DIST the distance between
/// the centre of rotation and the tool tip and MB the retraction path in the active tool-axis
/// direction (TNC 620 user's manual p. 556, DOMAIN.md §4; seed S0 §2.3.3 "Abstand",
/// "Rückzug"), and the PLANE dialog refuses a negative value; no source prints their input
/// range or says whether a sign is allowed. **UNCONFIRMED**: not negative, at most the usual
/// Klartext length ±99999.9999 (TNC 426/430 manual, technical information).
pub const POSITIONING_LENGTH_LIMIT: f64 = 99_999.999_9;

/// PLANE AXIAL angle limit. **UNCONFIRMED** (DOMAIN.md §5); the machine's limit switches apply
/// on top of it when the solver positions the axes.
pub const AXIAL_LIMIT: f64 = 99_999.999_9;

// ---------------------------------------------------------------------------------------------
// Simulator (issue 5): conventions of the block-by-block run that no source confirms.
// ---------------------------------------------------------------------------------------------

/// The simulator's error wordings other than "Winkel nicht erlaubt"/"Entered angle not permitted"
/// \[S2\] are **UNCONFIRMED** (our wording in the control's style): "Q-Parameter nicht definiert",
/// "Zyklus nicht definiert", "Zyklusparameter fehlt", "Endschalter X+", "Achse nicht vorhanden",
/// "Label-Nummer nicht vorhanden", "Verschachtelung zu tief", "Rechenfehler", "Satz fehlerhaft",
/// "Vorzeichen Tiefe falsch", and for the contour (issue 15) "Kreismittelpunkt undefiniert",
/// "Kreis-Endposition falsch", "Kreisradius zu klein", "Tangentialer Anschluss nicht möglich",
/// "RND/CHF nicht möglich", and their English versions.
pub const SIM_MESSAGES_UNCONFIRMED: bool = true;

/// Datum shift and mirror act in the W-CS when programmed with no tilt active (they move and
/// mirror the tilt origin, DOMAIN.md §6 \[S3\]) and in the WPL-CS when a tilt is active; TRANS
/// ROTATION / cycle 10 always acts in the WPL-CS. Within a level the order is fixed: shift,
/// then mirror, then rotation, all about the shifted datum. TRANS DATUM RESET and TRANS MIRROR
/// RESET clear both levels; a WPL-CS shift survives PLANE RESET with its numbers. DOMAIN.md §6
/// calls the composition in detail **UNCONFIRMED**. `false` would put every transformation in
/// the WPL-CS list.
pub const TRANSFORM_LEVELS: bool = true;

/// Block numbers in a file read from outside (a CAM system's, a shop's): the control's editor
/// numbers the blocks itself (TNC 620 ISO manual, "Programme eröffnen und eingeben": the TNC
/// numbers the blocks automatically), and the blocks run in their order in the file. What the
/// control says on reading numbers that are missing, repeated, not ascending, written `N…` or
/// followed directly by a comment (`12;`) is **UNCONFIRMED**: the trainer reads them all and says each kind once per file, as a warning
/// (`true`); `false` would make them errors again.
pub const IMPORT_BLOCK_NUMBERS_ARE_WARNINGS: bool = true;

/// The control applies the kinematic transformation (linear axes computed from the rotary axis
/// positions so that programmed points land on the workpiece) only while a tilt (PLANE or
/// cycle 19) is active; without it, the rotary axes are ignored (3-axis behaviour, `L Z…` moves
/// the Z axis) even after `PLANE RESET STAY` left them tilted. **UNCONFIRMED**.
pub const COMPENSATION_ONLY_WHEN_TILTED: bool = true;

/// `M128` (TCPM) acts from the start of its block, so a rotary move in the same block is
/// already compensated; `M129` acts at the end of its block. TCPM compensates whether or not a
/// tilt is active, and the tool tip runs straight between programmed points (as `FUNCTION TCPM
/// F TCP AXIS POS` would). DOMAIN.md §6 names M128/M129, not when they act. **UNCONFIRMED**.
pub const TCPM_FROM_BLOCK_START: bool = true;

/// `TOOL CALL`, and a block with `M91` or `M92`, while TCPM (`M128` or `FUNCTION TCPM`) is on
/// stop the run with an error; `false` would switch TCPM off before the block instead. The
/// manuals say to reset TCPM before them [M:scribd-TCPM] (DOMAIN.md §6), not what the control
/// does when it is not. **UNCONFIRMED**.
pub const TCPM_REFUSES_TOOL_CALL_M91_M92: bool = true;

/// `PLANE … MOVE` without `DIST`: the centre of rotation is the tool tip itself (DIST = 0), so
/// the tool tip keeps its place on the workpiece. **UNCONFIRMED** default.
pub const MOVE_DEFAULT_DIST: f64 = 0.0;

/// `MB`/`MB MAX` retract at rapid traverse (FMAX), before the swivel at the block's feed.
/// **UNCONFIRMED** (DOMAIN.md §4 gives no feed for the retract).
pub const MB_RETRACT_AT_RAPID: bool = true;

/// `M140 MB MAX F5000`: a feed written right after `MB` is the retraction's feed (without one it
/// runs at rapid). CAM post-processors write it (NX, converters for DMU machines); the manuals
/// at hand name only `M140 MB…`. **UNCONFIRMED**.
pub const M140_FEED_AFTER_MB: bool = true;

/// `M92`: the block's coordinates refer to an additional machine datum whose distance from the
/// machine datum the machine tool builder sets per axis (TNC 426B ISO manual, "Behavior with
/// M92 — Additional machine datum"). No shipped machine's data gives that distance, so the M92
/// datum is taken as the machine datum: `M92` moves as `M91` does (a CAM post's
/// `L Z+0 R0 FMAX M92` goes up to the top of Z, not to the workpiece's Z0). **UNCONFIRMED**.
pub const M92_AT_MACHINE_DATUM: bool = true;

/// `MB MAX` retracts "to just before the software limit switch" (DOMAIN.md §4): how far before
/// is machine data the sources do not give; each linear axis stops this many mm inside its
/// limits. **UNCONFIRMED**.
pub const MB_MAX_CLEARANCE: f64 = 1.0;

/// The tool holder of the collision check ([`crate::sim::collision`]): the tool table gives only
/// the tool's length (gauge point to tip, holder included) and radius, no holder. Taken as a
/// cylinder ending at the gauge point, 35 % of the tool length long but at most 50 mm, of radius
/// max(tool radius, 12 mm) + 14 mm: the sizes the 3D view draws (`web/src/render/machine_parts.rs`),
/// a shrink-fit chuck of a small mill. **UNCONFIRMED** (no source; machine data on a real
/// control).
#[must_use]
pub fn holder(tool_length: f64, tool_radius: f64) -> Holder {
    Holder { length: (0.35 * tool_length).min(50.0), radius: tool_radius.max(12.0) + 14.0 }
}

/// A tool length `L` (table or `TOOL DEF`, before DL) below this many mm is read as the
/// difference to a zero tool, the older of the two ways the manuals give to determine L ("the
/// difference in length between the tool and a zero tool, or with a tool presetter", TNC 370 /
/// TNC 426 user's manuals, ch. 4.2; its sign negative for a tool shorter than the zero tool): a
/// length measured from the spindle's gauge point is never this short, and CAM posts write such
/// tools as `TOOL DEF 101 L+1.000 R+0.000` or `L-55.606`. **UNCONFIRMED** threshold; the control
/// itself cannot tell the two apart.
pub const ZERO_TOOL_DIFFERENCE_BELOW: f64 = 30.0;

/// The zero tool's own length for [`ZERO_TOOL_DIFFERENCE_BELOW`], mm: the simulated tool is
/// `ZERO_TOOL_LENGTH + L` long (at least 1 mm). **UNCONFIRMED**: a shop's zero tool is not in the
/// program.
pub const ZERO_TOOL_LENGTH: f64 = 100.0;

/// The simulated length of a tool whose table or `TOOL DEF` length is `l` (mm): `l` itself, or
/// the zero tool's length plus `l` when `l` reads as a difference ([`ZERO_TOOL_DIFFERENCE_BELOW`]).
#[must_use]
pub fn physical_tool_length(l: f64) -> f64 {
    if l < ZERO_TOOL_DIFFERENCE_BELOW { (ZERO_TOOL_LENGTH + l).max(1.0) } else { l }
}

/// On a machine with a table top, a program without a blank written in numbers (no BLK FORM, or
/// one from parameters) has its datum this many mm above the table's centre, as if a 50 mm
/// blank were clamped there ([`crate::sim::placed`]). **UNCONFIRMED**: nothing in such a
/// program says where its datum is.
pub const DATUM_ABOVE_TABLE: f64 = 50.0;

/// The tool holder's size ([`holder`]), mm.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Holder {
    pub length: f64,
    pub radius: f64,
}

/// `PLANE … MOVE|TURN` and `L` blocks that move rotary axes: a programmed F counts as °/min for
/// the rotary share of the motion (the duration is the longer of the linear and rotary shares);
/// `F AUTO` is the feed of the last `TOOL CALL`. Only the animation speed depends on it.
/// **UNCONFIRMED**.
pub const ROTARY_FEED_DEG_PER_MIN: bool = true;

/// Cycle 19 inputs are spatial angles (the OEM parameter `planeOrientation` (201202) decides on
/// a real control \[S3\]); `false` would treat them as axis angles (forward kinematics, no mirror
/// effect). **UNCONFIRMED** which one a given machine uses.
pub const CYCLE19_INPUT_SPATIAL: bool = true;

/// Cycle 19 does not move the rotary axes itself (like STAY: "compensation for an axis starts
/// when that axis moves" [M:320cyc-p258]); the program positions them, e.g.
/// `L A+Q120 C+Q122 R0 FMAX`. All angles 0 (or none) in `19.1` resets the tilt.
/// **UNCONFIRMED** for machines whose OEM lets cycle 19 position the axes automatically.
pub const CYCLE19_MOVES_AXES: bool = false;

/// Maximum nesting of subprogram calls (`CALL LBL` without `REP`). **UNCONFIRMED** number.
pub const MAX_CALL_DEPTH: usize = 19;

/// `CALL LBL n REP m` is a program-section repeat: jump back to `LBL n` m times, so the section
/// runs m+1 times; `CALL LBL n` without REP is a subprogram call that returns at `LBL 0`.
/// A `REP` to a label after the call is treated the same way (jump, no return).
/// **UNCONFIRMED** for the forward case.
pub const REP_IS_SECTION_REPEAT: bool = true;

/// After `M30`/`M2` the blocks up to `END PGM` are listed as "not executed" (a state with the
/// axes unchanged and a message), so every block of a program has a row; subprograms after
/// M30 are therefore never executed by running on. **UNCONFIRMED** presentation choice (the
/// control simply stops).
pub const LIST_BLOCKS_AFTER_END: bool = true;

/// A machining cycle with a positive depth Q201: the control's machine parameter `displayDepthErr`
/// decides; we report an error (its usual setting, **UNCONFIRMED**).
pub const CYCLE_POSITIVE_DEPTH_IS_ERROR: bool = true;

/// Cycle 232: maximum stepover from Q370. Cycles 251/252 define "Q370 × tool radius = stepover
/// factor k"; cycle 232 calls Q370 "max. overlap factor" without a formula here.
/// **UNCONFIRMED**: stepover = Q370 × tool radius; the rows are then spread evenly over Q219.
#[must_use]
pub fn cycle232_stepover(q370: f64, tool_radius: f64) -> f64 {
    q370 * tool_radius
}

/// Cycle 232 strategies Q389 = 1 (one direction) and 2 (spiral) are simulated as the meander of
/// Q389 = 0, with a message. **UNCONFIRMED** simplification.
pub const CYCLE232_STRATEGY: bool = true;

/// A datum shift (TRANS DATUM AXIS, or one cycle 7 definition over its sub-blocks) with an
/// absolute coordinate replaces the whole shift of its level: axes not written are 0. With only
/// incremental coordinates the axes not written keep the active shift. **UNCONFIRMED**.
pub const DATUM_ABSOLUTE_REPLACES: bool = true;

/// Q120–Q122 ("tilting the working plane with mathematical angles: rotary axis coordinates
/// calculated by the TNC", the preassigned Q parameters of the iTNC 530/TNC 640 manuals) are
/// written by tilts with spatial angles (every PLANE function except AXIAL and RESET, cycle 19)
/// and left unchanged by PLANE AXIAL and PLANE RESET. **UNCONFIRMED** for AXIAL and RESET.
pub const Q120_ONLY_FOR_SPATIAL_TILTS: bool = true;

/// `C`/`CR`/`CP` without `DR`: the last programmed direction of rotation (the manuals say so
/// for the polar arc without direction, iTNC 530 DIN/ISO manual p. 211); before any `DR` in the
/// program: DR+ (+1). **UNCONFIRMED** for the first arc.
pub const ARC_DIRECTION_WITHOUT_DR: f64 = 1.0;

/// `C`: how far (mm) the end point may lie off the circle through the start point around CC
/// before "Kreis-Endposition falsch"; also how much longer than the diameter a `CR` chord may be.
/// The control's tolerance is a machine parameter not given in the sources; **UNCONFIRMED**.
pub const CIRCLE_END_TOLERANCE: f64 = 0.01;

/// A coordinate of the tool axis in `C`, `CR`, `CT` (`C X… Y… Z…`) moves linearly while the arc
/// turns, like the helix of `CP … IZ…`. The manuals describe the helix only for `CP`;
/// **UNCONFIRMED** for the Cartesian arcs.
pub const ARC_TOOL_AXIS_LINEAR: bool = true;

/// `CP IPA… DR±`: the turned angle is |IPA| in the direction of DR (the manual asks for both and
/// shows them with the same sign, `CP IPA-1800 IZ+5 DR-`); without DR the sign of IPA gives the
/// direction. **UNCONFIRMED** when the signs disagree.
pub const CP_IPA_DIRECTION_FROM_DR: bool = true;

/// Cycles 203/205: the next infeed after `made` infeeds is Q202 (`first`) less the decrement
/// Q212 per infeed, never less than the minimum plunging depth Q205 (the manual); when that
/// leaves no positive step (Q205 = 0) or the step reaches past the depth, the `rest` is drilled
/// in one step. **UNCONFIRMED** for the exhausted decrement.
#[must_use]
pub fn decremented_infeed(first: f64, decrement: f64, min: f64, made: usize, rest: f64) -> f64 {
    let step = (first - decrement * made as f64).max(min);
    if step > 0.0 && step < rest { step } else { rest }
}

/// Cycles 203/205: the chip-breaking retraction by Q256 runs at the retraction feed Q208 (the
/// manuals give the distance, not the feed). **UNCONFIRMED**.
pub const CHIP_BREAK_AT_RETRACTION_FEED: bool = true;

/// Cycle 205: the advanced stop distance after the infeed that reached `reached` of `total`:
/// Q258 (`upper`) at the top, Q259 (`lower`) at the depth, linear in between (the manual: "the
/// control changes the advanced stop distance between the first and last plunging depth at the
/// same rate"; the measure of "rate" is **UNCONFIRMED**: the depth).
#[must_use]
pub fn advanced_stop_distance(upper: f64, lower: f64, reached: f64, total: f64) -> f64 {
    if total > 0.0 { upper + (lower - upper) * (reached / total).clamp(0.0, 1.0) } else { upper }
}

/// Cycle 205: a retraction feed Q208 of 0 retracts at the plunging feed Q206, as cycles 201 and
/// 203 state. **UNCONFIRMED** for 205.
pub const CYCLE205_Q208_ZERO_IS_Q206: bool = true;

/// Cycle 205 defined without Q208 (the parameter list of older software, as CAM posts for it
/// still write it: Q200 … Q211, Q379, Q253): retracts at this feed, rapid traverse, as the old
/// pecking cycle does ("the tool is then retracted at rapid traverse (FMAX)", TNC 370 manual,
/// cycle 1 PECKING) and as PREDEF sets Q208. **UNCONFIRMED** what the older cycle 205 did.
pub const CYCLE205_WITHOUT_Q208_FEED: f64 = CYCLE_FMAX_FEED;

/// Cycle 208 with a pre-drilled diameter Q342: the helices widen the hole by at most this many
/// tool radii each ("the control calculates the lateral infeed itself"). **UNCONFIRMED**.
pub const BORE_MILL_STEPOVER: f64 = 1.0;

/// Pockets with helical plunging (Q366 = 1): the helix radius in tool radii (less when the
/// pocket is narrower; vertical when there is no room) and one turn per infeed, as the tool's
/// plunge angle ANGLE is not in the tool table. **UNCONFIRMED**.
pub const POCKET_HELIX: f64 = 1.0;

/// Pockets with reciprocating plunging (Q366 = 2) are simulated with a vertical plunge, with a
/// message. **UNCONFIRMED** simplification.
pub const POCKET_RECIPROCATING_AS_VERTICAL: bool = true;

/// Slots 253 and 254 have no path overlap Q370: their roughing paths are at most this many
/// tool radii apart. **UNCONFIRMED**.
pub const SLOT_STEPOVER: f64 = 1.0;

/// Cycle 254 with Q367 = 1, 2, 3 ("left slot circle", "centre line", "right slot circle"): the
/// tool position is the centre line's start (at Q376), middle or end. **UNCONFIRMED** mapping of
/// left/right to start/end.
pub const CIRCULAR_SLOT_REFERENCE: bool = true;

/// Cycle 233 is simulated through cycle 232's meander (strategies Q389 and the limits
/// Q347–Q349 with a message). **UNCONFIRMED** simplification.
pub const CYCLE233_AS_232: bool = true;

/// `PATTERN DEF` PAT and FRAME are machined row by row, every other row backwards, like cycle
/// 221 (the manual gives no order for them). **UNCONFIRMED**.
pub const PATTERN_GRID_ORDER: bool = true;

/// Cycle 220 with the stepping angle Q247 = 0: the manual computes it "from the starting and
/// stopping angles and the number of repetitions". **UNCONFIRMED** how: a full circle
/// (|Q246 − Q245| = 360) in `n` equal steps, otherwise from start to stop, both included.
#[must_use]
pub fn cycle220_step(start: f64, stop: f64, n: usize) -> f64 {
    let span = stop - start;
    if (span.abs() - 360.0).abs() < 1e-9 {
        span / n.max(1) as f64
    } else if n > 1 {
        span / (n - 1) as f64
    } else {
        0.0
    }
}

/// Cycles 220/221: after the last machining position the tool goes to the 2nd set-up
/// clearance, whatever Q301 said between the positions. **UNCONFIRMED**.
pub const PATTERN_CYCLE_END: bool = true;

/// `CYCL CALL POS` with the tool below the workpiece surface: "first in the tool axis to the
/// clearance height" is taken as the 2nd set-up clearance Q204 above the surface.
/// **UNCONFIRMED**.
pub const CYCL_CALL_POS_CLEARANCE: bool = true;

/// `M89` (modal cycle call) calls the cycle at the end of its own block too, not only at every
/// following positioning block (the TNC 306/406 technical manual: "modal cycle-call M89 at end
/// of block", "for every following positioning block"). **UNCONFIRMED** for its own block.
pub const M89_CALLS_AT_ITS_BLOCK: bool = true;

/// `CYCL CALL PAT F…`: the feed applies to the moves between the points (FMAX or none: rapid).
/// **UNCONFIRMED**.
pub const CYCL_CALL_PAT_FEED_BETWEEN_POINTS: bool = true;
/// RL/RR: the transition arc around an outside corner (the control's default; M197 would
/// extend the elements instead, not simulated) is run at the start of the block after the corner,
/// so after each block the tool stands perpendicular to the end of its element (the manual's
/// picture of the compensated path; which block the arc belongs to it does not say).
/// **UNCONFIRMED**; `false` runs it at the end of the block before the corner.
pub const COMP_CORNER_ARC_WITH_NEXT_BLOCK: bool = true;

/// `APPR CT`/`LCT`, `DEP CT`/`LCT`: `R` is the radius of the tool centre path ("the tool moves
/// on a circular path"); `false`: the radius on the contour side, the tool centre path then
/// smaller or larger by the tool radius like any compensated arc. **UNCONFIRMED**.
pub const APPR_DEP_RADIUS_OF_CENTRE_PATH: bool = true;

/// A decimal comma (`X-49,000`), a blank between an address letter and its value
/// (`L Z 25.000`), a point after an M function (`M128.`), `R0` in `DEP LT`/`DEP LN`,
/// `CYCLE DEF` for an old-style cycle, a straight line without its `L` (`Z0.0 B0.0 FMAX`), a
/// speed in a path block (`L Z-45 S6000`), a feed in a tool definition (`TOOL DEF1 L+30 F300`)
/// and a comment in parentheses after the words (`L IX-80 (MODAL DRILL POINT)`),
/// as some CAM posts and exporting
/// simulators write: read as the canonical spelling, said once per kind and file
/// (`parse::Lenient`). **UNCONFIRMED** whether the control reads them on import.
pub const IMPORT_LENIENT_SPELLINGS: bool = true;

/// A setup-sheet header's cuboid blank (`(Quader: QX100 QY90 QZ20)`, before `BEGIN PGM`, as a
/// training simulator exports it) is used when the program has no BLK FORM: in mm, with the
/// datum on the top face at the corner of smallest X and Y (`BLK FORM 0.1 Z X+0 Y+0 Z-20`,
/// `0.2 X+100 Y+90 Z+0`), the placement training programs mostly use. **UNCONFIRMED**: the
/// header does not say where its datum is.
pub const HEADER_BLANK_AT_DATUM: bool = true;

/// A cycle defined without its parameter lines (`CYCL DEF 200 BOHREN`, then `Q200 = 2`,
/// `Q201 = -15` as blocks of their own, as a training simulator's examples write it) takes its
/// parameters from the Q parameters Q200…Q1199 at its call: the user's manuals name that range
/// the cycles' parameters, "globally effective". **UNCONFIRMED** whether the control calls such
/// a definition at all; `false` stops at the call ("parameters left out").
pub const CYCLE_PARAMS_FROM_GLOBAL_Q: bool = true;

/// `CALL LBL n REP Q…`: the number of repeats from a parameter, as some shop programs write
/// it; read, and the parameter must hold a whole number 0…65534 when the block runs.
/// **UNCONFIRMED** whether the control's dialog takes a parameter there.
pub const REP_FROM_PARAMETER: bool = true;

/// `END PGM` with another name than `BEGIN PGM` (`BEGIN PGM YL-01 MM` … `END PGM 100 MM`, as
/// programs renamed outside the control come): a warning, and the program ends there as if the
/// names agreed — the program name is the control's bookkeeping, written from the file name, as
/// the block numbers are. **UNCONFIRMED**: no manual in `shared/` says what the control does with
/// such a file; refusing a program whose every block is right would turn away what the trainee
/// brought for a name the simulation never uses.
pub const END_PGM_NAME_IS_BOOKKEEPING: bool = true;

/// `FN 28: TABREAD Q… = row / "columns"` of a table the simulator does not have: each parameter
/// it fills that has no value yet gets 0, one with a value keeps it, and the block says so (as a
/// tool nobody defined runs with a stated default tool). **UNCONFIRMED**: the control reads the
/// table, which a simulated run does not have.
pub const TABREAD_ASSUMES_ZERO: bool = true;

/// `CC` naming the two axes of another main plane than the working plane (`CC X… Z…` with tool
/// axis Z, as CAM systems write ramps) puts the circles `C`, `CP` and the polar lines `LP` after
/// it in that plane, with the reference axis and DR+ of that plane as working plane (ZX: from Z,
/// DR+ turning Z towards X) — the three working planes of the manuals' "Circle center CC"
/// table. Radius compensation there is refused (`CompensationOffPlane`). **UNCONFIRMED**: no
/// manual page in `shared/` describes circles outside the working plane.
pub const ARC_PLANE_OF_CC: bool = true;

/// `BEGIN PGM … INCH`: lengths are in inches (25.4 mm) and F in 1/10 inch/min, so one unit of F
/// is 2.54 mm/min (`F100` = 10 inch/min), as HEIDENHAIN's Klartext manuals give the feed unit
/// of inch programs; the rotary share of a motion keeps F as written, in °/min. The simulator
/// works in mm and converts each length and feed where a block uses it; Q parameters keep the
/// program's numbers. **UNCONFIRMED**: no manual page in `shared/` states the feed unit.
pub const INCH_FEED_MM_PER_MIN: f64 = 2.54;

/// A cycle parameter written `FMAX` (`Q253=FMAX`, `Q208=FMAX`): the cycle's moves at this feed
/// in mm/min, the largest the cycle dialogs take ("0…99999.999, alternatively FMAX"), so they
/// are drawn and timed as the cycle's own feed moves. **UNCONFIRMED**: the control moves at
/// the machine's rapid.
pub const CYCLE_FMAX_FEED: f64 = 99_999.0;

/// A cycle parameter written `PREDEF`: the value of the global program settings (`GLOBAL DEF`),
/// which the trainer does not simulate. These are the values it assumes (set-up clearance Q200
/// 2 mm, 2nd set-up clearance Q204 50 mm, pre-positioning feed Q253 750 mm/min, retraction feed
/// Q208 rapid, chip-breaking distance Q256 0.2 mm, dwell times Q210/Q211 0 s, overlap factor
/// Q370 1, climb milling Q351 +1, helical plunge Q366 1); any other parameter written `PREDEF`
/// stops the run with a message. A cycle 208 written without Q351 (programs for older software)
/// takes the same climb milling. **UNCONFIRMED**: a real control takes them from its
/// GLOBAL DEF settings.
#[must_use]
pub fn predef(param: u32) -> Option<f64> {
    Some(match param {
        200 => 2.0,
        204 => 50.0,
        253 => 750.0,
        208 => CYCLE_FMAX_FEED,
        256 => 0.2,
        210 | 211 => 0.0,
        370 | 351 | 366 => 1.0,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_decision_is_listed_once_with_a_text_in_both_languages() {
        for (i, d) in Decision::ALL.iter().enumerate() {
            assert!(!Decision::ALL[..i].contains(d), "{d:?} listed twice");
            let t = d.text();
            assert!(!t.de.is_empty() && !t.en.is_empty() && t.de != t.en, "{d:?}");
        }
        let texts: Vec<_> = Decision::ALL.iter().map(|d| d.text().de).collect();
        for (i, t) in texts.iter().enumerate() {
            assert!(!texts[..i].contains(t), "the same text twice: {t}");
        }
    }
}
