//! The transformation chain I-CS → WPL-CS → W-CS (DOMAIN.md §1, §6):
//!
//! ```text
//! p_W = d_W + R · M_W · (d_I + M_I · Rz(rot) · p_I)
//! ```
//! `d_W`, `M_W`: datum shift and mirror programmed while no tilt was active (they move the tilt
//! origin and mirror the whole program incl. the spatial angles, DOMAIN.md §6, seed S3);
//! `R`: the machine-realised orientation of the working plane (for spatial-angle functions
//! R = M_W·R_programmed·M_W, derived: M_W·R_prog·q = (M_W·R_prog·M_W)·(M_W·q));
//! `d_I`, `M_I`, `rot`: datum shift and mirror programmed while a tilt was active, and every
//! rotation (TRANS ROTATION / cycle 10), all in the WPL-CS ([`unconfirmed::TRANSFORM_LEVELS`]).

use glam::{DMat3, DVec3};
use serde::Serialize;

use crate::unconfirmed;

use super::geometry::Affine;

/// Which coordinate system a datum shift or mirror acts in.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Level {
    /// Programmed before the tilt: acts in the W-CS (moves/mirrors the WPL-CS).
    Wcs,
    /// Programmed with a tilt active: acts in the WPL-CS (gives the I-CS).
    Wpl,
}

/// The active transformations, as the status line lists them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum ActiveTransform {
    Datum { level: Level, offset: [f64; 3] },
    Mirror { level: Level, axes: [bool; 3] },
    Rotation { deg: f64 },
    Tilt { spatial: [f64; 3], tool_axis: [f64; 3] },
}

/// The programmed transformations (everything except the preset).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Transforms {
    pub datum_w: DVec3,
    pub mirror_w: [bool; 3],
    /// The machine-realised working-plane orientation R (columns = tilted axes in W-CS), if a
    /// tilt (PLANE or cycle 19) is active.
    pub tilt: Option<DMat3>,
    pub datum_i: DVec3,
    pub mirror_i: [bool; 3],
    pub rotation: f64,
}

impl Default for Transforms {
    fn default() -> Self {
        Transforms {
            datum_w: DVec3::ZERO,
            mirror_w: [false; 3],
            tilt: None,
            datum_i: DVec3::ZERO,
            mirror_i: [false; 3],
            rotation: 0.0,
        }
    }
}

/// diag(±1) of a mirror.
#[must_use]
pub fn mirror_matrix(axes: [bool; 3]) -> DMat3 {
    let s = |b: bool| if b { -1.0 } else { 1.0 };
    DMat3::from_diagonal(DVec3::new(s(axes[0]), s(axes[1]), s(axes[2])))
}

impl Transforms {
    /// The level a datum shift or mirror programmed now acts on.
    #[must_use]
    pub fn level_now(&self) -> Level {
        if self.tilt.is_some() || !unconfirmed::TRANSFORM_LEVELS { Level::Wpl } else { Level::Wcs }
    }

    /// M_W.
    #[must_use]
    pub fn mirror_w_matrix(&self) -> DMat3 {
        mirror_matrix(self.mirror_w)
    }

    /// The working plane R (identity when nothing is tilted).
    #[must_use]
    pub fn r(&self) -> DMat3 {
        self.tilt.unwrap_or(DMat3::IDENTITY)
    }

    /// WPL-CS → W-CS: q ↦ d_W + R·q.
    #[must_use]
    pub fn wpl_to_wcs(&self) -> Affine {
        Affine { m: self.r(), v: self.datum_w }
    }

    /// I-CS → WPL-CS: p ↦ M_W·(d_I + M_I·Rz(rot)·p).
    #[must_use]
    pub fn ics_to_wpl(&self) -> Affine {
        let mw = self.mirror_w_matrix();
        let lin = mw * mirror_matrix(self.mirror_i) * DMat3::from_rotation_z(self.rotation.to_radians());
        Affine { m: lin, v: mw * self.datum_i }
    }

    /// I-CS → W-CS, the whole chain.
    #[must_use]
    pub fn ics_to_wcs(&self) -> Affine {
        self.wpl_to_wcs().after(&self.ics_to_wpl())
    }

    /// The list for the status line, in chain order W-CS → I-CS.
    #[must_use]
    pub fn list(&self, spatial: Option<[f64; 3]>) -> Vec<ActiveTransform> {
        let mut out = Vec::new();
        if self.datum_w != DVec3::ZERO {
            out.push(ActiveTransform::Datum { level: Level::Wcs, offset: self.datum_w.to_array() });
        }
        if self.mirror_w.iter().any(|&b| b) {
            out.push(ActiveTransform::Mirror { level: Level::Wcs, axes: self.mirror_w });
        }
        if let Some(r) = self.tilt {
            out.push(ActiveTransform::Tilt {
                spatial: spatial.unwrap_or_else(|| crate::orientation::to_spatial(&r)),
                tool_axis: r.z_axis.to_array(),
            });
        }
        if self.datum_i != DVec3::ZERO {
            out.push(ActiveTransform::Datum { level: Level::Wpl, offset: self.datum_i.to_array() });
        }
        if self.mirror_i.iter().any(|&b| b) {
            out.push(ActiveTransform::Mirror { level: Level::Wpl, axes: self.mirror_i });
        }
        if self.rotation != 0.0 {
            out.push(ActiveTransform::Rotation { deg: self.rotation });
        }
        out
    }
}
