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
//! A motion removes, on every ray that can meet its sweep (in its bounding box, within the
//! tool's radius of the parallelogram its axis sweeps), the interval where the ray
//! meets the volume the tool sweeps (`sweep`: closed form for a straight move with a fixed
//! tool orientation). A motion that turns the tool relative to the workpiece (rotary axes
//! moving, PLANE … MOVE) is cut as straight sub-moves with the orientation of each sub-move's
//! middle, so many that no point of the tool strays more than a quarter of the resolution from
//! its true path (`plan`). Consecutive cuts on one short straight line (CAM output's moves of a
//! few hundredths of a millimetre) are one sweep of their chord, belonging to their last step
//! (`plan`: at most half the resolution long, every point within 1/64 of it from the chord).
//! The result after a step is the same however one got there:
//! [`Cutting`] applies the same cuts in the same order from the blank or from a checkpoint.

mod closed;
mod mesh;
mod plan;
mod sweep;

use std::hash::{DefaultHasher, Hash, Hasher};
use std::sync::atomic::{AtomicU64, Ordering};

use glam::DVec3;

use crate::sim::Blank;

pub use mesh::{StockMesh, TiledMesh};
pub use plan::{Collisions, Cutting, StockCursor, StockNote, StockNoteKind, StockOptions};
pub(crate) use sweep::Cutter;

/// Spans shorter than this (mm) are dropped after a cut: what a neighbouring cut leaves over from
/// roundoff, far below any resolution.
const MIN_SPAN: f64 = 1e-7;

/// A sweep whose slab reaches less than this (mm) into a ray's material only touches it: the
/// ray is skipped. Passes of a face mill at one height leave each ray's end exactly on the next
/// pass's tip plane; without this margin roundoff would make every later pass re-cut (and
/// re-count) those rays for nothing. 1 nm, far below any resolution.
const TOUCH: f64 = 1e-6;

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
        // The common ray of one span, without the scratch list (the same pieces as below).
        if let Dexel::One(s) = *self {
            if s.hi <= lo || s.lo >= hi {
                return 0.0;
            }
            let left = (s.lo < lo && lo - s.lo >= MIN_SPAN).then_some(Span { lo: s.lo, hi: lo });
            let right = (s.hi > hi && s.hi - hi >= MIN_SPAN).then_some(Span { lo: hi, hi: s.hi });
            *self = match (left, right) {
                (None, None) => Dexel::Empty,
                (Some(a), None) | (None, Some(a)) => Dexel::One(a),
                (Some(a), Some(b)) => Dexel::Many(vec![a, b]),
            };
            return s.hi.min(hi) - s.lo.max(lo);
        }
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
        match (scratch.as_slice(), &mut *self) {
            ([], _) => *self = Dexel::Empty,
            ([s], _) => *self = Dexel::One(*s),
            // A ray cut often keeps its allocation.
            (more, Dexel::Many(v)) => {
                v.clear();
                v.extend_from_slice(more);
            }
            (more, _) => *self = Dexel::Many(more.to_vec()),
        }
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
    /// Rays of the cut's box looked at, computed or not.
    pub visited: usize,
    /// Tiles that got the cut's stamp (each is meshed again for the view).
    pub tiles: usize,
}

impl Removal {
    /// The cut's work in computed rays, the view's meshing included: a ray looked at and
    /// skipped costs about an eighth of one whose crossing is computed, meshing a tile again
    /// about 400 (measured natively on Musterprogramm 1).
    #[must_use]
    pub fn work(&self) -> usize {
        self.rays + self.visited / 8 + 400 * self.tiles
    }
}

/// Rays per side of a tile: the view meshes (and uploads) the stock in tiles of at most
/// `TILE × TILE` rays of one grid, and after a cut only the tiles it changed. 64 keeps a tile's
/// mesh well under a millisecond and Musterprogramm 1's stock at about a hundred tiles (draw
/// calls).
pub const TILE: usize = 64;

/// Tile stamps: equal stamps mean equal rays, in any stock (clones, checkpoints and the live
/// stock alike), so a cached tile mesh is reused exactly when its stamp matches. A cut by
/// [`Cutting`] stamps the tiles it changed with a value fixed by the run and the cut's index
/// ([`Stamp::done`]), so a cursor that went back to a checkpoint and cut forward again ends
/// with the same stamps as the first pass and only the tiles that really differ are meshed
/// again; a cut stopped halfway stamps with a value never used before ([`Stamp::fresh`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Stamp(pub u64);

