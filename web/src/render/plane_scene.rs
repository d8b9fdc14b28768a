//! A scene for "this PLANE block on this machine, from these axes": the solver's choice as the
//! machine state, the other candidate as the ghost, the orientation as WPL-CS. The simulator will
//! provide full per-block states; until then this drives the 3D page (`#3d…`,
//! `components/page3d.rs`) and shows how an `Explanation` maps onto [`SceneState`].

use glam::DMat3;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::number::parse_f64;
use schwenkbar_core::orientation::spatial;
use schwenkbar_core::solve::{Explanation, SolveOptions, solve};

use glam::{DAffine3, DVec3};

use super::pose::poses;
use super::scene::{Blank, Frame, SceneState};
use super::toolpath::PathPoint;

/// The state after positioning for `r` from `start`: chosen axes, the other candidate as ghost.
/// With no solution (error) the axes stay at `start` and there is no ghost.
#[must_use]
pub fn state_for(machine: &Machine, r: DMat3, start: AxisValues) -> (SceneState, Explanation) {
    let e = solve(machine, &r, &SolveOptions { start, ..SolveOptions::default() });
    let mut s = SceneState::for_machine(machine);
    s.wpl.rot = r;
    s.axes.rotary = e.chosen_axes().unwrap_or(start);
    s.ghost = match e.chosen {
        Some(i) => e.candidates.iter().enumerate().find(|(j, _)| *j != i).map(|(_, c)| c.axes),
        None => None,
    };
    // Like `L Z+50` in the tilted plane after positioning: tool tip 50 mm above the WPL-CS origin.
    let tip = workpiece_point(machine, &s, s.wpl.origin + r.col(2) * 50.0);
    s.axes.linear = linear_for_tip(machine, &s.axes.rotary, s.tool.length, tip);
    (s, e)
}

/// A W-CS point in M-CS for the state's rotary axes.
#[must_use]
pub fn workpiece_point(machine: &Machine, s: &SceneState, p_w: DVec3) -> DVec3 {
    let p = poses(machine, &s.axes.rotary, DVec3::ZERO, s.tool.length);
    (p.workpiece * DAffine3::from_mat3_translation(s.wcs.rot, s.wcs.origin)).transform_point3(p_w)
}

/// The linear axes that put the tool tip at `tip` (M-CS) with these rotary axes: the carriage
/// only translates, so it is the tip's position minus where the tip is with X/Y/Z at 0.
#[must_use]
pub fn linear_for_tip(machine: &Machine, rotary: &AxisValues, tool_length: f64, tip: DVec3) -> DVec3 {
    tip - poses(machine, rotary, DVec3::ZERO, tool_length).tool.translation
}

/// A face-milling path over the blank's top in the working plane (WPL-CS lines 15 mm apart,
/// approached and left by rapid moves), as W-CS points: shows that the path lies in the tilted
/// plane and turns with the workpiece.
#[must_use]
pub fn demo_path(blank: &Blank, wpl: &Frame) -> Vec<PathPoint> {
    let to_w = |x: f64, y: f64, z: f64| wpl.origin + wpl.rot * DVec3::new(x, y, z);
    let (x0, x1) = (blank.min.x - 15.0, blank.max.x + 15.0);
    let mut pts = vec![PathPoint { at: to_w(x0, blank.min.y, 50.0), rapid: true }];
    pts.push(PathPoint { at: to_w(x0, blank.min.y, 0.0), rapid: true });
    let mut y = blank.min.y;
    let mut forward = true;
    while y <= blank.max.y + 1e-9 {
        let (a, b) = if forward { (x0, x1) } else { (x1, x0) };
        pts.push(PathPoint { at: to_w(a, y, 0.0), rapid: false });
        pts.push(PathPoint { at: to_w(b, y, 0.0), rapid: false });
        forward = !forward;
        y += 15.0;
    }
    let last = pts[pts.len() - 1].at;
    pts.push(PathPoint { at: last + wpl.rot.col(2) * 50.0, rapid: true });
    pts
}

