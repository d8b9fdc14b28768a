//! What the 3D view draws, as plain data: the machine state (axes, frames, tool, blank), the
//! optional ghost of the other candidate, and which triads are shown. The parent fills it (later
//! from the simulator's per-block states); the renderer only reads it.
//!
//! Coordinates: M-CS, Z up, mm. Frames attached to the workpiece (W-CS, WPL-CS), the blank and
//! the toolpath are given **on the table at home** (all rotary axes at 0°); the renderer moves
//! them with the table axes.

pub mod pose;

use glam::{DMat3, DQuat, DVec3};
use schwenkbar_core::Text;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::plane::RotaryAxis;
use schwenkbar_core::sim::collision::{Bodies, Placed};
use schwenkbar_core::sim::{Collision, Kin, State};

/// Axis positions as the control shows them in M-CS.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct MachineAxes {
    /// X, Y, Z: where the tool tip is with every head axis at 0° (mm).
    pub linear: DVec3,
    /// A, B, C in degrees; a missing axis stands at 0°.
    pub rotary: AxisValues,
}

impl MachineAxes {
    /// The axes a `fraction` (0…1) of the way from `self` to `to`. Every axis travels its own
    /// programmed difference linearly (what the control does in a positioning block; the
    /// simulator's segments carry the same values).
    #[must_use]
    pub fn lerp(&self, to: &MachineAxes, fraction: f64) -> MachineAxes {
        let f = fraction.clamp(0.0, 1.0);
        let mut rotary = AxisValues::default();
        for axis in [RotaryAxis::A, RotaryAxis::B, RotaryAxis::C] {
            match (self.rotary.get(axis), to.rotary.get(axis)) {
                (None, None) => {}
                (a, b) => {
                    let (a, b) = (a.unwrap_or(0.0), b.unwrap_or(0.0));
                    rotary.set(axis, a + (b - a) * f);
                }
            }
        }
        MachineAxes { linear: self.linear.lerp(to.linear, f), rotary }
    }
}

/// A coordinate system: origin and rotation (columns = its X, Y, Z in the parent's axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub origin: DVec3,
    pub rot: DMat3,
}

impl Default for Frame {
    fn default() -> Self {
        Frame { origin: DVec3::ZERO, rot: DMat3::IDENTITY }
    }
}

/// The tool from the tool table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tool {
    pub length: f64,
    pub radius: f64,
}

impl Default for Tool {
    fn default() -> Self {
        Tool { length: 100.0, radius: 10.0 }
    }
}

/// The blank from `BLK FORM 0.1/0.2` (MIN and MAX point in W-CS).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Blank {
    pub min: DVec3,
    pub max: DVec3,
}

impl Default for Blank {
    /// The default blank of the trainer: 100 × 100 × 40, top face at Z 0 (Musterprogramm 1).
    fn default() -> Self {
        Blank { min: DVec3::new(0.0, 0.0, -40.0), max: DVec3::new(100.0, 100.0, 0.0) }
    }
}

impl Blank {
    /// A W-CS on the table at home that centres this blank on the table's rotation axis (X/Y)
    /// with its top at M-CS Z 0: the default preset when nothing else is known.
    #[must_use]
    pub fn centred_wcs(&self) -> Frame {
        let c = (self.min + self.max) / 2.0;
        Frame { origin: DVec3::new(-c.x, -c.y, -self.max.z), rot: DMat3::IDENTITY }
    }
}

/// Which coordinate triads are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Triads {
    pub mcs: bool,
    pub wcs: bool,
    pub wpl: bool,
    pub tcs: bool,
}

impl Default for Triads {
    fn default() -> Self {
        Triads { mcs: true, wcs: true, wpl: true, tcs: true }
    }
}

impl Triads {
    /// None drawn: the moment of a collision shows the two bodies, not four triads over them
    /// (classroom trial II found that view crowded); the switches bring any back.
    pub const NONE: Triads = Triads { mcs: false, wcs: false, wpl: false, tcs: false };

    /// The switches a moment starts with: all at a normal one, none at a collision.
    #[must_use]
    pub fn at_start(collision: bool) -> Triads {
        if collision { Triads::NONE } else { Triads::default() }
    }

    /// Switch `i` in the order M-CS, W-CS, WPL-CS, T-CS (`false` past the end).
    #[must_use]
    pub fn get(&self, i: usize) -> bool {
        [self.mcs, self.wcs, self.wpl, self.tcs].get(i).copied().unwrap_or(false)
    }

    /// Turns switch `i` over (nothing past the end).
    pub fn flip(&mut self, i: usize) {
        let slot = match i {
            0 => &mut self.mcs,
            1 => &mut self.wcs,
            2 => &mut self.wpl,
            3 => &mut self.tcs,
            _ => return,
        };
        *slot = !*slot;
    }
}

