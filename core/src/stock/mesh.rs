//! The stock as triangles for the 3D view: every dexel end is a small square, as large
//! as its ray's cell (the dexel-end rendering of Van Hook 1986, with three grids so that walls
//! along each axis are covered), laid on the plane of the surface its grid's ends sample there
//! and lit with that surface's normal. A smooth surface is drawn by the grid whose rays meet it
//! closest to head-on (the others' ends on it would cross its squares at a steep angle: a dotted
//! moiré), so a tilted face is one closed layer of squares. Neighbouring equal ends merge into
//! rectangles (greedy meshing, within [`MERGE`]), so the raw blank's faces, flat cuts and faces
//! tilted about one axis cost few triangles. The view meshes the stock in tiles and after a cut
//! only the tiles it changed ([`TiledMesh`]).
//! The mesh is not watertight (an edge between surfaces drawn by different grids may leave a gap
//! of part of a cell); it is meant for looking at, not for volume computations
//! ([`super::Stock::volume`]); the STL is the closed mesh of `closed.rs`.
//!
//! Positions are `f32` because the GPU takes them so (WebGL2 has no double attributes).

use std::rc::Rc;

use super::{Stock, TILE, others};

/// Bits of [`StockMesh::flags`].
pub mod flag {
    /// The face's normal axis (0 = X, 1 = Y, 2 = Z).
    pub const AXIS: u8 = 0b11;
    /// The normal points to −axis.
    pub const NEGATIVE: u8 = 0b100;
    /// A cut face (else the raw blank's face).
    pub const CUT: u8 = 0b1000;
}

/// Dexel ends closer than this (mm) along a row or a column count as one face: their heights
/// differ only by the roundoff of neighbouring rays' crossings with one tool surface (a face
/// tilted about one axis gives equal ends along the other), far below what `f32` positions or a
/// screen show. A merged face keeps its first end, so it strays from any end by at most this.
const MERGE: f64 = 1e-4;

/// Triangles of the stock, W-CS: `positions` three per triangle, `flags` and `normals` one per
/// vertex (the same for the three vertices of a triangle, so the view can pass them as vertex
/// attributes). A normal is the surface's the ends sample (`surface`), not only its
/// face's axis.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StockMesh {
    pub positions: Vec<[f32; 3]>,
    pub flags: Vec<u8>,
    pub normals: Vec<[f32; 3]>,
}

/// A rectangle of equal dexel ends in one grid: cells `start..end` along the row axis, rows
/// `row..` (closed when emitted).
#[derive(Clone, Copy)]
struct Rect {
    value: f64,
    negative: bool,
    start: usize,
    end: usize,
    row: usize,
}

impl Rect {
    fn same(&self, other: &Rect) -> bool {
        self.start == other.start
            && self.end == other.end
            && self.negative == other.negative
            && (self.value - other.value).abs() <= MERGE
    }

    fn key(&self) -> (usize, usize, bool) {
        (self.start, self.end, self.negative)
    }

    fn order(&self, other: &Rect) -> std::cmp::Ordering {
        self.key().cmp(&other.key()).then(self.value.total_cmp(&other.value))
    }
}

/// Reused buffers of [`StockMesh::add_tile`].
#[derive(Default)]
struct Scratch {
    ends: Vec<(f64, bool)>,
    slots: Vec<Rect>,
    row: Vec<Rect>,
    open: Vec<Rect>,
    next: Vec<Rect>,
}

impl StockMesh {
    /// The mesh of `stock` (all its tiles).
    #[must_use]
    pub fn of(stock: &Stock) -> StockMesh {
        let mut mesh = StockMesh::default();
        let mut scratch = Scratch::default();
        for (d, ti, tj) in stock.tiles() {
            mesh.add_tile(stock, d, ti, tj, &mut scratch);
        }
        mesh
    }

