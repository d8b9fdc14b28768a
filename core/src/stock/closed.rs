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

/// One bit per cell; each row of cells along X (fixed Y and Z) starts a new word, so a row is
/// a slice of words and neighbouring rows or cells compare a word (64 cells) at a time. The bits
/// after the last cell of a row stay 0: outside the grid is empty.
struct Cells {
    n: [usize; 3],
    /// Words per row.
    words: usize,
    bits: Vec<u64>,
}

impl Cells {
    fn empty(n: [usize; 3]) -> Cells {
        let words = n[0].div_ceil(64);
        Cells { n, words, bits: vec![0; words * n[1] * n[2]] }
    }

    /// The cells whose centre is material on its Z ray.
    fn of(stock: &Stock) -> Cells {
        let n = stock.n;
        let mut cells = Cells::empty(n);
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

    /// The first word of row (`y`, `z`).
    fn row(&self, y: usize, z: usize) -> usize {
        (y + self.n[1] * z) * self.words
    }

    /// Word `w` of row (`y`, `z`) moved by `shift` cells: bit `i` is cell `64·w + i + shift`
    /// (`shift` −1, 0 or 1; a cell before the row's first or after its last is empty).
    fn word(&self, y: usize, z: usize, w: usize, shift: isize) -> u64 {
        let r = self.row(y, z);
        let at = |k: usize| if k < self.words { self.bits[r + k] } else { 0 };
        match shift {
            0 => at(w),
            1 => (at(w) >> 1) | (at(w + 1) << 63),
            _ => (at(w) << 1) | if w > 0 { at(w - 1) >> 63 } else { 0 },
        }
    }

    /// Sets the cells of `mask` in word `w` of row (`y`, `z`) moved by `shift` (0 or 1) cells.
    fn fill(&mut self, y: usize, z: usize, w: usize, shift: usize, mask: u64) {
        let r = self.row(y, z);
        if shift == 0 {
            self.bits[r + w] |= mask;
        } else {
            self.bits[r + w] |= mask << 1;
            if w + 1 < self.words {
                self.bits[r + w + 1] |= mask >> 63;
            }
        }
    }

    fn set(&mut self, c: [usize; 3]) {
        let r = self.row(c[1], c[2]);
        self.bits[r + c[0] / 64] |= 1 << (c[0] % 64);
    }
}

/// Fills cells until no grid edge has material on one diagonal of its four cells and none on
/// the other: there the boundary would pass the edge twice (four triangles on one edge, a
/// non-manifold surface). Filling one of the two empty cells joins the two along a face; the
/// stock grows by at most that cell, within a ray spacing of the true one. Such an edge lies
/// inside the grid (at the grid's side one cell of each diagonal is outside, so empty), so both
/// empty cells are inside. Each fill adds a cell, so the loop ends. 64 edges at a time: the four
/// cells around the edges along axis `e` are words of rows, moved by a cell along X where the
/// edge's plane contains X.
fn fill_edge_contacts(cells: &mut Cells) {
    let n = cells.n;
    // The cell (du, dv) of the four around an edge along `e`, as (shift along X, dy, dz): the
    // cells differ along `others(e)` = (e + 1, e + 2) mod 3.
    let offset = |e: usize, du: usize, dv: usize| match e {
        0 => (0, du, dv),
        1 => (dv, 0, du),
        _ => (du, dv, 0),
    };
    loop {
        let mut filled = false;
        for e in 0..3 {
            let [c00, c10, c01, c11] = [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(du, dv)| offset(e, du, dv));
            let (ny, nz) =
                (n[1].saturating_sub(usize::from(e != 1)), n[2].saturating_sub(usize::from(e != 2)));
            for z in 0..nz {
                for y in 0..ny {
                    for w in 0..cells.words {
                        let get =
                            |(sx, dy, dz): (usize, usize, usize)| cells.word(y + dy, z + dz, w, sx as isize);
                        let (a, b, c, d) = (get(c00), get(c10), get(c01), get(c11));
                        let one = a & d & !b & !c;
                        let other = b & c & !a & !d;
                        if one | other == 0 {
                            continue;
                        }
                        cells.fill(y + c10.1, z + c10.2, w, c10.0, one);
                        cells.fill(y + c00.1, z + c00.2, w, c00.0, other);
                        filled = true;
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
                for w in 0..cells.words {
                    let here = cells.word(y, z, w, 0);
                    if here == 0 {
                        continue;
                    }
                    for d in 0..3 {
                        let (a, b) = others(d);
                        for negative in [false, true] {
                            // The neighbour across the face, empty outside the grid.
                            let next = match (d, negative) {
                                (0, false) => cells.word(y, z, w, 1),
                                (0, true) => cells.word(y, z, w, -1),
                                (1, false) if y + 1 < n[1] => cells.word(y + 1, z, w, 0),
                                (1, true) if y > 0 => cells.word(y - 1, z, w, 0),
                                (2, false) if z + 1 < n[2] => cells.word(y, z + 1, w, 0),
                                (2, true) if z > 0 => cells.word(y, z - 1, w, 0),
                                _ => 0,
                            };
                            let mut faces = here & !next;
                            while faces != 0 {
                                let i = [64 * w + faces.trailing_zeros() as usize, y, z];
                                faces &= faces - 1;
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
        }
        mesh
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cells(n: [usize; 3], set: &[[usize; 3]]) -> Cells {
        let mut c = Cells::empty(n);
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

    /// Cell by cell, the second method: material at `c`, outside empty.
    fn material(c: &Cells, p: [isize; 3]) -> bool {
        (0..3).all(|k| p[k] >= 0 && (p[k] as usize) < c.n[k]) && {
            let r = c.row(p[1] as usize, p[2] as usize);
            c.bits[r + p[0] as usize / 64] >> (p[0] as usize % 64) & 1 == 1
        }
    }

    /// Over random grids whose rows span word borders (70 and 130 cells along X), the words
    /// filled leave no edge with material on one diagonal only, checked cell by cell, and keep
    /// every cell that was material.
    #[test]
    fn no_edge_contact_is_left_and_the_faces_are_those_of_the_cells() {
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        for n in [[70, 4, 3], [130, 3, 4], [5, 6, 7]] {
            for density in [2, 4] {
                let mut c = Cells::empty(n);
                for z in 0..n[2] {
                    for y in 0..n[1] {
                        for x in 0..n[0] {
                            // xorshift64: a fixed sequence, so the cases are the same each run.
                            seed ^= seed << 13;
                            seed ^= seed >> 7;
                            seed ^= seed << 17;
                            if seed % density == 0 {
                                c.set([x, y, z]);
                            }
                        }
                    }
                }
                let before = c.bits.clone();
                fill_edge_contacts(&mut c);
                assert!(before.iter().zip(&c.bits).all(|(b, a)| b & !a == 0), "a cell was lost");
                let m = |p: [isize; 3]| material(&c, p);
                for e in 0..3 {
                    let (a, b) = others(e);
                    for w in 0..n[e] as isize {
                        for u in -1..n[a] as isize {
                            for v in -1..n[b] as isize {
                                let at = |du: isize, dv: isize| {
                                    let mut p = [0; 3];
                                    (p[e], p[a], p[b]) = (w, u + du, v + dv);
                                    p
                                };
                                let (p00, p10, p01, p11) =
                                    (m(at(0, 0)), m(at(1, 0)), m(at(0, 1)), m(at(1, 1)));
                                // Material on one diagonal only: both of it, neither of the other.
                                let one_diagonal = matches!(
                                    (p00, p11, p10, p01),
                                    (true, true, false, false) | (false, false, true, true)
                                );
                                assert!(!one_diagonal, "{n:?} e{e} {w} {u} {v}");
                            }
                        }
                    }
                }
            }
        }
    }
}
