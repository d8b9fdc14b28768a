//! The stock as a closed mesh for export (`run --stock-stl`, issue 32): the view's mesh of dexel
//! ends ([`super::mesh`]) has gaps and T-junctions where its merged rectangles meet, so slicers
//! and CAD tools need to repair it. This one is the boundary of the stock's cells: a cell of the
//! grid is material when its centre is, on its Z ray; every face between a material cell and an
//! empty one (or the outside) becomes two triangles. All corners lie on the one lattice of cell
//! corners and no face is merged, so there is no T-junction, and every edge of the surface is
//! shared by exactly two triangles once no edge is touched by two material cells that meet only
//! there ([`fill_edge_contacts`]).

use super::mesh::{StockMesh, flag};
use super::{Stock, others};

/// One bit per cell, `x + n[0]·(y + n[1]·z)`.
struct Cells {
    n: [usize; 3],
    bits: Vec<u64>,
}

impl Cells {
    /// The cells whose centre is material on its Z ray.
    fn of(stock: &Stock) -> Cells {
        let n = stock.n;
        let mut cells = Cells { n, bits: vec![0; (n[0] * n[1] * n[2]).div_ceil(64)] };
        let (z0, hz) = (stock.min.z, stock.h.z);
        for y in 0..n[1] {
            for x in 0..n[0] {
                for span in stock.spans(2, x, y) {
                    // Centres z0 + (k + ½)·hz inside [lo, hi].
                    let first = ((span.lo - z0) / hz - 0.5).ceil().max(0.0) as usize;
                    let last = ((span.hi - z0) / hz - 0.5).floor();
                    if last < 0.0 {
                        continue;
                    }
                    for z in first..=(last as usize).min(n[2] - 1) {
                        cells.set([x, y, z]);
                    }
                }
            }
        }
        cells
    }

    fn index(&self, c: [usize; 3]) -> usize {
        c[0] + self.n[0] * (c[1] + self.n[1] * c[2])
    }

    /// Material at `c`; outside the grid is empty.
    fn get(&self, c: [isize; 3]) -> bool {
        if (0..3).any(|k| c[k] < 0 || c[k] as usize >= self.n[k]) {
            return false;
        }
        let i = self.index(c.map(|v| v as usize));
        self.bits[i / 64] & (1 << (i % 64)) != 0
    }

    fn set(&mut self, c: [usize; 3]) {
        let i = self.index(c);
        self.bits[i / 64] |= 1 << (i % 64);
    }
}

/// Fills cells until no grid edge has material on one diagonal of its four cells and none on
/// the other: there the boundary would pass the edge twice (four triangles on one edge, a
/// non-manifold surface). Filling one of the two empty cells (one inside the grid: if both
/// material cells are inside, so is one empty cell of the pair) joins the two along a face; the
/// stock grows by at most that cell, within a ray spacing of the true one. Each fill adds a
/// cell, so the loop ends.
fn fill_edge_contacts(cells: &mut Cells) {
    let n = cells.n.map(|v| v as isize);
    loop {
        let mut filled = false;
        for e in 0..3 {
            let (a, b) = others(e);
            for w in 0..n[e] {
                for u in -1..n[a] {
                    for v in -1..n[b] {
                        let at = |du: isize, dv: isize| {
                            let mut c = [0; 3];
                            (c[e], c[a], c[b]) = (w, u + du, v + dv);
                            c
                        };
                        let m = |du, dv| cells.get(at(du, dv));
                        let empty = if m(0, 0) && m(1, 1) && !m(1, 0) && !m(0, 1) {
                            [at(1, 0), at(0, 1)]
                        } else if m(1, 0) && m(0, 1) && !m(0, 0) && !m(1, 1) {
                            [at(0, 0), at(1, 1)]
                        } else {
                            continue;
                        };
                        let inside = |c: &[isize; 3]| (0..3).all(|k| c[k] >= 0 && c[k] < n[k]);
                        if let Some(c) = empty.iter().find(|c| inside(c)) {
                            cells.set(c.map(|v| v as usize));
                            filled = true;
                        }
                    }
                }
            }
        }
        if !filled {
            return;
        }
    }
}

impl StockMesh {
    /// The closed mesh of `stock` (see the module doc): for STL export.
    #[must_use]
    pub fn closed(stock: &Stock) -> StockMesh {
        let mut cells = Cells::of(stock);
        fill_edge_contacts(&mut cells);
        let n = stock.n;
        let corner = |k: usize, i: usize| (stock.min[k] + i as f64 * stock.h[k]) as f32;
        let mut mesh = StockMesh::default();
        for z in 0..n[2] {
            for y in 0..n[1] {
                for x in 0..n[0] {
                    let c = [x as isize, y as isize, z as isize];
                    if !cells.get(c) {
                        continue;
                    }
                    for d in 0..3 {
                        let (a, b) = others(d);
                        for negative in [false, true] {
                            let mut next = c;
                            next[d] += if negative { -1 } else { 1 };
                            if cells.get(next) {
                                continue;
                            }
                            let i = [x, y, z];
                            let face = if negative { i[d] } else { i[d] + 1 };
                            let raw = face == 0 || face == n[d];
                            let flags = d as u8
                                | if negative { flag::NEGATIVE } else { 0 }
                                | if raw { 0 } else { flag::CUT };
                            let at = |da: usize, db: usize| {
                                let mut p = [0.0_f32; 3];
                                p[d] = corner(d, face);
                                p[a] = corner(a, i[a] + da);
                                p[b] = corner(b, i[b] + db);
                                p
                            };
                            mesh.push_quad(
                                [at(0, 0), at(1, 0), at(1, 1), at(0, 1)],
                                negative,
                                flags,
                                StockMesh::normal(flags),
                            );
                        }
                    }
                }
            }
        }
        mesh
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cells(n: [usize; 3], set: &[[usize; 3]]) -> Cells {
        let mut c = Cells { n, bits: vec![0; (n[0] * n[1] * n[2]).div_ceil(64)] };
        set.iter().for_each(|&p| c.set(p));
        c
    }

    fn count(c: &Cells) -> usize {
        c.bits.iter().map(|b| b.count_ones() as usize).sum()
    }

    /// Two cells that meet only along an edge, in each of the three axes' planes, get a third
    /// that joins them along faces; cells that meet along a face or only at a corner stay.
    #[test]
    fn cells_meeting_only_along_an_edge_are_joined_and_no_others() {
        for (a, b) in [([0, 0, 0], [1, 1, 0]), ([0, 0, 0], [0, 1, 1]), ([1, 0, 0], [0, 0, 1])] {
            let mut c = cells([2, 2, 2], &[a, b]);
            fill_edge_contacts(&mut c);
            assert_eq!(count(&c), 3, "{a:?} {b:?}");
        }
        for set in [vec![[0, 0, 0], [1, 0, 0]], vec![[0, 0, 0], [1, 1, 1]]] {
            let mut c = cells([2, 2, 2], &set);
            fill_edge_contacts(&mut c);
            assert_eq!(count(&c), 2, "{set:?}");
        }
        // The empty cell to fill is the one inside the grid.
        let mut c = cells([2, 2, 1], &[[1, 0, 0], [0, 1, 0]]);
        fill_edge_contacts(&mut c);
        assert_eq!(count(&c), 3);
    }
}