    /// Adds tile `(ti, tj)` of grid `d`: along each row, neighbouring equal ends merge into a
    /// strip; strips equal in extent and end on consecutive rows merge into a rectangle (greedy
    /// meshing of a height field).
    fn add_tile(&mut self, stock: &Stock, d: usize, ti: usize, tj: usize, s: &mut Scratch) {
        let (a, b) = others(d);
        let (i0, i1) = (ti * TILE, ((ti + 1) * TILE).min(stock.n[a]));
        let (j0, j1) = (tj * TILE, ((tj + 1) * TILE).min(stock.n[b]));
        let bounds = [i0, i1, j0, j1];
        s.open.clear();
        for j in j0..j1 {
            s.row.clear();
            s.slots.clear();
            for i in i0..i1 {
                s.ends.clear();
                for span in stock.spans(d, i, j) {
                    s.ends.push((span.lo, true));
                    s.ends.push((span.hi, false));
                }
                if s.ends.len() != s.slots.len() {
                    s.row.extend(s.slots.drain(..).map(|r| Rect { end: i, ..r }));
                    s.slots.extend(s.ends.iter().map(|&(value, negative)| Rect {
                        value,
                        negative,
                        start: i,
                        end: i,
                        row: j,
                    }));
                    continue;
                }
                for (slot, &(value, negative)) in s.slots.iter_mut().zip(&s.ends) {
                    if (slot.value - value).abs() > MERGE {
                        s.row.push(Rect { end: i, ..*slot });
                        *slot = Rect { value, negative, start: i, end: i, row: j };
                    }
                }
            }
            s.row.extend(s.slots.drain(..).map(|r| Rect { end: i1, ..r }));
            // Continue the open rectangles the row repeats; close the others.
            s.row.sort_by(Rect::order);
            s.next.clear();
            let (mut p, mut q) = (0, 0);
            while p < s.open.len() || q < s.row.len() {
                match (s.open.get(p), s.row.get(q)) {
                    (Some(o), Some(r)) if o.same(r) => {
                        s.next.push(*o);
                        p += 1;
                        q += 1;
                    }
                    (Some(o), Some(r)) if o.order(r).is_lt() => {
                        self.quad(stock, d, o, j, Some(bounds));
                        p += 1;
                    }
                    (Some(o), None) => {
                        self.quad(stock, d, o, j, Some(bounds));
                        p += 1;
                    }
                    (_, Some(r)) => {
                        s.next.push(*r);
                        q += 1;
                    }
                    (None, None) => break,
                }
            }
            std::mem::swap(&mut s.open, &mut s.next);
        }
        for r in &s.open {
            self.quad(stock, d, r, j1, Some(bounds));
        }
    }

    /// Adds tile `(ti, tj)` of grid `d` of the uncut blank without looking at its rays: its two
    /// faces, what [`StockMesh::add_tile`] makes of rays that all run from `min` to `max`.
    fn add_blank_tile(&mut self, stock: &Stock, d: usize, ti: usize, tj: usize) {
        let (a, b) = others(d);
        let (i0, i1) = (ti * TILE, ((ti + 1) * TILE).min(stock.n[a]));
        let (j0, j1) = (tj * TILE, ((tj + 1) * TILE).min(stock.n[b]));
        // In add_tile's order (the +d face sorts first).
        for (value, negative) in [(stock.max[d], false), (stock.min[d], true)] {
            self.quad(stock, d, &Rect { value, negative, start: i0, end: i1, row: j0 }, j1, None);
        }
    }

    /// Emits `rect` of grid `d`, closed before row `end_row`: for a cut tile on the plane of
    /// the surface its ends sample and lit with that surface's normal, from the rays of its tile
    /// (`tile`: cells `i0..i1` × rows `j0..j1`); for the uncut blank flat and lit with its axis'.
    /// An end on a smooth surface that faces more along another grid's axis is left to that
    /// grid ([`Surface::facing_away`]).
    fn quad(&mut self, stock: &Stock, d: usize, rect: &Rect, end_row: usize, tile: Option<[usize; 4]>) {
        let (a, b) = others(d);
        let raw = if rect.negative { stock.min[d] } else { stock.max[d] };
        let cut = (rect.value - raw).abs() > MERGE;
        let flags =
            d as u8 | if rect.negative { flag::NEGATIVE } else { 0 } | if cut { flag::CUT } else { 0 };
        let cell = |k: usize, i: usize| stock.min[k] + i as f64 * stock.h[k];
        let (a0, a1) = (cell(a, rect.start), cell(a, rect.end));
        let (b0, b1) = (cell(b, rect.row), cell(b, end_row));
        let surface = match tile {
            Some(tile) => surface(stock, d, rect, end_row, tile),
            None => Surface { slope: [0.0; 2], normal: Self::normal(flags), facing_away: false },
        };
        if surface.facing_away {
            return;
        }
        // The rect's ends lie on its middle; its corners on the plane through them.
        let (am, bm) = (0.5 * (a0 + a1), 0.5 * (b0 + b1));
        let at = |u: f64, v: f64| {
            let mut p = [0.0_f32; 3];
            p[d] = (rect.value + surface.slope[0] * (u - am) + surface.slope[1] * (v - bm)) as f32;
            p[a] = u as f32;
            p[b] = v as f32;
            p
        };
        self.push_quad(
            [at(a0, b0), at(a1, b0), at(a1, b1), at(a0, b1)],
            rect.negative,
            flags,
            surface.normal,
        );
    }

