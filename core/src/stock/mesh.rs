//! The stock as triangles for the 3D view and STL: every dexel end is a small square facing
//! along its ray, as large as its ray's cell (the dexel-end rendering of Van Hook 1986, with
//! three grids so that walls along each axis are covered). Neighbouring ends along a row at the
//! same height merge into one strip, so the raw blank's faces and flat cuts cost few triangles.
//! The mesh is not watertight (tilted faces are sampled by the ends, like a heightfield of
//! tiles); it is meant for looking at, not for volume computations ([`super::Stock::volume`]).
//!
//! Positions are `f32` because the GPU takes them so (WebGL2 has no double attributes).

use super::{Stock, others};

/// Bits of [`StockMesh::flags`].
pub mod flag {
    /// The face's normal axis (0 = X, 1 = Y, 2 = Z).
    pub const AXIS: u8 = 0b11;
    /// The normal points to −axis.
    pub const NEGATIVE: u8 = 0b100;
    /// A cut face (else the raw blank's face).
    pub const CUT: u8 = 0b1000;
}

/// Triangles of the stock, W-CS: `positions` three per triangle, `flags` one per vertex (the
/// same for the three vertices of a triangle, so the view can pass it as a vertex attribute).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StockMesh {
    pub positions: Vec<[f32; 3]>,
    pub flags: Vec<u8>,
}

/// A run of equal dexel ends along one row.
#[derive(Clone, Copy)]
struct Run {
    value: f64,
    negative: bool,
    start: usize,
}

impl StockMesh {
    /// The mesh of `stock`.
    #[must_use]
    pub fn of(stock: &Stock) -> StockMesh {
        let mut mesh = StockMesh::default();
        let mut ends = Vec::new();
        let mut runs: Vec<Run> = Vec::new();
        for d in 0..3 {
            let (a, b) = others(d);
            for j in 0..stock.n[b] {
                for i in 0..stock.n[a] {
                    ends.clear();
                    for s in stock.spans(d, i, j) {
                        ends.push((s.lo, true));
                        ends.push((s.hi, false));
                    }
                    let same = ends.len() == runs.len();
                    if !same {
                        for r in runs.drain(..) {
                            mesh.quad(stock, d, j, r, i);
                        }
                    }
                    for (k, &(value, negative)) in ends.iter().enumerate() {
                        if same {
                            if runs[k].value.to_bits() == value.to_bits() {
                                continue;
                            }
                            let r = runs[k];
                            mesh.quad(stock, d, j, r, i);
                            runs[k] = Run { value, negative, start: i };
                        } else {
                            runs.push(Run { value, negative, start: i });
                        }
                    }
                }
                for r in runs.drain(..) {
                    mesh.quad(stock, d, j, r, stock.n[a]);
                }
            }
        }
        mesh
    }

    /// Emits the strip of `run` on row `j` of grid `d`, cells `run.start..end`.
    fn quad(&mut self, stock: &Stock, d: usize, j: usize, run: Run, end: usize) {
        let (a, b) = others(d);
        let raw = if run.negative { stock.min[d] } else { stock.max[d] };
        let cut = run.value.to_bits() != raw.to_bits();
        let flags = d as u8 | if run.negative { flag::NEGATIVE } else { 0 } | if cut { flag::CUT } else { 0 };
        let (a0, a1) = (stock.min[a] + run.start as f64 * stock.h[a], stock.min[a] + end as f64 * stock.h[a]);
        let (b0, b1) = (stock.min[b] + j as f64 * stock.h[b], stock.min[b] + (j + 1) as f64 * stock.h[b]);
        let at = |u: f64, v: f64| {
            let mut p = [0.0_f32; 3];
            p[d] = run.value as f32;
            p[a] = u as f32;
            p[b] = v as f32;
            p
        };
        // Counter-clockwise seen from outside: e_a × e_b = e_d, so (a, b) order faces +d.
        let (p00, p10, p11, p01) = (at(a0, b0), at(a1, b0), at(a1, b1), at(a0, b1));
        let tris = if run.negative { [p00, p11, p10, p00, p01, p11] } else { [p00, p10, p11, p00, p11, p01] };
        self.positions.extend_from_slice(&tris);
        self.flags.extend_from_slice(&[flags; 6]);
    }

    /// Number of triangles.
    #[must_use]
    pub fn triangles(&self) -> usize {
        self.positions.len() / 3
    }

    /// The outward unit normal of a vertex's face.
    #[must_use]
    pub fn normal(flags: u8) -> [f32; 3] {
        let mut n = [0.0; 3];
        n[usize::from(flags & flag::AXIS).min(2)] = if flags & flag::NEGATIVE != 0 { -1.0 } else { 1.0 };
        n
    }

    /// Binary STL (80-byte header, triangle count, per triangle normal, three vertices and a
    /// zero attribute word; little-endian, as the format's 3D Systems definition has it).
    #[must_use]
    pub fn to_stl(&self) -> Vec<u8> {
        let n = self.triangles();
        let mut out = Vec::with_capacity(84 + 50 * n);
        let mut header = [b' '; 80];
        let title = b"schwenkbar stock (tri-dexel ends, W-CS, mm)";
        header[..title.len()].copy_from_slice(title);
        out.extend_from_slice(&header);
        out.extend_from_slice(&u32::try_from(n).unwrap_or(u32::MAX).to_le_bytes());
        for (tri, flags) in self.positions.chunks_exact(3).zip(self.flags.chunks_exact(3)) {
            for x in Self::normal(flags[0]).iter().chain(tri.iter().flatten()) {
                out.extend_from_slice(&x.to_le_bytes());
            }
            out.extend_from_slice(&[0, 0]);
        }
        out
    }
}
