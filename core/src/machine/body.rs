//! Collision bodies of a machine (JSON key `collision`, issue 17): boxes and cylinders, each
//! fixed to what carries it, which [`crate::sim::collision`] places for given axis values.
//!
//! JSON form, one entry per body:
//! ```json
//! { "name": {"de": "Rundtisch", "en": "rotary table"}, "carrier": "C",
//!   "cylinder": {"base": [0,0,-230], "direction": [0,0,1], "radius": 80, "height": 30} }
//! { "name": {"de": "Maschinenbett", "en": "machine bed"}, "carrier": "bed",
//!   "box": {"center": [0,60,-310], "size": [760,760,60]} }
//! ```
//! `carrier` is `bed` (the machine frame: never moves), `head` (moves with the linear axes and
//! every head axis) or the letter of a **table** axis of the chain (turns with that axis and with
//! every table axis that carries it, i.e. comes after it in the chain workpiece → tool).
//! Coordinates as the chain's pivots: bed and table bodies in M-CS with every axis at home, head
//! bodies relative to the spindle gauge point (one tool length above the tip) with the head at
//! home. A box is axis-parallel in its carrier's home frame.

use std::borrow::Cow;

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::lang::Text;

/// One entry of `collision` as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyDef {
    pub name: Text,
    /// `"bed"`, `"head"` or a table axis letter of the chain.
    pub carrier: Cow<'static, str>,
    /// Exactly one of `box` and `cylinder`.
    #[serde(rename = "box", default, skip_serializing_if = "Option::is_none")]
    pub cuboid: Option<BoxDef>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cylinder: Option<CylinderDef>,
}

/// `box`: centre and edge lengths along X, Y, Z of the carrier's home frame, mm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxDef {
    pub center: [f64; 3],
    pub size: [f64; 3],
}

/// `cylinder`: the centre of one end face, the unit direction to the other, radius and height, mm.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CylinderDef {
    pub base: [f64; 3],
    pub direction: [f64; 3],
    pub radius: f64,
    pub height: f64,
}

/// What carries a validated body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum BodyCarrier {
    /// The machine frame.
    Bed,
    /// The table axis with this index in the chain (workpiece → tool).
    Table { joint: usize },
    /// The head: linear axes and every head axis.
    Head,
}

/// A validated shape in its carrier's home frame.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "shape", rename_all = "snake_case")]
pub enum BodyShape {
    Box {
        center: DVec3,
        half: DVec3,
    },
    /// `direction` is a unit vector; `radius`, `height` > 0.
    Cylinder {
        base: DVec3,
        direction: DVec3,
        radius: f64,
        height: f64,
    },
}

/// A validated collision body.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Body {
    pub name: Text,
    pub carrier: BodyCarrier,
    pub shape: BodyShape,
}

impl Body {
    /// The description as written (the carrier's word given by the caller, who knows the chain).
    #[must_use]
    pub fn to_def(&self, carrier: Cow<'static, str>) -> BodyDef {
        let (cuboid, cylinder) = match self.shape {
            BodyShape::Box { center, half } => {
                (Some(BoxDef { center: center.to_array(), size: (2.0 * half).to_array() }), None)
            }
            BodyShape::Cylinder { base, direction, radius, height } => (
                None,
                Some(CylinderDef { base: base.to_array(), direction: direction.to_array(), radius, height }),
            ),
        };
        BodyDef { name: self.name.clone(), carrier, cuboid, cylinder }
    }
}