    /// The two triangles of the quad `p00 p10 p11 p01` of a face normal to axis `d`, its corners
    /// stepping along `(a, b) = others(d)`: counter-clockwise seen from outside, since
    /// e_a × e_b = e_d makes that order face +d; reversed when the face looks to −d.
    pub(super) fn push_quad(
        &mut self,
        [p00, p10, p11, p01]: [[f32; 3]; 4],
        negative: bool,
        flags: u8,
        normal: [f32; 3],
    ) {
        let tris = if negative { [p00, p11, p10, p00, p01, p11] } else { [p00, p10, p11, p00, p11, p01] };
        self.positions.extend_from_slice(&tris);
        self.flags.extend_from_slice(&[flags; 6]);
        self.normals.extend_from_slice(&[normal; 6]);
    }

    /// Number of triangles.
    #[must_use]
    pub fn triangles(&self) -> usize {
        self.positions.len() / 3
    }

    /// The outward unit normal of a vertex's face's axis.
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
        let title = b"schwenkbar stock (W-CS, mm)";
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

/// What the ends of a rect sample ([`surface`]).
struct Surface {
    /// ∂f/∂x_a and ∂f/∂x_b of the ends' surface x_d = f(x_a, x_b).
    slope: [f64; 2],
    /// Its outward unit normal.
    normal: [f32; 3],
    /// A smooth surface (both neighbours agree) steeper than [`STEEP`] against the grid's axis:
    /// another grid's ends sample it more densely and draw it. Drawn by both grids, the two sets
    /// of small faces crossed each other at a steep angle and showed as a dotted moiré on a
    /// tilted face (issue 32's machined look).
    facing_away: bool,
}

/// The slope (tan of the angle against the grid's plane) above which an end on a smooth surface
/// is left to another grid: a little over 1 (45°), so that around 45° both grids draw it and no
/// gap opens where their estimates of the slope differ.
const STEEP: f64 = 1.25;

/// The surface the ends of `rect` (grid `d`, rows `rect.row..end_row`) sample, from the ends
/// of the neighbouring rays at its middle cell, within its tile (so that a tile's mesh depends
/// on its own rays only, [`TiledMesh`]). The ends of grid `d` lie on a surface
/// x_d = f(x_a, x_b) whose outward normal is ±(e_d − ∂f/∂x_a·e_a − ∂f/∂x_b·e_b), + at a ray's
/// upper end: lit with it and laid on its plane, a face tilted against the grid shades evenly
/// and closes instead of showing the terraces of its stepped ends (issue 32's moiré). Where the
/// two one-sided slopes disagree (an edge of the surface), the flatter is taken: the end
/// belongs to the face it continues.
fn surface(stock: &Stock, d: usize, rect: &Rect, end_row: usize, tile: [usize; 4]) -> Surface {
    let (a, b) = others(d);
    let [i0, i1, j0, j1] = tile;
    let (i, j) =
        ((rect.start + rect.end.max(rect.start + 1) - 1) / 2, (rect.row + end_row.max(rect.row + 1) - 1) / 2);
    // The neighbour's end of the same kind nearest to this one.
    let end_at = |i: usize, j: usize| -> Option<f64> {
        stock
            .spans(d, i, j)
            .iter()
            .map(|s| if rect.negative { s.lo } else { s.hi })
            .min_by(|x, y| (x - rect.value).abs().total_cmp(&(y - rect.value).abs()))
    };
    // The slope, and whether it is a smooth surface's (not an edge's).
    let slope = |back: Option<f64>, ahead: Option<f64>, h: f64| {
        let (p, q) = (back.map(|v| (rect.value - v) / h), ahead.map(|v| (v - rect.value) / h));
        match (p, q) {
            (Some(p), Some(q)) if (p - q).abs() <= 0.5 * p.abs().max(q.abs()).max(1.0) => {
                (0.5 * (p + q), true)
            }
            (Some(p), Some(q)) => (if p.abs() <= q.abs() { p } else { q }, false),
            (Some(p), None) | (None, Some(p)) => (p, true),
            (None, None) => (0.0, false),
        }
    };
    let (ga, smooth_a) = slope(
        (i > i0).then(|| end_at(i - 1, j)).flatten(),
        (i + 1 < i1).then(|| end_at(i + 1, j)).flatten(),
        stock.h[a],
    );
    let (gb, smooth_b) = slope(
        (j > j0).then(|| end_at(i, j - 1)).flatten(),
        (j + 1 < j1).then(|| end_at(i, j + 1)).flatten(),
        stock.h[b],
    );
    let facing_away = (smooth_a && ga.abs() > STEEP) || (smooth_b && gb.abs() > STEEP);
    let mut n = glam::DVec3::ZERO;
    (n[d], n[a], n[b]) = (1.0, -ga, -gb);
    let n = if rect.negative { -n.normalize() } else { n.normalize() };
    if n.is_finite() {
        // Laid on its plane only within the steepness it is drawn at: an edge's end stays
        // within its cell.
        let slope = [ga.clamp(-STEEP, STEEP), gb.clamp(-STEEP, STEEP)];
        Surface { slope, normal: n.as_vec3().to_array(), facing_away }
    } else {
        let normal = StockMesh::normal(d as u8 | if rect.negative { flag::NEGATIVE } else { 0 });
        Surface { slope: [0.0; 2], normal, facing_away: false }
    }
}

/// The stock's mesh in tiles ([`TILE`]), each made again only when its stamp changed: after a
/// cut, only the tiles it touched ([`TiledMesh::update`]).
#[derive(Debug, Clone, Default)]
pub struct TiledMesh {
    /// `(stamp, mesh)` per tile of the stock, in the order of [`Stock::tiles`].
    tiles: Vec<(u64, Rc<StockMesh>)>,
}

impl TiledMesh {
    /// Brings every tile up to `stock`; returns how many tiles were meshed again.
    pub fn update(&mut self, stock: &Stock) -> usize {
        self.update_within(stock, usize::MAX).0
    }

