//! Where a field of a machine description is: the one name of a field that [`super::validate`]
//! reports a problem at and the machine editor shows it at, so neither writes the schema's
//! paths as strings of its own. Written as the JSON path (`chain[1].direction`,
//! `geometry.linear_limits.X`, `collision[0].box.size`).

use std::fmt;

use serde::{Serialize, Serializer};

use crate::lang::Lang;

/// A field (or a group of fields) of a machine description.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MachinePath {
    /// The description as a whole (unreadable JSON); written as nothing.
    Whole,
    Id,
    Name(Lang),
    Description(Lang),
    /// The chain as a whole (the number of its axes).
    Chain,
    /// A field of rotary axis `i` of the chain (0 the slave, 1 the master).
    Joint(usize, JointField),
    Geometry(GeometryField),
    /// Collision body `i` as a whole (its shape).
    Body(usize),
    /// A field of collision body `i`.
    BodyField(usize, BodyField),
}

/// A field of a rotary axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JointField {
    Axis,
    Carrier,
    Direction,
    Pivot,
    Endless,
    Limits,
}

/// A field of the geometry.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GeometryField {
    Preset,
    /// The limits of linear axis 0 = X, 1 = Y, 2 = Z.
    LinearLimits(usize),
    RapidLinear,
    RapidRotary,
    Start,
    TableTop,
}

/// A field of a collision body.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BodyField {
    Name(Lang),
    Carrier,
    BoxCenter,
    BoxSize,
    CylinderBase,
    CylinderDirection,
    CylinderRadius,
    CylinderHeight,
}

impl fmt::Display for MachinePath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            MachinePath::Whole => Ok(()),
            MachinePath::Id => f.write_str("id"),
            MachinePath::Name(l) => write!(f, "name.{}", l.code()),
            MachinePath::Description(l) => write!(f, "description.{}", l.code()),
            MachinePath::Chain => f.write_str("chain"),
            MachinePath::Joint(i, field) => {
                let name = match field {
                    JointField::Axis => "axis",
                    JointField::Carrier => "carrier",
                    JointField::Direction => "direction",
                    JointField::Pivot => "pivot",
                    JointField::Endless => "endless",
                    JointField::Limits => "limits",
                };
                write!(f, "chain[{i}].{name}")
            }
            MachinePath::Geometry(field) => {
                f.write_str("geometry.")?;
                match field {
                    GeometryField::Preset => f.write_str("preset"),
                    GeometryField::LinearLimits(a) => {
                        write!(f, "linear_limits.{}", ["X", "Y", "Z"][a.min(2)])
                    }
                    GeometryField::RapidLinear => f.write_str("rapid_linear"),
                    GeometryField::RapidRotary => f.write_str("rapid_rotary"),
                    GeometryField::Start => f.write_str("start"),
                    GeometryField::TableTop => f.write_str("table_top"),
                }
            }
            MachinePath::Body(i) => write!(f, "collision[{i}]"),
            MachinePath::BodyField(i, field) => {
                write!(f, "collision[{i}].")?;
                match field {
                    BodyField::Name(l) => write!(f, "name.{}", l.code()),
                    BodyField::Carrier => f.write_str("carrier"),
                    BodyField::BoxCenter => f.write_str("box.center"),
                    BodyField::BoxSize => f.write_str("box.size"),
                    BodyField::CylinderBase => f.write_str("cylinder.base"),
                    BodyField::CylinderDirection => f.write_str("cylinder.direction"),
                    BodyField::CylinderRadius => f.write_str("cylinder.radius"),
                    BodyField::CylinderHeight => f.write_str("cylinder.height"),
                }
            }
        }
    }
}

/// Serialised as its written form (the CLI's JSON and the editor's `data-path`).
impl Serialize for MachinePath {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}
