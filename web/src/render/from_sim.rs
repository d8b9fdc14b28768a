//! The simulator's output as the view's input: a [`SceneState`] per block, the state at any
//! fraction of a block's motion, and the run's toolpath. The geometry comes from
//! `core::sim` ([`Kin`]); this only changes frames of reference.

use glam::{DMat3, DQuat};
use schwenkbar_core::machine::Machine;
use schwenkbar_core::sim::{Kin, Segment, SegmentKind, SegmentPath, State};

use super::toolpath::PathPoint;
use schwenkbar_app::scene::{Blank, Frame, MachineAxes, SceneState, Tool};

fn axes(a: &schwenkbar_core::sim::MachineAxes) -> MachineAxes {
    MachineAxes { linear: a.linear, rotary: a.rotary_values() }
}

/// The view's state after a simulated block. The simulator gives the frames in M-CS as the
/// machine stands; the view keeps the W-CS on the table at home (so it turns with the table axes
/// during an animation) and the WPL-CS relative to the W-CS.
#[must_use]
pub fn scene_state(machine: &Machine, s: &State) -> SceneState {
    let kin = Kin::new(machine, s.tool.length);
    let home = kin.workpiece_pose(s.axes.rotary).inverse_orthogonal();
    let (wcs, wpl) = (&s.frames.wcs, &s.frames.wpl);
    let to_wcs = wcs.axes.transpose();
    let ghost = s.explanation.as_ref().and_then(|e| {
        let chosen = e.chosen?;
        e.candidates.iter().enumerate().find(|(i, _)| *i != chosen).map(|(_, c)| c.axes)
    });
    SceneState {
        axes: axes(&s.axes),
        ghost,
        wcs: Frame { origin: home.apply(wcs.origin), rot: home.m * wcs.axes },
        wpl: Frame { origin: to_wcs * (wpl.origin - wcs.origin), rot: to_wcs * wpl.axes },
        tool: Tool { length: s.tool.length, radius: s.tool.radius },
        blank: s.blank.map_or_else(Blank::default, |b| Blank { min: b.min, max: b.max }),
        toolpath_drawn: None,
        stock: None,
        contact: None,
        bodies: Vec::new(),
    }
}

/// The view's state at `fraction` (0…1) of one of `after`'s segments: the axes from the
/// simulator's `Segment::axes_at` (MOVE keeps its centre of rotation, TURN moves only the
/// rotary axes), and for STAY the working plane turning from its old to its new orientation
/// (quaternion slerp, the shortest turn) while nothing moves.
#[must_use]
pub fn scene_during(machine: &Machine, after: &State, segment: &Segment, fraction: f64) -> SceneState {
    let mut st = scene_state(machine, after);
    st.axes = axes(&segment.axes_at(fraction));
    if let SegmentPath::Stay { from, to } = &segment.path {
        let f = fraction.clamp(0.0, 1.0);
        st.wpl.rot = DMat3::from_quat(DQuat::from_mat3(from).slerp(DQuat::from_mat3(to), f));
    }
    st
}

/// The tool tip's path of a run in W-CS, with how far it reaches after each step.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RunPath {
    pub points: Vec<PathPoint>,
    /// `segments_after[step]` = segments of `points` travelled when `step` is done (for
    /// [`SceneState::toolpath_drawn`]).
    pub segments_after: Vec<usize>,
}

/// Samples per swivel or MOVE segment: the tip travels an arc relative to the workpiece there.
const ARC_SAMPLES: u32 = 12;

/// Largest turn (radians) of one straight piece of a programmed arc (C, CR, CT, CP, RND). The
/// path is built once per run, not per frame, so it is tessellated by angle, which keeps the
/// error a fixed share of the radius at every zoom: the sagitta of a piece is r·(1 − cos(θ/2)),
/// below half a pixel for θ = 3.6° as long as the arc's radius on screen is under 1000 px
/// (1 − cos 1.8° = 4.9·10⁻⁴), i.e. 100 pieces per full circle.
const ARC_STEP: f64 = 3.6 * std::f64::consts::PI / 180.0;

/// Most pieces of one arc (a helix of many turns): keeps one block's line buffer bounded.
const MAX_ARC_PIECES: f64 = 4096.0;

