//! The toolpath of a run as one static line set (built and uploaded when the run changes, never
//! per frame). Points are the tool tip in W-CS coordinates on the table at home, so the path
//! turns with the workpiece.

use glam::DVec3;

use super::mesh::Lines;

/// One point of the tool tip's path; `rapid` tells how the segment *to* it was travelled.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathPoint {
    pub at: DVec3,
    pub rapid: bool,
}

/// Rapid traverse (FMAX): dashed-looking warm yellow; feed moves: bright green (the usual
/// simulation colours, readable on the dark background).
pub const RAPID: [f32; 3] = [1.0, 0.80, 0.25];
pub const FEED: [f32; 3] = [0.35, 1.0, 0.55];

/// The segments of a polyline with a colour per kind.
#[must_use]
pub fn lines(points: &[PathPoint]) -> Lines {
    let mut l = Lines { vertices: Vec::with_capacity(points.len().saturating_sub(1) * 12) };
    for w in points.windows(2) {
        let colour = if w[1].rapid { RAPID } else { FEED };
        l.segment(w[0].at.as_vec3(), w[1].at.as_vec3(), colour);
    }
    l
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_polyline_of_n_points_gives_n_minus_one_coloured_segments() {
        let p = |x: f64, rapid| PathPoint { at: DVec3::new(x, 0.0, 0.0), rapid };
        let l = lines(&[p(0.0, true), p(10.0, true), p(20.0, false)]);
        assert_eq!(l.vertex_count(), 4);
        assert_eq!(&l.vertices[3..6], &RAPID);
        assert_eq!(&l.vertices[15..18], &FEED);
        assert_eq!(l.vertices[12], 10.0, "the second segment starts where the first ended");
        assert!(lines(&[p(0.0, false)]).vertices.is_empty());
    }
}
