//! The blank as material that the program cuts (issue 14): a tri-dexel model of the `BLK FORM`
//! box from which every executed motion removes the volume its tool sweeps, in any tool
//! orientation.
//!
//! # The model
//! A *dexel* (depth element) is a ray through the workpiece holding the sorted, disjoint
//! intervals where it runs in material (Van Hook, "Real-time shaded NC milling display",
//! SIGGRAPH 1986). One grid of parallel rays is exact only along its direction; three orthogonal
//! grids along X, Y and Z of the W-CS (the *tri-dexel* model: Benouamer & Michelucci, "Bridging
//! the gap between CSG and Brep via a triple ray representation", ACM Solid Modeling 1997;
//! Müller, Surmann & Weinert, "Tri-dexel model for material removal simulation", 2003) sample
//! every surface, tilted faces and hole walls included, with exact end points along their rays.
//! The rays sit at the centres of the cells of a grid of the chosen resolution over the blank
//! (the spacing per axis is `size / ⌈size / resolution⌉`, so the cells tile the blank exactly).
//!
//! # Cutting
//! A motion removes, on every ray that crosses its bounding box, the interval where the ray
//! meets the volume the tool sweeps ([`sweep`]: closed form for a straight move with a fixed
//! tool orientation). A motion that turns the tool relative to the workpiece (rotary axes
//! moving, PLANE … MOVE) is cut as straight sub-moves with the orientation of each sub-move's
//! middle, so many that no point of the tool strays more than a quarter of the resolution from
//! its true path ([`plan`]). The result after a step is the same however one got there:
//! [`Cutting`] applies the same cuts in the same order from the blank or from a checkpoint.

mod mesh;
mod plan;
mod sweep;

use std::hash::{DefaultHasher, Hash, Hasher};

use glam::DVec3;

use crate::sim::Blank;

pub use mesh::StockMesh;
pub use plan::{Cutting, StockCursor, StockNote, StockNoteKind, StockOptions};
pub(crate) use sweep::Cutter;

/// Spans shorter than this (mm) are dropped after a cut: what a neighbouring cut leaves over from
/// roundoff, far below any resolution.
const MIN_SPAN: f64 = 1e-7;

/// At most this many rays in all three grids: about 14 MB at one span per ray (24 bytes each),
/// so the live stock and its checkpoints stay within the 64 MB. A bigger blank gets a
/// coarser resolution ([`Stock::new`]).
pub const MAX_RAYS: usize = 600_000;

/// Where a ray runs in material, `lo < hi` (mm along its axis).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    pub lo: f64,
    pub hi: f64,
}

/// The material of one ray: most rays hold one span all their life, so it is kept without a
/// heap allocation.
#[derive(Debug, Clone, PartialEq)]
enum Dexel {
    Empty,
    One(Span),
    Many(Vec<Span>),
}

impl Dexel {
    fn spans(&self) -> &[Span] {
        match self {
            Dexel::Empty => &[],
            Dexel::One(s) => std::slice::from_ref(s),
            Dexel::Many(v) => v,
        }
    }

    /// Removes `[lo, hi]`; returns the length removed.
    fn subtract(&mut self, lo: f64, hi: f64, scratch: &mut Vec<Span>) -> f64 {
        let spans = self.spans();
        if !spans.iter().any(|s| s.hi > lo && s.lo < hi) {
            return 0.0;
        }
        scratch.clear();
        let mut removed = 0.0;
        for s in spans {
            if s.hi <= lo || s.lo >= hi {
                scratch.push(*s);
                continue;
            }
            removed += s.hi.min(hi) - s.lo.max(lo);
            if s.lo < lo && lo - s.lo >= MIN_SPAN {
                scratch.push(Span { lo: s.lo, hi: lo });
            }
            if s.hi > hi && s.hi - hi >= MIN_SPAN {
                scratch.push(Span { lo: hi, hi: s.hi });
            }
        }
        *self = match scratch.as_slice() {
            [] => Dexel::Empty,
            [s] => Dexel::One(*s),
            more => Dexel::Many(more.to_vec()),
        };
        removed
    }
}

/// What one cut removed.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Removal {
    /// Removed volume, mm³ (mean of the three grids' estimates).
    pub volume: f64,
    /// The longest piece removed from one ray, mm.
    pub depth: f64,
    /// Rays whose crossing with the sweep was computed (the work of the cut).
    pub rays: usize,
}

/// The tri-dexel stock.
#[derive(Debug, Clone, PartialEq)]
pub struct Stock {
    min: DVec3,
    max: DVec3,
    /// Cells per axis.
    n: [usize; 3],
    /// Ray spacing per axis, mm.
    h: DVec3,
    /// Grid `d` holds the rays along axis `d`, ray `(i, j)` at index `i + n[a]·j` over the other
    /// two axes `a = (d + 1) % 3`, `b = (d + 2) % 3`.
    grids: [Vec<Dexel>; 3],
}