/// How many straight pieces draw a segment of the run.
fn pieces(seg: &Segment) -> u32 {
    match &seg.path {
        // At least one piece; the cast is exact, the count is clamped to MAX_ARC_PIECES.
        SegmentPath::Arc(arc) => (arc.sweep.abs() / ARC_STEP).ceil().clamp(1.0, MAX_ARC_PIECES) as u32,
        SegmentPath::Linear if seg.rotary_delta == [0.0; 2] => 1,
        _ => ARC_SAMPLES,
    }
}

/// Adds `states`, the run's next steps from where `path` stands, to `path` (a long run is drawn
/// in parts, between frames); how many there were.
pub fn extend_path(machine: &Machine, path: &mut RunPath, states: impl Iterator<Item = State>) -> usize {
    let mut count = 0;
    for st in states {
        let kin = Kin::new(machine, st.tool.length);
        for seg in &st.segments {
            if path.points.is_empty() {
                path.points.push(PathPoint { at: kin.tip_wcs(&seg.start), rapid: true });
            }
            let rapid = !matches!(seg.kind, SegmentKind::Feed | SegmentKind::CycleFeed);
            let samples = pieces(seg);
            for k in 1..=samples {
                let at = kin.tip_wcs(&seg.axes_at(f64::from(k) / f64::from(samples)));
                path.points.push(PathPoint { at, rapid });
            }
        }
        path.segments_after.push(path.points.len().saturating_sub(1));
        count += 1;
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DAffine3, DVec3};
    use schwenkbar_app::document::Document;
    use schwenkbar_app::run::SimRef;
    use schwenkbar_app::scene::pose::poses;
    use schwenkbar_core::ast::Program;
    use schwenkbar_core::plane::RotaryAxis;
    use schwenkbar_core::sim::Simulation;

    /// The toolpath of a whole run (re-simulates once through [`Simulation::states`]).
    fn toolpath(sim: &Simulation, program: &Program) -> RunPath {
        let mut path = RunPath::default();
        extend_path(&sim.machine, &mut path, sim.states(program));
        path
    }

    fn musterprogramm1() -> (Program, Machine, Simulation) {
        let doc = Document::new(include_str!("../../../static/programs/musterprogramm1.h").to_owned());
        let machine = Machine::builtin("ac-table").expect("machine");
        let sim = SimRef::of(&doc.program, &machine).0.as_ref().clone();
        assert!(sim.error.is_none(), "{:?}", sim.error);
        (doc.program.clone(), machine, sim)
    }

    fn step_of_block(sim: &Simulation, program: &Program, number: u32) -> usize {
        let block = program.blocks.iter().position(|b| b.number() == Some(number)).expect("block");
        sim.step_of_block(block).expect("executed")
    }

    /// The scene pane makes the path in parts from one iterator: the parts add up to the whole,
    /// every step once, and the last part says it was short.
    #[test]
    fn the_path_made_in_parts_is_the_whole_path() {
        let (program, machine, sim) = musterprogramm1();
        let whole = toolpath(&sim, &program);
        assert_eq!(whole.segments_after.len(), sim.len());
        let mut parts = RunPath::default();
        let mut states = sim.states(&program);
        let mut counts = Vec::new();
        loop {
            let n = extend_path(&machine, &mut parts, states.by_ref().take(5));
            counts.push(n);
            if n < 5 {
                break;
            }
        }
        assert_eq!(parts, whole);
        assert_eq!(counts.iter().sum::<usize>(), sim.len(), "{counts:?}");
    }

    #[test]
    fn after_block_10_the_tilted_plane_lies_flat_under_the_tool_and_the_ghost_is_the_other_solution() {
        // Musterprogramm 1, block 10: PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN on the A/C table.
        let (program, machine, sim) = musterprogramm1();
        let st = sim.state_at(&program, step_of_block(&sim, &program, 10)).expect("state");
        let scene = scene_state(&machine, &st);
        let near = |v: Option<f64>, want: f64| v.is_some_and(|x| (x - want).abs() < 1e-9);
        assert!(
            near(scene.axes.rotary.a, 15.0) && near(scene.axes.rotary.c, 90.0),
            "{:?}",
            scene.axes.rotary
        );
        let g = scene.ghost.expect("the other candidate");
        assert!(near(g.a, -15.0) && near(g.c, -90.0), "{g:?}");
        // The view's WPL-CS, carried by the table, must be the simulator's WPL-CS in M-CS.
        let p = poses(&machine, &scene.axes.rotary, scene.axes.linear, scene.tool.length);
        let wcs = p.workpiece * DAffine3::from_mat3_translation(scene.wcs.rot, scene.wcs.origin);
        let wpl_z = wcs.matrix3 * scene.wpl.rot.col(2);
        assert!((wpl_z - st.frames.wpl.axes.col(2)).length() < 1e-9);
        assert!((wpl_z - DVec3::Z).length() < 1e-9, "tilted tool axis vertical: {wpl_z}");
        assert!((wcs.transform_point3(scene.wpl.origin) - st.frames.wpl.origin).length() < 1e-9);
        // The tool tip drawn is the simulator's.
        assert!((p.tool.translation - st.tip_mcs).length() < 1e-9);
    }

    #[test]
    fn the_face_milling_of_block_12_runs_in_the_plane_tilted_by_spb15() {
        let (program, machine, sim) = musterprogramm1();
        let path = toolpath(&sim, &program);
        assert_eq!(path.segments_after.len(), sim.len());
        let (from, to) = {
            let s12 = step_of_block(&sim, &program, 12);
            // Cycle 232 moves at its call (M99 in block 13).
            let s13 = step_of_block(&sim, &program, 13);
            (path.segments_after[s12.min(s13 - 1)], path.segments_after[s13])
        };
        let st = sim.state_at(&program, step_of_block(&sim, &program, 13)).expect("state");
        let scene = scene_state(&machine, &st);
        let n = scene.wpl.rot.col(2);
        let depth = |p: DVec3| (p - scene.wpl.origin).dot(n);
        // The milling strokes: feed moves across the face at one depth along the tilted tool axis.
        let strokes: Vec<(f64, f64)> = path.points[from..=to]
            .windows(2)
            .filter(|w| !w[1].rapid && (w[1].at - w[0].at).length() > 50.0)
            .map(|w| (depth(w[0].at), depth(w[1].at)))
            .collect();
        assert!(strokes.len() >= 2, "the cycle mills: {strokes:?}");
        for (a, b) in strokes {
            assert!((a - b).abs() < 1e-6, "a stroke parallel to the tilted plane: {a} → {b}");
            // Q386 = 0 (end depth) and Q227 = +2 (start): every stroke between them.
            assert!((-1e-6..=2.0 + 1e-6).contains(&a), "stroke depth {a}");
        }
        assert!(n.x > 0.25, "SPB+15 tilts the plane normal towards +X: {n}");
    }

    #[test]
    fn a_full_circle_is_drawn_as_an_arc_of_100_pieces_on_its_radius() {
        let doc = Document::new(
            "0 BEGIN PGM K MM\n1 TOOL CALL 16 Z S1000 F500\n2 L X+30 Y+10 Z+5 R0 FMAX\n3 CC X+10 Y+10\n\
             4 C X+30 Y+10 DR- F500\n5 END PGM K MM\n"
                .to_owned(),
        );
        let machine = Machine::builtin("ac-table").expect("machine");
        let sim = SimRef::of(&doc.program, &machine).0.as_ref().clone();
        assert!(sim.error.is_none(), "{:?}", sim.error);
        let path = toolpath(&sim, &doc.program);
        let step = step_of_block(&sim, &doc.program, 4);
        let arc = &path.points[path.segments_after[step - 1]..=path.segments_after[step]];
        assert_eq!(arc.len(), 101, "360° in 3.6° pieces");
        for (k, p) in arc.iter().enumerate() {
            let r = (p.at - DVec3::new(10.0, 10.0, 5.0)).length();
            // `rapid` tells how the point was reached: the first one by the positioning before.
            assert!((r - 20.0).abs() < 1e-9 && (k == 0 || !p.rapid), "on the circle: {p:?}");
        }
        assert!((arc[100].at - arc[0].at).length() < 1e-9, "closed");
        // DR−: clockwise seen from +Z, so the first piece heads −Y from (30, 10).
        assert!(arc[1].at.y < arc[0].at.y);
    }

    #[test]
    fn a_turn_swivel_is_drawn_moving_and_ends_at_the_block_state() {
        let (program, machine, sim) = musterprogramm1();
        let st = sim.state_at(&program, step_of_block(&sim, &program, 10)).expect("state");
        let seg = st.segments.iter().find(|s| s.kind == SegmentKind::SwivelTurn).expect("TURN segment");
        let half = scene_during(&machine, &st, seg, 0.5);
        let a = half.axes.rotary.get(RotaryAxis::A).expect("A");
        assert!(a > 0.0 && a < 15.0, "halfway through the swivel: A{a}");
        assert_eq!(scene_during(&machine, &st, seg, 1.0).axes, scene_state(&machine, &st).axes);
    }
}
