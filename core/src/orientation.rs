//! Every PLANE function as one rotation **R** whose columns are the tilted X', Y', Z' axes in
//! W-CS coordinates (DOMAIN.md §2), and the way back from any R to spatial and Euler angles.
//!
//! Tool axis t = R·ez = third column. Angles are degrees throughout; glam's elementary rotations
//! are active and right-handed, exactly the matrices of DOMAIN.md §2.

use glam::{DMat3, DVec3};
use serde::Serialize;

use crate::angle::{acosd, atan2d, clean, wrap180, wrap360};
use crate::axes::AxisValues;
use crate::lang::Text;
use crate::machine::Machine;
use crate::plane::{PROJECTED_LIMIT, PlaneDef, RelAxis, RotaryAxis};
use crate::unconfirmed;

pub use crate::angle::PARALLEL_EPS;

/// Which vector of a PLANE block is meant in an error.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum VectorName {
    /// `BX BY BZ` of PLANE VECTOR.
    Base,
    /// `NX NY NZ` of PLANE VECTOR.
    Normal,
    /// P1→P2 of PLANE POINTS.
    P1P2,
}

impl VectorName {
    fn name(self) -> Text {
        match self {
            VectorName::Base => Text::new("Basisvektor (BX, BY, BZ)", "base vector (BX, BY, BZ)"),
            VectorName::Normal => Text::new("Normalenvektor (NX, NY, NZ)", "normal vector (NX, NY, NZ)"),
            VectorName::P1P2 => Text::new("Strecke P1→P2", "segment P1→P2"),
        }
    }
}

/// A PLANE block whose values cannot define a working plane. Every variant carries the numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "code", rename_all = "snake_case")]
pub enum PlaneError {
    /// NaN or infinity in a block word (e.g. from a Q parameter).
    NotFinite { word: &'static str, value: f64 },
    /// A value outside the input range of DOMAIN.md §5.
    OutOfRange { word: &'static str, value: f64, min: f64, max: f64 },
    /// A vector of length (practically) zero.
    ZeroVector { vector: VectorName, length: f64 },
    /// PLANE VECTOR: base vector parallel to the normal vector; `angle` between them in degrees.
    BaseParallelToNormal { base: [f64; 3], normal: [f64; 3], angle: f64 },
    /// PLANE POINTS: the three points lie on one line; `sine` of the angle at P1.
    CollinearPoints { p1: [f64; 3], p2: [f64; 3], p3: [f64; 3], sine: f64 },
    /// PLANE AXIAL needs a machine for its forward kinematics.
    MachineRequired,
    /// PLANE AXIAL names an axis the machine does not have.
    AxisNotOnMachine { axis: RotaryAxis, machine: String },
    /// PLANE AXIAL names an axis twice.
    DuplicateAxis { axis: RotaryAxis },
}

impl PlaneError {
    /// The message with the numbers. A range error on an angle says what the control says,
    /// "Winkel nicht erlaubt" / "Entered angle not permitted" \[S2\]; on other values
    /// "Eingabewert falsch" / "Invalid input" (the parser's wording for the same check).
    #[must_use]
    pub fn message(&self) -> Text {
        let t = Text::owned;
        match self {
            PlaneError::NotFinite { word, value } => t(
                format!("Ungültiger Zahlenwert: {word} = {value}"),
                format!("Invalid number: {word} = {value}"),
            ),
            PlaneError::OutOfRange { word, value, min, max } => {
                let angle =
                    !matches!(word.as_bytes().first(), Some(b'B' | b'N' | b'P')) || word.starts_with("PRO");
                let (de, en) = if angle {
                    ("Winkel nicht erlaubt", "Entered angle not permitted")
                } else {
                    ("Eingabewert falsch", "Invalid input")
                };
                t(
                    format!("{de}: {word} = {value} (erlaubt {min} … {max})"),
                    format!("{en}: {word} = {value} (allowed {min} … {max})"),
                )
            }
            PlaneError::ZeroVector { vector, length } => {
                let name = vector.name();
                t(
                    format!("{} hat die Länge null ({length})", name.de),
                    format!("The {} has zero length ({length})", name.en),
                )
            }
            PlaneError::BaseParallelToNormal { angle, .. } => t(
                format!("Basisvektor parallel zum Normalenvektor (Winkel {angle}°)"),
                format!("Base vector parallel to the normal vector (angle {angle}°)"),
            ),
            PlaneError::CollinearPoints { sine, .. } => t(
                format!("Die drei Punkte liegen auf einer Geraden (sin Winkel bei P1 = {sine})"),
                format!("The three points lie on one line (sine of the angle at P1 = {sine})"),
            ),
            PlaneError::MachineRequired => Text::new(
                "PLANE AXIAL: keine Maschinenkinematik gewählt",
                "PLANE AXIAL: no machine kinematics selected",
            ),
            PlaneError::AxisNotOnMachine { axis, machine } => t(
                format!("Achse {axis} nicht vorhanden (Maschine {machine})"),
                format!("Axis {axis} does not exist (machine {machine})"),
            ),
            PlaneError::DuplicateAxis { axis } => {
                t(format!("Achse {axis} mehrfach programmiert"), format!("Axis {axis} programmed twice"))
            }
        }
    }
}

impl std::fmt::Display for PlaneError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message().en)
    }
}