/// One machine state to draw.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneState {
    pub axes: MachineAxes,
    /// The other candidate of a PLANE block (rotary axes only), drawn translucent.
    pub ghost: Option<AxisValues>,
    /// W-CS on the table at home (the preset).
    pub wcs: Frame,
    /// WPL-CS relative to W-CS (origin in W-CS, rotation = the PLANE orientation R).
    pub wpl: Frame,
    pub tool: Tool,
    pub blank: Blank,
    /// How many toolpath segments to draw (`None` = all), for a run in progress.
    pub toolpath_drawn: Option<usize>,
    /// The cut stock (W-CS), drawn in place of the blank's box.
    pub stock: Option<StockShape>,
    /// The two bodies of the collision that stopped the run, placed at `axes` (M-CS), drawn in
    /// the warning colour ([`SceneState::at_collision`]).
    pub contact: Option<[Placed; 2]>,
    /// Every collision body placed at `axes` (M-CS), drawn translucent: the machine editor's
    /// preview ([`SceneState::with_bodies`]).
    pub bodies: Vec<Placed>,
}

/// The stock to draw: the run's stock and where in it (the renderer cuts and meshes towards
/// it frame by frame, [`crate::stock::StockRef::mesh_toward`]).
#[derive(Debug, Clone, PartialEq)]
pub struct StockShape {
    pub stock: crate::stock::StockRef,
    pub step: usize,
    /// Of the step's motion, 0…1.
    pub fraction: f64,
}

impl Default for SceneState {
    fn default() -> Self {
        let blank = Blank::default();
        SceneState {
            axes: MachineAxes { linear: DVec3::new(0.0, 0.0, 150.0), rotary: AxisValues::default() },
            ghost: None,
            wcs: blank.centred_wcs(),
            wpl: Frame::default(),
            tool: Tool::default(),
            blank,
            toolpath_drawn: None,
            stock: None,
            contact: None,
            bodies: Vec::new(),
        }
    }
}

impl SceneState {
    /// The state before a program runs on `machine`: its preset (the simulator's W-CS), the
    /// linear axes at the program start, the default blank and tool, rotary axes at 0°.
    #[must_use]
    pub fn for_machine(machine: &Machine) -> SceneState {
        let g = &machine.geometry;
        SceneState {
            axes: MachineAxes { linear: g.start, rotary: AxisValues::default() },
            wcs: Frame { origin: g.preset, rot: DMat3::IDENTITY },
            ..SceneState::default()
        }
    }

    /// [`SceneState::for_machine`] with the machine's collision bodies, the default tool and
    /// its holder placed there (no blank: it is the program's).
    #[must_use]
    pub fn with_bodies(machine: &Machine) -> SceneState {
        let s = SceneState::for_machine(machine);
        let kin = Kin::new(machine, s.tool.length);
        let axes = schwenkbar_core::sim::MachineAxes {
            linear: s.axes.linear,
            rotary: [0.0; 2],
            letters: std::array::from_fn(|i| machine.joints()[i].axis),
        };
        let placed = Bodies::new(machine, &kin, s.tool.radius, None).map(|b| b.placed(&axes));
        SceneState { bodies: placed.into_iter().flatten().map(|(_, p)| p).collect(), ..s }
    }

    /// The state a `fraction` (0…1) of the way from `from` to `to`, for animating a block: the
    /// axes travel linearly ([`MachineAxes::lerp`]), the W-CS and WPL-CS turn along the shortest
    /// arc (quaternion slerp), so PLANE … STAY shows only the frame turning. Tool, blank, ghost
    /// and the drawn toolpath are `to`'s. For MOVE, whose linear axes follow the rotary ones
    /// along a curve, put the simulator's `axes_at(fraction)` into `axes` afterwards.
    #[must_use]
    pub fn between(from: &SceneState, to: &SceneState, fraction: f64) -> SceneState {
        let f = fraction.clamp(0.0, 1.0);
        let turn = |a: &Frame, b: &Frame| Frame {
            origin: a.origin.lerp(b.origin, f),
            rot: DMat3::from_quat(DQuat::from_mat3(&a.rot).slerp(DQuat::from_mat3(&b.rot), f)),
        };
        SceneState {
            axes: from.axes.lerp(&to.axes, f),
            wcs: turn(&from.wcs, &to.wcs),
            wpl: turn(&from.wpl, &to.wpl),
            ..to.clone()
        }
    }
}