    /// Brings the tiles up to `stock` in their order, meshing at most `limit` cut tiles again
    /// (an uncut tile is two squares and not counted); returns how many tiles were meshed and
    /// whether every tile is up to date (else the next call goes on where this one stopped).
    pub fn update_within(&mut self, stock: &Stock, limit: usize) -> (usize, bool) {
        let (mut made, mut cut) = (0, 0);
        let mut scratch = Scratch::default();
        let count = stock.tiles().count();
        self.tiles.truncate(count);
        for (k, (d, ti, tj)) in stock.tiles().enumerate() {
            let stamp = stock.tile_stamp(k);
            if let Some(t) = self.tiles.get_mut(k)
                && (t.0 == stamp || stock.renamed(k, t.0) == Some(stamp))
            {
                t.0 = stamp;
                continue;
            }
            let mut mesh = StockMesh::default();
            if stock.is_pristine(k) {
                mesh.add_blank_tile(stock, d, ti, tj);
            } else {
                if cut == limit {
                    return (made, false);
                }
                cut += 1;
                mesh.add_tile(stock, d, ti, tj, &mut scratch);
            }
            let entry = (stamp, Rc::new(mesh));
            match self.tiles.get_mut(k) {
                Some(t) => *t = entry,
                None => self.tiles.push(entry),
            }
            made += 1;
        }
        (made, true)
    }

    /// `(stamp, mesh)` per tile: a tile with an unchanged stamp has the same mesh.
    #[must_use]
    pub fn tiles(&self) -> &[(u64, Rc<StockMesh>)] {
        &self.tiles
    }

    /// Number of triangles.
    #[must_use]
    pub fn triangles(&self) -> usize {
        self.tiles.iter().map(|t| t.1.triangles()).sum()
    }
}