impl std::error::Error for PlaneError {}

/// What a PLANE block needs besides its own words.
#[derive(Debug, Clone, Copy)]
pub struct Context<'a> {
    /// The active tilt before this block (PLANE RELATIV composes on it); identity if none
    /// ([`unconfirmed::RELATIV_UNTILTED_REFERENCE`]).
    pub active: DMat3,
    /// The machine, needed by PLANE AXIAL only.
    pub machine: Option<&'a Machine>,
    /// Current rotary axis positions (PLANE AXIAL: incremental words and axes not written).
    pub current: AxisValues,
}

impl Default for Context<'_> {
    fn default() -> Self {
        Context {
            active: unconfirmed::RELATIV_UNTILTED_REFERENCE,
            machine: None,
            current: AxisValues::default(),
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Elementary rotations and the PLANE functions
// ---------------------------------------------------------------------------------------------

/// PLANE SPATIAL: R = Rz(SPC)·Ry(SPB)·Rx(SPA) (DOMAIN.md §2.1, extrinsic X-Y-Z, \[S0\]).
#[must_use]
pub fn spatial(spa: f64, spb: f64, spc: f64) -> DMat3 {
    DMat3::from_rotation_z(spc.to_radians())
        * DMat3::from_rotation_y(spb.to_radians())
        * DMat3::from_rotation_x(spa.to_radians())
}

/// PLANE EULER: R = Rz(EULPR)·Rx(EULNU)·Rz(EULROT) (DOMAIN.md §2.2, intrinsic Z-X'-Z'', \[S1\]).
#[must_use]
pub fn euler(eulpr: f64, eulnu: f64, eulrot: f64) -> DMat3 {
    DMat3::from_rotation_z(eulpr.to_radians())
        * DMat3::from_rotation_x(eulnu.to_radians())
        * DMat3::from_rotation_z(eulrot.to_radians())
}

/// PLANE PROJECTED (DOMAIN.md §2.3): Z' = normalize(u1 × u2), X'0 = u1, Y'0 = Z' × X'0,
/// R = [X'0 Y'0 Z']·Rz(ROT). The sign of the traces is **UNCONFIRMED** and lives in
/// [`unconfirmed::projected_traces`]. Unvalidated: use [`orientation`] for checked input.
#[must_use]
pub fn projected(propr: f64, promin: f64, rot: f64) -> Option<DMat3> {
    let (u1, u2) = unconfirmed::projected_traces(propr, promin);
    let z = u1.cross(u2).try_normalize()?;
    let y = z.cross(u1);
    Some(DMat3::from_cols(u1, y, z) * DMat3::from_rotation_z(rot.to_radians()))
}

/// PLANE VECTOR (DOMAIN.md §2.4): Z' = N/|N|, X' = normalize(B − (B·Z')Z'), Y' = Z' × X'.
pub fn vector(base: DVec3, normal: DVec3) -> Result<DMat3, PlaneError> {
    let n_len = normal.length();
    if n_len < PARALLEL_EPS {
        return Err(PlaneError::ZeroVector { vector: VectorName::Normal, length: n_len });
    }
    let b_len = base.length();
    if b_len < PARALLEL_EPS {
        return Err(PlaneError::ZeroVector { vector: VectorName::Base, length: b_len });
    }
    let z = normal / n_len;
    let x = unconfirmed::vector_frame(base, z).ok_or_else(|| PlaneError::BaseParallelToNormal {
        base: base.to_array(),
        normal: normal.to_array(),
        angle: acosd(base.dot(normal) / (b_len * n_len)),
    })?;
    Ok(DMat3::from_cols(x, z.cross(x), z))
}

/// PLANE POINTS (DOMAIN.md §2.5, [M:iTNC530iso-p476]): X' = normalize(P2−P1),
/// Z' = normalize((P2−P1) × (P3−P1)), Y' = Z' × X'.
pub fn points(p1: DVec3, p2: DVec3, p3: DVec3) -> Result<DMat3, PlaneError> {
    let d12 = p2 - p1;
    let d13 = p3 - p1;
    let l12 = d12.length();
    if l12 < PARALLEL_EPS {
        return Err(PlaneError::ZeroVector { vector: VectorName::P1P2, length: l12 });
    }
    let normal = d12.cross(d13);
    // Sine of the angle at P1 (0 when P3 = P1 or the points are collinear).
    let sine = normal.length() / (l12 * d13.length()).max(f64::MIN_POSITIVE);
    if sine < PARALLEL_EPS || !sine.is_finite() {
        return Err(PlaneError::CollinearPoints {
            p1: p1.to_array(),
            p2: p2.to_array(),
            p3: p3.to_array(),
            sine,
        });
    }
    let x = d12 / l12;
    let z = normal.normalize();
    Ok(DMat3::from_cols(x, z.cross(x), z))
}

/// PLANE RELATIV (DOMAIN.md §2.6): R_new = R_active · Rx|Ry|Rz(angle).
#[must_use]
pub fn relativ(active: DMat3, axis: RelAxis, angle: f64) -> DMat3 {
    let a = angle.to_radians();
    active
        * match axis {
            RelAxis::Spa => DMat3::from_rotation_x(a),
            RelAxis::Spb => DMat3::from_rotation_y(a),
            RelAxis::Spc => DMat3::from_rotation_z(a),
        }
}

/// PLANE AXIAL: the absolute axis positions the block asks for (incremental words added to the
/// current position; axes not written per [`unconfirmed::AXIAL_MISSING_AXIS_KEEPS_POSITION`]).
pub fn axial_targets(
    axes: &[crate::plane::AxialAngle<f64>],
    machine: &Machine,
    current: &AxisValues,
) -> Result<AxisValues, PlaneError> {
    let mut out = AxisValues::default();
    for joint in machine.joints() {
        let keep =
            if unconfirmed::AXIAL_MISSING_AXIS_KEEPS_POSITION { current.get(joint.axis) } else { None };
        out.set(joint.axis, keep.unwrap_or(0.0));
    }
    let mut seen = AxisValues::default();
    for word in axes {
        if machine.joint(word.axis).is_none() {
            return Err(PlaneError::AxisNotOnMachine { axis: word.axis, machine: machine.id.clone() });
        }
        if seen.get(word.axis).is_some() {
            return Err(PlaneError::DuplicateAxis { axis: word.axis });
        }
        seen.set(word.axis, word.value);
        let base = if word.incremental { current.get(word.axis).unwrap_or(0.0) } else { 0.0 };
        out.set(word.axis, base + word.value);
    }
    Ok(out)
}

/// The orientation R of any PLANE function, after validating its words (DOMAIN.md §2, §5).
pub fn orientation(def: &PlaneDef<f64>, ctx: &Context<'_>) -> Result<DMat3, PlaneError> {
    validate(def)?;
    Ok(match def {
        PlaneDef::Spatial { spa, spb, spc } => spatial(*spa, *spb, *spc),
        PlaneDef::Euler { eulpr, eulnu, eulrot } => euler(*eulpr, *eulnu, *eulrot),
        PlaneDef::Projected { propr, promin, rot } => {
            // validate() keeps PROPR/PROMIN inside ±89.9999°, where u1 × u2 never vanishes; the
            // fallback error still reports the numbers should the ranges ever be widened.
            projected(*propr, *promin, *rot).ok_or(PlaneError::OutOfRange {
                word: "PROPR",
                value: *propr,
                min: -PROJECTED_LIMIT,
                max: PROJECTED_LIMIT,
            })?
        }
        PlaneDef::Vector { base, normal } => vector(DVec3::from_array(*base), DVec3::from_array(*normal))?,
        PlaneDef::Points { p1, p2, p3 } => {
            points(DVec3::from_array(*p1), DVec3::from_array(*p2), DVec3::from_array(*p3))?
        }
        PlaneDef::Relativ { axis, angle } => relativ(ctx.active, *axis, *angle),
        PlaneDef::Axial { axes } => {
            let machine = ctx.machine.ok_or(PlaneError::MachineRequired)?;
            machine.forward(&axial_targets(axes, machine, &ctx.current)?)
        }
        PlaneDef::Reset => DMat3::IDENTITY,
    })
}

/// Checks every word of a PLANE definition: finite, and inside its input range
/// ([`crate::plane::Word::range`], the one table the parser and the dialog use too).
pub fn validate(def: &PlaneDef<f64>) -> Result<(), PlaneError> {
    for (word, &value) in def.values() {
        let word_text = word.as_str();
        if !value.is_finite() {
            return Err(PlaneError::NotFinite { word: word_text, value });
        }
        let r = word.range();
        if !r.contains(value) {
            return Err(PlaneError::OutOfRange { word: word_text, value, min: r.min, max: r.max });
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Inverse: any R → spatial angles, Euler angles
// ---------------------------------------------------------------------------------------------

/// Below this, cos SPB (or sin EULNU) counts as zero: the singular (gimbal-lock) case.
/// Numerical choice (derived): well below the 4-decimal display, well above f64 noise.
pub const GIMBAL_EPS: f64 = 1e-10;

/// Spatial angles `[SPA, SPB, SPC]` of any rotation (DOMAIN.md §2.1 inverse):
/// SPB = atan2(−R31, √(R11²+R21²)), SPA = atan2(R32, R33), SPC = atan2(R21, R11).
///
/// Ranges: SPA, SPC in (−180, 180], SPB in [−90, 90]. Singular case cos SPB = 0 (tool axis along
/// ±X): only SPC ∓ SPA is fixed; the choice here is **SPA = 0** and SPC = atan2(−R12, R22)
/// (derived: with SPA = 0, R = Rz(SPC)·Ry(±90), whose second column is (−sin SPC, cos SPC, 0)).
#[must_use]
pub fn to_spatial(r: &DMat3) -> [f64; 3] {
    // glam is column-major: r.col(j)[i] = R(i+1)(j+1).
    let (r11, r21, r31) = (r.x_axis.x, r.x_axis.y, r.x_axis.z);
    let (r32, r33) = (r.y_axis.z, r.z_axis.z);
    let cb = r11.hypot(r21);
    let spb = atan2d(-r31, cb);
    let (spa, spc) = if cb < GIMBAL_EPS {
        (0.0, atan2d(-r.y_axis.x, r.y_axis.y))
    } else {
        (atan2d(r32, r33), atan2d(r21, r11))
    };
    [clean(wrap180(spa)), clean(spb), clean(wrap180(spc))]
}

/// Euler angles `[EULPR, EULNU, EULROT]` of any rotation (DOMAIN.md §2.2 inverse):
/// EULNU = acos(R33), EULPR = atan2(R13, −R23), EULROT = atan2(R31, R32) mod 360.
///
/// Ranges: EULPR in (−180, 180], EULNU in [0, 180], EULROT in [0, 360). Singular case
/// sin EULNU = 0 (tool axis ±Z): only EULPR ± EULROT is fixed; the choice here is **EULROT = 0**
/// and EULPR = atan2(R21, R11) (derived: R = Rz(EULPR)·Rx(0 or 180), first column (cos, sin, 0)).
#[must_use]
pub fn to_euler(r: &DMat3) -> [f64; 3] {
    let (r13, r23, r33) = (r.z_axis.x, r.z_axis.y, r.z_axis.z);
    let (r31, r32) = (r.x_axis.z, r.y_axis.z);
    let sn = r13.hypot(r23);
    let nu = atan2d(sn, r33);
    let (pr, rot) = if sn < GIMBAL_EPS {
        (atan2d(r.x_axis.y, r.x_axis.x), 0.0)
    } else {
        (atan2d(r13, -r23), atan2d(r31, r32))
    };
    [clean(wrap180(pr)), clean(nu), clean(wrap360(rot))]
}

/// The tool axis t = R·ez (DOMAIN.md §2).
#[must_use]
pub fn tool_axis(r: &DMat3) -> DVec3 {
    r.z_axis
}

/// R written row by row, as DOMAIN.md §10 lists matrices (and the CLI prints them).
#[must_use]
pub fn rows(r: &DMat3) -> [[f64; 3]; 3] {
    let t = r.transpose();
    [t.x_axis.to_array().map(clean), t.y_axis.to_array().map(clean), t.z_axis.to_array().map(clean)]
}
