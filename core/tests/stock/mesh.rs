//! The mesh the view and the STL get: the STL closed, a tilted face lit with its normal and drawn
//! as one layer on its plane (issue 32 items 2 and 5).

use super::*;

/// Issue 32: the exported STL is a closed mesh. Read back from its bytes, every edge (its two
/// corners' positions) belongs to exactly two triangles, once in each direction (the triangles
/// face consistently outwards); and the volume the mesh encloses (divergence theorem:
/// Σ p0 · (p1 × p2) / 6, a second method) is the stock's within 1 %.
#[test]
fn the_exported_stl_is_closed_every_edge_in_exactly_two_triangles() {
    use std::collections::HashMap;
    let swivel = format!(
        "{BLANK}TOOL CALL 1 Z S1000\nL X+50 Y+50 Z+10 R0 FMAX\nL Z-5 F100\n\
         PLANE SPATIAL SPA+30 SPB+0 SPC+0 TURN FMAX\nM30\n"
    );
    for (what, src) in [("Musterprogramm 1", musterprogramm()), ("swivel in the material", swivel)] {
        let (_, _, c) = run(&src, StockOptions { resolution: 0.5, checkpoints: 0 });
        let stock = c.final_stock().expect("stock");
        let stl = StockMesh::closed(&stock).to_stl();
        let n = u32::from_le_bytes(stl[80..84].try_into().expect("count")) as usize;
        assert_eq!(stl.len(), 84 + 50 * n, "{what}");
        let corner = |t: &[u8], k: usize| -> [u32; 3] {
            std::array::from_fn(|i| {
                u32::from_le_bytes(t[12 + 12 * k + 4 * i..][..4].try_into().expect("f32"))
            })
        };
        let mut edges: HashMap<([u32; 3], [u32; 3]), usize> = HashMap::new();
        let mut volume = 0.0;
        for t in stl[84..].chunks_exact(50) {
            let p = [corner(t, 0), corner(t, 1), corner(t, 2)];
            for k in 0..3 {
                *edges.entry((p[k], p[(k + 1) % 3])).or_default() += 1;
            }
            let v = p.map(|c| DVec3::from_array(c.map(|b| f64::from(f32::from_bits(b)))));
            volume += v[0].dot(v[1].cross(v[2])) / 6.0;
        }
        assert!(n > 12, "{what}: {n} triangles");
        for (&(a, b), &count) in &edges {
            assert_eq!((count, edges.get(&(b, a))), (1, Some(&1)), "{what}: edge {a:?}–{b:?}");
        }
        let exact = stock.volume();
        assert!(
            (volume - exact).abs() <= 0.01 * exact,
            "{what}: {volume:.0} mm³ enclosed, stock {exact:.0} mm³"
        );
    }
}

/// Issue 32's machined look: the face milled at SPB+15 is the plane x·sin15 + z·cos15 = −2
/// (the face mill's path, worked by hand as in `face_mill_pass_over_the_tilted_plane_is_a_prism`).
/// Every grid samples it with stepped ends; lit with their axes' normals they showed terraces
/// and moiré. Each end on the face away from its edges now carries the plane's normal
/// (sin15, 0, cos15), within 3°.
#[test]
fn the_ends_on_a_tilted_face_carry_the_faces_normal() {
    let mesh = face_mill_15_mesh();
    let plane = tilt();
    let (mut on_face, mut along) = (0, 0);
    for (tri, normals) in mesh.positions.chunks_exact(3).zip(mesh.normals.chunks_exact(3)) {
        let centre = tri.iter().fold(DVec3::ZERO, |s, p| s + DVec3::from_array(p.map(f64::from))) / 3.0;
        let on_plane = (centre.dot(plane) + 2.0).abs() < 0.3;
        if !on_plane || (centre.y - 50.0).abs() > 20.0 || !(5.0..95.0).contains(&centre.x) {
            continue;
        }
        on_face += 1;
        let n = DVec3::from_array(normals[0].map(f64::from));
        if n.angle_between(plane).to_degrees() < 3.0 {
            along += 1;
        }
    }
    assert!(on_face > 100, "{on_face} triangles on the face");
    assert!(along * 100 >= on_face * 95, "{along} of {on_face} along the face's normal");
}

/// Issue 32's machined look, the face closed: the SPB+15 face (as above) is drawn by the Z grid
/// alone, one layer of squares laid on the plane. The X grid's ends on it (its rays meet the face
/// at 15°) crossed those squares and showed as a dotted moiré; and flat squares at stepped
/// heights left slits between them. Away from its edges no square of another grid lies on the
/// face, every corner lies on the plane (within 0.005 mm; a flat square's corners stray by up
/// to half a cell times tan 15° = 0.033 mm), and each point of the face is under exactly one
/// square.
#[test]
fn a_tilted_face_is_one_layer_of_squares_on_its_plane() {
    let mesh = face_mill_15_mesh();
    let plane = tilt();
    let inside = |p: DVec3| (p.y - 50.0).abs() < 15.0 && (20.0..80.0).contains(&p.x);
    // A quad is two triangles, six positions (`push_quad`); a Z grid's quad spans cells in x, y.
    let mut squares = Vec::new();
    let mut others = 0;
    for (quad, flags) in mesh.positions.chunks_exact(6).zip(mesh.flags.chunks_exact(6)) {
        let p: Vec<DVec3> = quad.iter().map(|v| DVec3::from_array(v.map(f64::from))).collect();
        let (lo, hi) =
            p.iter().fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(l, h), v| (l.min(*v), h.max(*v)));
        let centre = 0.5 * (lo + hi);
        if (centre.dot(plane) + 2.0).abs() > 0.3 {
            continue;
        }
        // The low two bits: the grid (the face's axis, `mesh::flag::AXIS`).
        if flags[0] & 0b11 != 2 {
            others += usize::from(inside(centre));
            continue;
        }
        for v in &p {
            if inside(*v) {
                assert!(
                    (v.dot(plane) + 2.0).abs() < 0.005,
                    "corner {v} off the plane by {}",
                    v.dot(plane) + 2.0
                );
            }
        }
        squares.push((lo, hi));
    }
    assert_eq!(others, 0, "squares of the X or Y grid on the face");
    // Points off the cells' boundaries (multiples of 0.25 mm), 0.61 mm apart.
    for k in 0..90 {
        for l in 0..45 {
            let (x, y) = (20.113 + 0.61 * f64::from(k), 36.07 + 0.61 * f64::from(l));
            let over = squares
                .iter()
                .filter(|(lo, hi)| (lo.x..hi.x).contains(&x) && (lo.y..hi.y).contains(&y))
                .count();
            assert_eq!(over, 1, "squares over x {x} y {y}");
        }
    }
}

/// The view's mesh of the blank after [`face_mill_15`]: its face is the plane
/// x·sin15 + z·cos15 = −2.
fn face_mill_15_mesh() -> StockMesh {
    let (_, _, c) = run(&face_mill_15(), StockOptions::default());
    StockMesh::of(&c.final_stock().expect("stock"))
}