/// Why a blank gives no stock.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StockError {
    /// Not finite, or no volume.
    InvalidBlank,
}

/// The two other axes of grid `d`.
const fn others(d: usize) -> (usize, usize) {
    ((d + 1) % 3, (d + 2) % 3)
}

impl Stock {
    /// The blank as full material at `resolution` (mm), or at the finest resolution that keeps
    /// the rays within [`MAX_RAYS`] (see [`Stock::resolution`]).
    pub fn new(blank: &Blank, resolution: f64) -> Result<Stock, StockError> {
        let (min, max) = (blank.min.min(blank.max), blank.min.max(blank.max));
        let size = max - min;
        if !(min.is_finite() && max.is_finite()) || size.min_element() <= 0.0 {
            return Err(StockError::InvalidBlank);
        }
        // Rays ≈ (sx·sy + sy·sz + sz·sx) / res², so res ≥ √(area / MAX_RAYS) keeps the cap.
        let area = size.x * size.y + size.y * size.z + size.z * size.x;
        let floor = (area / MAX_RAYS as f64).sqrt();
        let mut res =
            if resolution.is_finite() && resolution > 0.0 { resolution.max(floor) } else { floor.max(1.0) };
        let cells = |res: f64| size.to_array().map(|s| ((s / res).ceil().max(1.0)) as usize);
        let count = |n: [usize; 3]| n[0] * n[1] + n[1] * n[2] + n[2] * n[0];
        let mut n = cells(res);
        // The ceiling may add a row per axis; grow the resolution until the count fits.
        while count(n) > MAX_RAYS {
            res *= 1.05;
            n = cells(res);
        }
        if !res.is_finite() {
            return Err(StockError::InvalidBlank);
        }
        let h = size / DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64);
        let grids = std::array::from_fn(|d| {
            let (a, b) = others(d);
            vec![Dexel::One(Span { lo: min[d], hi: max[d] }); n[a] * n[b]]
        });
        Ok(Stock { min, max, n, h, grids })
    }

    /// The blank's corners, W-CS.
    #[must_use]
    pub fn bounds(&self) -> (DVec3, DVec3) {
        (self.min, self.max)
    }

    /// The coarsest ray spacing, mm (the resolution asked for unless the blank was too big).
    #[must_use]
    pub fn resolution(&self) -> f64 {
        self.h.max_element()
    }

    /// Ray spacing per axis, mm.
    #[must_use]
    pub fn spacing(&self) -> DVec3 {
        self.h
    }

    /// Cells per axis.
    #[must_use]
    pub fn cells(&self) -> [usize; 3] {
        self.n
    }

    /// The material of ray `(i, j)` of grid `d` (rays along axis `d`; `i`, `j` over the next two
    /// axes in cyclic order), empty outside the grid.
    #[must_use]
    pub fn spans(&self, d: usize, i: usize, j: usize) -> &[Span] {
        let (a, _) = others(d % 3);
        if i >= self.n[a] {
            return &[];
        }
        self.grids[d % 3].get(i + self.n[a] * j).map_or(&[], Dexel::spans)
    }

    /// Where ray `(i, j)` of grid `d` runs: its coordinates on the two other axes.
    #[must_use]
    pub fn ray_position(&self, d: usize, i: usize, j: usize) -> (f64, f64) {
        let (a, b) = others(d % 3);
        (self.min[a] + (i as f64 + 0.5) * self.h[a], self.min[b] + (j as f64 + 0.5) * self.h[b])
    }

    /// Whether `p` (W-CS) is in material, as the Z grid's ray through its cell has it.
    #[must_use]
    pub fn material_at(&self, p: DVec3) -> bool {
        let cell = (p - self.min) / self.h;
        if !(cell.x >= 0.0 && cell.y >= 0.0) {
            return false;
        }
        let (i, j) = (cell.x as usize, cell.y as usize);
        j < self.n[1] && self.spans(2, i, j).iter().any(|s| s.lo <= p.z && p.z <= s.hi)
    }

    /// Volume of material, mm³: each grid's midpoint-rule sum of span lengths × cell area,
    /// averaged over the three grids.
    #[must_use]
    pub fn volume(&self) -> f64 {
        (0..3).map(|d| self.grid_volume(d)).sum::<f64>() / 3.0
    }

    /// Volume of material as grid `d` alone measures it, mm³.
    #[must_use]
    pub fn grid_volume(&self, d: usize) -> f64 {
        let (a, b) = others(d % 3);
        let len: f64 = self.grids[d % 3].iter().flat_map(Dexel::spans).map(|s| s.hi - s.lo).sum();
        len * self.h[a] * self.h[b]
    }

    /// A hash of every span end (bit-exact): equal stocks have equal digests.
    #[must_use]
    pub fn digest(&self) -> u64 {
        let mut hasher = DefaultHasher::new();
        self.n.hash(&mut hasher);
        for g in &self.grids {
            for dexel in g {
                let s = dexel.spans();
                s.len().hash(&mut hasher);
                for span in s {
                    span.lo.to_bits().hash(&mut hasher);
                    span.hi.to_bits().hash(&mut hasher);
                }
            }
        }
        hasher.finish()
    }

    /// Bytes held by the stock (rays and spilled spans).
    #[must_use]
    pub fn memory_bytes(&self) -> usize {
        let heap: usize = self
            .grids
            .iter()
            .flatten()
            .map(|d| match d {
                Dexel::Many(v) => v.capacity() * std::mem::size_of::<Span>(),
                _ => 0,
            })
            .sum();
        std::mem::size_of::<Stock>()
            + self.grids.iter().map(|g| g.capacity() * std::mem::size_of::<Dexel>()).sum::<usize>()
            + heap
    }

    /// Removes the volume `cutter` sweeps moving straight from tip `p0` to tip `p1` with tool
    /// axis `axis` (all W-CS).
    pub(crate) fn cut(&mut self, cutter: &Cutter, axis: DVec3, p0: DVec3, p1: DVec3) -> Removal {
        let mut out = Removal::default();
        if cutter.pieces.is_empty() || !(p0.is_finite() && p1.is_finite() && axis.is_finite()) {
            return out;
        }
        let frame = sweep::frame_of(axis);
        let t = frame[2];
        // Box of the tool at both ends: the axis segment grown by R·√(1 − t_k²) per axis (the
        // extent of a disc of radius R normal to t).
        let grow = DVec3::ONE - t * t;
        let grow = cutter.radius
            * DVec3::new(grow.x.max(0.0).sqrt(), grow.y.max(0.0).sqrt(), grow.z.max(0.0).sqrt());
        let top = t * cutter.length;
        let lo = p0.min(p0 + top).min(p1).min(p1 + top) - grow;
        let hi = p0.max(p0 + top).max(p1).max(p1 + top) + grow;
        let (lo, hi) = (lo.max(self.min), hi.min(self.max));
        if lo.cmpgt(hi).any() {
            return out;
        }
        // Every tool point lies between the tip's and the top's heights along t, so the sweep lies
        // in the slab s_lo ≤ p·t ≤ s_hi: a cheap test that skips rays whose material is outside
        // it (a tool passing just above a tilted face touches many rays' boxes but no material).
        let (s_lo, s_hi) = (p0.dot(t).min(p1.dot(t)) - 1e-9, p0.dot(t).max(p1.dot(t)) + cutter.length + 1e-9);
        let mut scratch = Vec::new();
        for d in 0..3 {
            let (a, b) = others(d);
            let range = |k: usize| {
                // Rays at min + (i + ½)·h inside [lo, hi].
                let first = ((lo[k] - self.min[k]) / self.h[k] - 0.5).ceil().max(0.0) as usize;
                let last = ((hi[k] - self.min[k]) / self.h[k] - 0.5).floor();
                let last = if last < 0.0 { None } else { Some((last as usize).min(self.n[k] - 1)) };
                last.filter(|&l| l >= first).map(|l| first..=l)
            };
            let (Some(ri), Some(rj)) = (range(a), range(b)) else { continue };
            let dir = DVec3::from_array(std::array::from_fn(|k| if k == d { 1.0 } else { 0.0 }));
            let area = self.h[a] * self.h[b];
            for j in rj {
                for i in ri.clone() {
                    let mut r0 = DVec3::ZERO;
                    r0[a] = self.min[a] + (i as f64 + 0.5) * self.h[a];
                    r0[b] = self.min[b] + (j as f64 + 0.5) * self.h[b];
                    // The slab along this ray: r0·t + λ·t_d within [s_lo, s_hi].
                    let (mut from, mut to) = (lo[d], hi[d]);
                    let at = r0.dot(t);
                    if t[d].abs() > 1e-12 {
                        let (x, y) = ((s_lo - at) / t[d], (s_hi - at) / t[d]);
                        from = from.max(x.min(y));
                        to = to.min(x.max(y));
                    } else if at < s_lo || at > s_hi {
                        continue;
                    }
                    let dexel = &mut self.grids[d][i + self.n[a] * j];
                    if from > to || !dexel.spans().iter().any(|s| s.hi > from && s.lo < to) {
                        continue;
                    }
                    out.rays += 1;
                    if let Some((x0, x1)) = cutter.ray_interval(&frame, p0, p1, r0, dir) {
                        let removed = dexel.subtract(x0, x1, &mut scratch);
                        out.volume += removed * area / 3.0;
                        out.depth = out.depth.max(removed);
                    }
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests;