static NEXT_STAMP: AtomicU64 = AtomicU64::new(1);

impl Stamp {
    /// A stamp no tile had before (the high bit keeps it apart from [`Stamp::done`]).
    pub fn fresh() -> Stamp {
        Stamp(NEXT_STAMP.fetch_add(1, Ordering::Relaxed) | 1 << 63)
    }

    /// A number for one run's cuts, apart from every other run's.
    pub fn run() -> u64 {
        NEXT_STAMP.fetch_add(1, Ordering::Relaxed) & 0x7fff_ffff
    }

    /// The stamp of tiles whose last change was event `event` of run `run`, cut whole.
    pub fn done(run: u64, event: usize) -> Stamp {
        Stamp(run << 32 | (event as u64 & 0xffff_ffff))
    }
}

/// The tri-dexel stock.
#[derive(Debug, Clone)]
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
    /// Per tile (grids in order, each row-major over `⌈n[a]/TILE⌉ × ⌈n[b]/TILE⌉`): the stamp of
    /// its rays' current content.
    stamps: Vec<u64>,
    /// The latest [`Stock::restamp`]s, `(tile, from, to)`: the tile meshed under `from` has the
    /// same rays under `to` ([`TiledMesh::update`] renames instead of meshing again).
    renames: Vec<(usize, u64, u64)>,
    /// The stamp of the tiles no cut has touched yet.
    pristine: u64,
}

/// Equal material; the tiles' stamps (bookkeeping of the view) do not count.
impl PartialEq for Stock {
    fn eq(&self, other: &Self) -> bool {
        self.min == other.min && self.max == other.max && self.n == other.n && self.grids == other.grids
    }
}

/// A row of one grid: where a cut made in parts goes on ([`Stock::cut_part`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct RowAt {
    d: usize,
    j: usize,
}

/// Which part of a cut [`Stock::cut_part`] makes: from row `start` on, until its work
/// ([`Removal::work`]) reached `budget`, the tiles it changes stamped `stamp`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Part {
    pub start: RowAt,
    pub budget: usize,
    pub stamp: Stamp,
}

impl Part {
    /// The whole cut at once, stamped `stamp`.
    pub fn whole(stamp: Stamp) -> Part {
        Part { start: RowAt::default(), budget: usize::MAX, stamp }
    }
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

/// Tiles of grid `d` along its two other axes.
fn tiles_of(n: [usize; 3], d: usize) -> (usize, usize) {
    let (a, b) = others(d);
    (n[a].div_ceil(TILE), n[b].div_ceil(TILE))
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
        let stamp = Stamp::fresh().0;
        let tiles = (0..3).map(|d| tiles_of(n, d)).map(|(ta, tb)| ta * tb).sum();
        Ok(Stock { min, max, n, h, grids, stamps: vec![stamp; tiles], renames: Vec::new(), pristine: stamp })
    }

    /// The blank's corners, W-CS.
    #[must_use]
    pub fn bounds(&self) -> (DVec3, DVec3) {
        (self.min, self.max)
    }

    /// The box around the material left, W-CS (`None` when nothing is left): along each axis
    /// the lowest and highest span end of the rays along that axis, exact to the cut there.
    #[must_use]
    pub fn material_bounds(&self) -> Option<(DVec3, DVec3)> {
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for (d, grid) in self.grids.iter().enumerate() {
            for s in grid.iter().flat_map(Dexel::spans) {
                lo[d] = lo[d].min(s.lo);
                hi[d] = hi[d].max(s.hi);
            }
        }
        lo.cmple(hi).all().then_some((lo, hi))
    }

