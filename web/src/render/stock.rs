//! The cut stock as the lit shader takes it: the core's [`StockMesh`] (triangles in W-CS, a flag
//! byte per vertex) turned into interleaved position + normal, the raw blank's faces first and
//! the cut faces after them, so each is one draw call in its own colour.

use schwenkbar_core::stock::StockMesh;

/// Cut faces: a light steel blue, far from the blank's amber in hue and brightness, so the
/// milled face reads on a projector.
pub const CUT: [f32; 3] = [0.55, 0.80, 0.95];

/// Bit of [`StockMesh::flags`] marking a cut face (`core::stock::mesh::flag::CUT`).
const CUT_BIT: u8 = 0b1000;

/// The stock's vertices (x, y, z, nx, ny, nz) and how many of them, from the start, are the
/// raw blank's.
#[must_use]
pub fn vertices(mesh: &StockMesh) -> (Vec<f32>, usize) {
    let cut = mesh.flags.iter().filter(|f| **f & CUT_BIT != 0).count();
    let raw = mesh.flags.len() - cut;
    let mut out = vec![0.0_f32; mesh.flags.len() * 6];
    let (mut r, mut c) = (0, raw);
    for ((p, &f), n) in mesh.positions.iter().zip(&mesh.flags).zip(&mesh.normals) {
        let slot = if f & CUT_BIT != 0 { &mut c } else { &mut r };
        out[*slot * 6..*slot * 6 + 6].copy_from_slice(&[p[0], p[1], p[2], n[0], n[1], n[2]]);
        *slot += 1;
    }
    (out, raw)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn raw_faces_come_first_with_their_normals() {
        let mesh = StockMesh {
            positions: vec![[1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [3.0, 0.0, 0.0], [4.0, 0.0, 0.0]],
            flags: vec![CUT_BIT | 2, 0b100 | 1, CUT_BIT, 2],
            normals: [2, 0b100 | 1, 0, 2].map(StockMesh::normal).to_vec(),
        };
        let (v, raw) = vertices(&mesh);
        assert_eq!(raw, 2);
        assert_eq!(&v[..6], &[2.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
        assert_eq!(&v[6..12], &[4.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(&v[12..18], &[1.0, 0.0, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(&v[18..], &[3.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
    }
}