/// Page parameters from a URL fragment such as `machine=b45-nutating;spa=0;spb=45;spc=0`
/// (unknown keys and bad numbers are ignored; defaults: `ac-table`, all angles 0).
#[derive(Debug, Clone, PartialEq)]
pub struct PageQuery {
    /// `None` = `ac-table`.
    pub machine: Option<String>,
    pub spatial: [f64; 3],
    pub ghost: bool,
    /// Draw the demo face-milling path.
    pub path: bool,
}

impl PageQuery {
    #[must_use]
    pub fn parse(s: &str) -> PageQuery {
        let mut q = PageQuery { machine: None, spatial: [0.0; 3], ghost: true, path: true };
        for part in s.split([';', '&', '?', ':']) {
            let Some((k, v)) = part.split_once('=') else { continue };
            let num = parse_f64(v).filter(|x| x.is_finite());
            match (k.trim().to_ascii_lowercase().as_str(), num) {
                ("machine", _) => q.machine = Some(v.trim().to_string()),
                ("spa", Some(x)) => q.spatial[0] = x,
                ("spb", Some(x)) => q.spatial[1] = x,
                ("spc", Some(x)) => q.spatial[2] = x,
                ("ghost", Some(x)) => q.ghost = x != 0.0,
                ("path", Some(x)) => q.path = x != 0.0,
                _ => {}
            }
        }
        q
    }

    /// The orientation of `PLANE SPATIAL` with these angles.
    #[must_use]
    pub fn orientation(&self) -> DMat3 {
        let [a, b, c] = self.spatial;
        spatial(a, b, c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use schwenkbar_core::plane::RotaryAxis;

    #[test]
    fn spb45_on_the_ac_table_gives_a45_c90_and_the_ghost_a_minus45_c_minus90() {
        // DOMAIN.md §10 oracle 13: both candidates, the + one chosen from A0 C0.
        let m = Machine::builtin("ac-table").expect("machine");
        let (s, e) = state_for(&m, spatial(0.0, 45.0, 0.0), AxisValues::default());
        assert!(e.error.is_none());
        assert_eq!(s.axes.rotary.get(RotaryAxis::A), Some(45.0));
        assert_eq!(s.axes.rotary.get(RotaryAxis::C), Some(90.0));
        let g = s.ghost.expect("the other candidate");
        assert_eq!((g.a, g.c), (Some(-45.0), Some(-90.0)));
    }

    #[test]
    fn the_tool_tip_stands_above_the_tilted_plane_on_every_machine() {
        for id in Machine::builtin_ids() {
            let m = Machine::builtin(id).expect("machine");
            let r = spatial(0.0, 30.0, 0.0);
            let (s, _) = state_for(&m, r, AxisValues::default());
            let p = poses(&m, &s.axes.rotary, s.axes.linear, s.tool.length);
            let tip = p.tool.translation;
            let want = workpiece_point(&m, &s, r.col(2) * 50.0);
            assert!((tip - want).length() < 1e-9, "{id}: tip {tip} vs {want}");
        }
    }

    #[test]
    fn the_demo_path_cuts_in_the_working_plane() {
        let wpl = Frame { origin: DVec3::new(0.0, 0.0, 0.0), rot: spatial(0.0, 15.0, 0.0) };
        let path = demo_path(&Blank::default(), &wpl);
        let feed: Vec<_> = path.iter().filter(|p| !p.rapid).collect();
        assert!(feed.len() >= 14);
        for p in feed {
            assert!((p.at - wpl.origin).dot(wpl.rot.col(2)).abs() < 1e-9, "{:?} off the plane", p.at);
        }
        assert!(path.first().is_some_and(|p| p.rapid) && path.last().is_some_and(|p| p.rapid));
    }

    #[test]
    fn the_query_reads_machine_and_angles_and_ignores_nonsense() {
        let q = PageQuery::parse(":machine=b45-nutating;spb=-30;spa=x;ghost=0;foo=1");
        assert_eq!(q.machine.as_deref(), Some("b45-nutating"));
        assert_eq!(q.spatial, [0.0, -30.0, 0.0]);
        assert!(!q.ghost);
        assert_eq!(PageQuery::parse("").machine, None);
    }
}