impl SceneState {
    /// The moment the run stopped on `c`, on the state `before` (the last step the control
    /// finished; its tool and blank are the colliding block's): every axis where the bodies
    /// touched, not the block's end; the pair placed there by the simulator's own bodies
    /// ([`Bodies::placed`]); and the collision-free other solution, if any, as the ghost (the
    /// ghost of an earlier PLANE block would mislead, so none without one).
    pub fn at_collision(&mut self, machine: &Machine, before: &State, c: &Collision) {
        self.axes = MachineAxes { linear: c.axes.linear, rotary: c.axes.rotary_values() };
        self.ghost = c.alternative.as_ref().map(|a| a.axes);
        let kin = Kin::new(machine, before.tool.length);
        let bodies = Bodies::new(machine, &kin, before.tool.radius, before.blank.as_ref());
        self.contact = bodies.and_then(|b| {
            let placed = b.placed(&c.axes);
            let find = |name: &Text| placed.iter().find(|(n, _)| n == name).map(|(_, p)| *p);
            Some([find(&c.a)?, find(&c.b)?])
        });
    }
}

/// Everything the renderer paints besides the camera.
#[derive(Debug, Clone, Copy)]
pub struct Scene<'a> {
    pub machine: &'a Machine,
    pub state: &'a SceneState,
    pub triads: Triads,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lerp_moves_every_axis_linearly_and_clamps() {
        let a = MachineAxes { linear: DVec3::ZERO, rotary: AxisValues::default().with(RotaryAxis::A, 0.0) };
        let b = MachineAxes {
            linear: DVec3::new(10.0, 0.0, -20.0),
            rotary: AxisValues::default().with(RotaryAxis::A, 45.0).with(RotaryAxis::C, 90.0),
        };
        let m = a.lerp(&b, 0.5);
        assert_eq!(m.linear, DVec3::new(5.0, 0.0, -10.0));
        assert_eq!(m.rotary.a, Some(22.5));
        assert_eq!(m.rotary.c, Some(45.0), "a missing start axis stands at 0°");
        assert_eq!(m.rotary.b, None);
        assert_eq!(a.lerp(&b, 7.0), MachineAxes { linear: b.linear, rotary: b.rotary });
    }

    #[test]
    fn between_turns_only_the_frame_for_stay_and_ends_at_the_target() {
        use schwenkbar_core::orientation::spatial;
        let from = SceneState::default();
        let to = SceneState {
            wpl: Frame { origin: DVec3::ZERO, rot: spatial(0.0, 15.0, 0.0) },
            ..SceneState::default()
        };
        let half = SceneState::between(&from, &to, 0.5);
        assert_eq!(half.axes, from.axes, "STAY: the axes stand still");
        let z = half.wpl.rot.col(2);
        let expected = spatial(0.0, 7.5, 0.0).col(2);
        assert!((z - expected).length() < 1e-9, "halfway: SPB 7.5° ({z})");
        let end = SceneState::between(&from, &to, 1.0);
        assert!((end.wpl.rot.col(2) - to.wpl.rot.col(2)).length() < 1e-9);
    }

    #[test]
    fn triad_switches_flip_one_at_a_time() {
        let mut t = Triads::default();
        t.flip(2);
        assert_eq!(t, Triads { wpl: false, ..Triads::default() });
        assert!(!t.get(2) && t.get(0) && t.get(3) && !t.get(4));
        t.flip(9);
        assert!(!t.get(2));
    }

    #[test]
    fn a_machines_own_state_uses_its_preset_and_start() {
        let m = Machine::builtin("ac-table").expect("machine");
        let s = SceneState::for_machine(&m);
        assert_eq!(s.wcs.origin, m.geometry.preset);
        assert_eq!(s.axes.linear, m.geometry.start);
    }

    #[test]
    fn the_editors_preview_places_every_body_tool_and_holder_at_the_start() {
        let m = Machine::builtin("ac-table").expect("ac-table");
        let s = SceneState::with_bodies(&m);
        assert_eq!(s.axes, SceneState::for_machine(&m).axes);
        assert_eq!(s.bodies.len(), m.bodies.len() + 2, "the machine's bodies, the tool and its holder");
        // The rotary table (a cylinder on C, all axes at home) stays where the file puts it.
        let Some(Placed::Cylinder { capsule, .. }) = s.bodies.get(3) else { panic!("{:?}", s.bodies) };
        assert_eq!((capsule.a, capsule.radius), (DVec3::new(0.0, 0.0, -240.0), 50.0));
        assert!(SceneState::default().bodies.is_empty(), "the trainer draws none");
    }

    #[test]
    fn centred_wcs_puts_the_blank_top_at_z0_over_the_axis() {
        let blank = Blank::default();
        let w = blank.centred_wcs();
        let centre_top = w.origin + DVec3::new(50.0, 50.0, 0.0);
        assert_eq!(centre_top, DVec3::ZERO);
    }
}