    /// The first point of material along the ray `origin + λ·dir`, λ ≥ 0 (W-CS): what lies
    /// under the pointer in the 3D view (issue 32: "how deep is this hole?"). The ray is
    /// clipped to the blank's box, sampled every half ray spacing and the first sample in
    /// material bisected against the one before, so the point is exact to a ray spacing on a
    /// wall and to the cut on a floor (the Z rays hold the heights). `None` when the ray meets
    /// no material.
    #[must_use]
    pub fn first_material(&self, origin: DVec3, dir: DVec3) -> Option<DVec3> {
        let dir = dir.try_normalize()?;
        if !origin.is_finite() {
            return None;
        }
        // The ray's part inside the box (slabs).
        let (mut enter, mut leave) = (0.0_f64, f64::INFINITY);
        for k in 0..3 {
            if dir[k].abs() < 1e-12 {
                if origin[k] < self.min[k] || origin[k] > self.max[k] {
                    return None;
                }
                continue;
            }
            let (a, b) = ((self.min[k] - origin[k]) / dir[k], (self.max[k] - origin[k]) / dir[k]);
            enter = enter.max(a.min(b));
            leave = leave.min(a.max(b));
        }
        if enter > leave {
            return None;
        }
        let step = 0.5 * self.h.min_element();
        let samples = ((leave - enter) / step).ceil() as usize + 1;
        let at = |l: f64| origin + l * dir;
        let mut before = enter;
        for k in 0..samples {
            let l = (enter + k as f64 * step).min(leave);
            if self.material_at(at(l)) {
                let (mut out, mut inside) = (before, l);
                if k == 0 {
                    return Some(at(l));
                }
                for _ in 0..40 {
                    let mid = 0.5 * (out + inside);
                    if self.material_at(at(mid)) {
                        inside = mid;
                    } else {
                        out = mid;
                    }
                }
                return Some(at(inside));
            }
            before = l;
        }
        None
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

    /// The tiles: `(grid, tile column, tile row)` in the order of [`Stock::tile_stamp`].
    pub fn tiles(&self) -> impl Iterator<Item = (usize, usize, usize)> + use<> {
        let n = self.n;
        (0..3).flat_map(move |d| {
            let (ta, tb) = tiles_of(n, d);
            (0..tb).flat_map(move |tj| (0..ta).map(move |ti| (d, ti, tj)))
        })
    }

    /// The stamp of tile `k` (index in [`Stock::tiles`]): equal stamps, equal rays.
    #[must_use]
    pub fn tile_stamp(&self, k: usize) -> u64 {
        self.stamps.get(k).copied().unwrap_or(0)
    }

    /// Stamps every tile with `stamp` (a new stock from a [`Cutting`]'s event).
    pub(crate) fn stamp_all(&mut self, stamp: Stamp) {
        self.stamps.fill(stamp.0);
        self.pristine = stamp.0;
    }

    /// Whether no cut has touched tile `k` (its rays are the blank's).
    pub(crate) fn is_pristine(&self, k: usize) -> bool {
        self.stamps.get(k) == Some(&self.pristine)
    }

    /// Stamps with `to` every tile stamped with one of `from` (a cut made in parts, now whole).
    pub(crate) fn restamp(&mut self, from: &[Stamp], to: Stamp) {
        for (k, s) in self.stamps.iter_mut().enumerate() {
            if from.iter().any(|f| f.0 == *s) {
                // Per tile: a stamp a part gave is the tile's content only if no later part
                // changed that tile again.
                self.renames.push((k, *s, to.0));
                *s = to.0;
            }
        }
        // A view is at most a few frames behind: the latest renames are enough.
        const KEEP: usize = 1024;
        if self.renames.len() > KEEP {
            self.renames.drain(..self.renames.len() - KEEP);
        }
    }

    /// The stamp tile `k`, meshed under `stamp`, has now if only a [`Stock::restamp`] changed
    /// it.
    pub(crate) fn renamed(&self, k: usize, stamp: u64) -> Option<u64> {
        self.renames.iter().rev().find(|(tile, from, _)| *tile == k && *from == stamp).map(|(_, _, to)| *to)
    }

    /// Grid `d`'s first tile index and its tiles per row: ray `(i, j)` is in tile
    /// `first + i / TILE + per_row * (j / TILE)`.
    fn tile_base(&self, d: usize) -> (usize, usize) {
        let first = (0..d).map(|g| tiles_of(self.n, g)).map(|(ta, tb)| ta * tb).sum();
        (first, tiles_of(self.n, d).0)
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
        // Outside the grid along X as well as Y: a cell index past a row's end is another ray.
        let cell = |k: usize| {
            let c = ((p[k] - self.min[k]) / self.h[k]).floor();
            (c >= 0.0 && c < self.n[k] as f64).then_some(c as usize)
        };
        let (Some(i), Some(j)) = (cell(0), cell(1)) else { return false };
        self.spans(2, i, j).iter().any(|s| s.lo <= p.z && p.z <= s.hi)
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
            + self.stamps.capacity() * std::mem::size_of::<u64>()
            + self.grids.iter().map(|g| g.capacity() * std::mem::size_of::<Dexel>()).sum::<usize>()
            + heap
    }

    /// [`Stock::cut_part`] whole, with a stamp of its own. The tests cut this way; a run's cuts
    /// go through [`Cutting`].
    #[cfg(test)]
    pub(crate) fn cut(&mut self, cutter: &Cutter, axis: DVec3, p0: DVec3, p1: DVec3) -> Removal {
        self.cut_part(cutter, axis, p0, p1, Part::whole(Stamp::fresh())).0
    }

    /// Removes the volume `cutter` sweeps moving straight from tip `p0` to tip `p1` with tool
    /// axis `axis` (all W-CS), the `part` of it from its row on, stopping after the row in which
    /// its work reached the part's budget: returns what was removed and the row to go on from
    /// (`None`: done). Each ray's result depends only on that ray's material and the sweep, so
    /// a cut made in parts leaves exactly the stock of the cut made at once.
    pub(crate) fn cut_part(
        &mut self,
        cutter: &Cutter,
        axis: DVec3,
        p0: DVec3,
        p1: DVec3,
        part: Part,
    ) -> (Removal, Option<RowAt>) {
        let Part { start, budget, stamp } = part;
        let mut out = Removal::default();
        if cutter.pieces.is_empty() || !(p0.is_finite() && p1.is_finite() && axis.is_finite()) {
            return (out, None);
        }
        let frame = sweep::frame_of(axis);
        let t = frame[2];
        // Box of the tool at both ends: the axis segment grown by R·√(1 − t_k²) per axis (the
        // extent of a disc of radius R normal to t).
        let grow = DVec3::ONE - t * t;
        let grow = cutter.radius
            * DVec3::new(grow.x.max(0.0).sqrt(), grow.y.max(0.0).sqrt(), grow.z.max(0.0).sqrt());
        // Only the tool up to `reach` along t can meet the stock: beyond it each disc of the tool
        // lies outside the stock's box grown by the disc's extent. Per axis that height is linear
        // in the tip, so the larger of the two ends bounds it for every position between; the
        // smallest over the axes bounds the tool. A tilted tool dipping into a face no longer
        // visits the rays under its whole length.
        let reach = (0..3)
            .filter(|&k| t[k].abs() > 1e-12)
            .map(|k| {
                let far = |p: DVec3| {
                    let (a, b) =
                        ((self.min[k] - grow[k] - p[k]) / t[k], (self.max[k] + grow[k] - p[k]) / t[k]);
                    a.max(b)
                };
                far(p0).max(far(p1))
            })
            .fold(cutter.length, f64::min)
            .max(0.0);
        let top = t * reach;
        let lo = p0.min(p0 + top).min(p1).min(p1 + top) - grow;
        let hi = p0.max(p0 + top).max(p1).max(p1 + top) + grow;
        let (lo, hi) = (lo.max(self.min), hi.min(self.max));
        if lo.cmpgt(hi).any() {
            return (out, None);
        }
        // Every tool point lies between the tip's and the top's heights along t, so the sweep lies
        // in the slab s_lo ≤ p·t ≤ s_hi: a cheap test that skips rays whose material is outside
        // it (a tool passing just above a tilted face touches many rays' boxes but no material).
        let (s_lo, s_hi) = (p0.dot(t).min(p1.dot(t)) - 1e-9, p0.dot(t).max(p1.dot(t)) + reach + 1e-9);
        let core = Core { origin: p0, edges: [p1 - p0, top], radius: cutter.radius };
        let sweep = cutter.sweep(frame, p0, p1);
        let mut scratch = Vec::new();
        for d in start.d..3 {
            let (a, b) = others(d);
            let range = |k: usize| {
                // Rays at min + (i + ½)·h inside [lo, hi].
                let first = ((lo[k] - self.min[k]) / self.h[k] - 0.5).ceil().max(0.0) as usize;
                let last = ((hi[k] - self.min[k]) / self.h[k] - 0.5).floor();
                let last = if last < 0.0 { None } else { Some((last as usize).min(self.n[k] - 1)) };
                last.filter(|&l| l >= first).map(|l| first..=l)
            };
            let (Some(ri), Some(rj)) = (range(a), range(b)) else { continue };
            let first_row = if d == start.d { start.j.max(*rj.start()) } else { *rj.start() };
            let dir = DVec3::from_array(std::array::from_fn(|k| if k == d { 1.0 } else { 0.0 }));
            let rays = sweep.rays(dir);
            let inv_td = (t[d].abs() > 1e-12).then(|| 1.0 / t[d]);
            let area = self.h[a] * self.h[b];
            let (tile_first, tiles_per_row) = self.tile_base(d);
            for j in first_row..=*rj.end() {
                // Only the rays of the row within the radius of the core's shadow.
                let y = self.min[b] + (j as f64 + 0.5) * self.h[b];
                let Some((x0, x1)) = core.row(a, b, y) else { continue };
                let first = ((x0 - self.min[a]) / self.h[a] - 0.5).ceil().max(*ri.start() as f64) as usize;
                let last = ((x1 - self.min[a]) / self.h[a] - 0.5).floor().min(*ri.end() as f64);
                if last < first as f64 {
                    continue;
                }
                let row = first..=last as usize;
                out.visited += row.end() + 1 - row.start();
                for i in row {
                    let mut r0 = DVec3::ZERO;
                    r0[a] = self.min[a] + (i as f64 + 0.5) * self.h[a];
                    r0[b] = self.min[b] + (j as f64 + 0.5) * self.h[b];
                    // The slab along this ray: r0·t + λ·t_d within [s_lo, s_hi].
                    let (mut from, mut to) = (lo[d], hi[d]);
                    let at = r0.dot(t);
                    if let Some(inv) = inv_td {
                        let (x, y) = ((s_lo - at) * inv, (s_hi - at) * inv);
                        from = from.max(x.min(y));
                        to = to.min(x.max(y));
                    } else if at < s_lo || at > s_hi {
                        continue;
                    }
                    let dexel = &mut self.grids[d][i + self.n[a] * j];
                    if from > to || !dexel.spans().iter().any(|s| s.hi > from + TOUCH && s.lo < to - TOUCH) {
                        continue;
                    }
                    out.rays += 1;
                    if let Some((x0, x1)) = rays.material_interval(r0, dexel.spans()) {
                        let removed = dexel.subtract(x0, x1, &mut scratch);
                        out.volume += removed * area / 3.0;
                        out.depth = out.depth.max(removed);
                        if removed > 0.0 {
                            let k = tile_first + i / TILE + tiles_per_row * (j / TILE);
                            if self.stamps[k] != stamp.0 {
                                self.stamps[k] = stamp.0;
                                out.tiles += 1;
                            }
                        }
                    }
                }
                if out.work() >= budget {
                    return (out, Some(RowAt { d, j: j + 1 }));
                }
            }
        }
        (out, None)
    }
}

/// The core of a sweep: the parallelogram the tool's axis sweeps (from `origin` along the move
/// and along the axis up to the reach), every point of the tool within `radius` of it (a tool is
/// round about its axis, no wider than its radius). A ray of grid `d` misses the sweep when, seen
/// along `d`, its point lies farther than the radius from the parallelogram's shadow: the
/// shadow's edges, each grown by the radius to a 2D capsule, bound the row's rays that can hit.
struct Core {
    origin: DVec3,
    edges: [DVec3; 2],
    radius: f64,
}

impl Core {
    /// The `a` coordinates of the points on the line `b = y` (the two other axes of a grid)
    /// within the radius of the shadow: the union of the four edges' capsules, which holds
    /// the shadow's part of the line too (its ends lie on edges).
    fn row(&self, a: usize, b: usize, y: f64) -> Option<(f64, f64)> {
        let flat = |v: DVec3| DVec3::new(v[a], v[b], 0.0);
        let (e1, e2) = (flat(self.edges[0]), flat(self.edges[1]));
        let start = DVec3::new(0.0, y - self.origin[b], 0.0);
        // A hair wider than the radius: roundoff must not drop a ray the sweep touches.
        let r = self.radius * (1.0 + 1e-9) + 1e-9;
        let mut out: Option<(f64, f64)> = None;
        for (from, along) in [(DVec3::ZERO, e1), (DVec3::ZERO, e2), (e1, e2), (e2, e1)] {
            // An edge farther than the radius from the line along y meets it nowhere.
            let (y0, y1) = (from.y.min(from.y + along.y), from.y.max(from.y + along.y));
            if start.y < y0 - r || start.y > y1 + r {
                continue;
            }
            if let Some((lo, hi)) = sweep::flat_capsule_interval(start - from, DVec3::X, along, r) {
                out = Some(out.map_or((lo, hi), |(l, h)| (l.min(lo), h.max(hi))));
            }
        }
        out.map(|(lo, hi)| (lo + self.origin[a], hi + self.origin[a]))
    }
}

#[cfg(test)]
mod tests;
