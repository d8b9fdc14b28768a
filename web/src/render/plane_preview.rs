//! A scene for "this PLANE block on this machine, from these axes": the solver's choice as the
//! machine state, the other candidate as the ghost, the orientation as WPL-CS. The simulator will
//! provide full per-block states; until then this drives the preview page (`#3d…`) and shows the
//! lead how an `Explanation` maps onto [`SceneState`].

use glam::DMat3;
use schwenkbar_core::axes::AxisValues;
use schwenkbar_core::machine::Machine;
use schwenkbar_core::orientation::spatial;
use schwenkbar_core::solve::{Explanation, SolveOptions, solve};

use super::scene::SceneState;

/// The state after positioning for `r` from `start`: chosen axes, the other candidate as ghost.
/// With no solution (error) the axes stay at `start` and there is no ghost.
#[must_use]
pub fn state_for(machine: &Machine, r: DMat3, start: AxisValues) -> (SceneState, Explanation) {
    let e = solve(machine, &r, &SolveOptions { start, ..SolveOptions::default() });
    let mut s = SceneState::default();
    s.wpl.rot = r;
    s.axes.rotary = e.chosen_axes().unwrap_or(start);
    s.ghost = match e.chosen {
        Some(i) => e.candidates.iter().enumerate().find(|(j, _)| *j != i).map(|(_, c)| c.axes),
        None => None,
    };
    (s, e)
}

/// Preview parameters from a URL fragment such as `machine=b45-nutating;spa=0;spb=45;spc=0`
/// (unknown keys and bad numbers are ignored; defaults: `ac-table`, all angles 0).
#[derive(Debug, Clone, PartialEq)]
pub struct PreviewQuery {
    pub machine: String,
    pub spatial: [f64; 3],
    pub ghost: bool,
}

impl PreviewQuery {
    #[must_use]
    pub fn parse(s: &str) -> PreviewQuery {
        let mut q = PreviewQuery { machine: "ac-table".into(), spatial: [0.0; 3], ghost: true };
        for part in s.split([';', '&', '?', ':']) {
            let Some((k, v)) = part.split_once('=') else { continue };
            let num = v.parse::<f64>().ok().filter(|x| x.is_finite());
            match (k.trim().to_ascii_lowercase().as_str(), num) {
                ("machine", _) => q.machine = v.trim().to_string(),
                ("spa", Some(x)) => q.spatial[0] = x,
                ("spb", Some(x)) => q.spatial[1] = x,
                ("spc", Some(x)) => q.spatial[2] = x,
                ("ghost", Some(x)) => q.ghost = x != 0.0,
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
    fn the_query_reads_machine_and_angles_and_ignores_nonsense() {
        let q = PreviewQuery::parse(":machine=b45-nutating;spb=-30;spa=x;ghost=0;foo=1");
        assert_eq!(q.machine, "b45-nutating");
        assert_eq!(q.spatial, [0.0, -30.0, 0.0]);
        assert!(!q.ghost);
        assert_eq!(PreviewQuery::parse("").machine, "ac-table");
    }
}
