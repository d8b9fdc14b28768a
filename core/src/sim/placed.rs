//! The blank on the table: on a machine that knows its table's clamping surface
//! ([`MachineGeometry::table_top`](crate::machine::MachineGeometry::table_top)), the program's
//! blank is set on the table, centred, and the preset (the program's datum) goes where the
//! blank puts it, so `M91`/`M92` positions, the limit switches and the table mean for the
//! program what they mean on the real machine (issue 31). A machine without it keeps its preset.

use std::borrow::Cow;

use glam::DVec3;

use crate::Program;
use crate::ast::{BlockBody, Unit};
use crate::machine::Machine;
use crate::plane::Value;
use crate::unconfirmed;

/// The blank the program writes in its `BLK FORM 0.1`/`0.2` with numbers (W-CS, mm), or its
/// setup-sheet header's cuboid when it has no BLK FORM; `None` when neither, or when the BLK
/// FORM takes its values from parameters (known only while running).
#[must_use]
// Out of line: the page split (scripts/split_pages.py) can leave it to the wasm loaded after the
// first screen (only a machine with a table top reads it).
#[inline(never)]
pub fn written_blank(program: &Program) -> Option<(DVec3, DVec3)> {
    let mut unit = Unit::Mm;
    let mut min = None;
    let mut header = None;
    for b in &program.blocks {
        match b.stored_body() {
            Some(BlockBody::BeginPgm { unit: u, .. }) => unit = *u,
            Some(BlockBody::Header { text }) if header.is_none() => {
                header = super::interp::header_blank(text)
                    .map(|s| (DVec3::new(0.0, 0.0, -s.z), DVec3::new(s.x, s.y, 0.0)));
            }
            Some(BlockBody::BlkForm(f)) => {
                let base = if f.part == 2 { min? } else { DVec3::ZERO };
                let mut p = base;
                for w in f.axes.iter() {
                    let Some(i) = super::interp::linear_index(w.axis) else { continue };
                    let Value::Number(v) = w.value else { return None };
                    p[i] = if w.incremental { base[i] + v * unit.mm() } else { v * unit.mm() };
                }
                if f.part == 2 {
                    let min = min?;
                    return Some((DVec3::min(min, p), DVec3::max(min, p)));
                }
                min = Some(p);
            }
            _ => {}
        }
    }
    header
}

/// The preset of `machine` for `program`: with a table top, the blank's bottom face centred on
/// it (W-CS parallel to M-CS at rotary zero); without a written blank the datum
/// [`unconfirmed::DATUM_ABOVE_TABLE`] above the table's centre. A machine without a table top
/// keeps its own.
#[must_use]
pub fn placed<'m>(machine: &'m Machine, program: &Program) -> Cow<'m, Machine> {
    let Some(top) = machine.geometry.table_top else { return Cow::Borrowed(machine) };
    let preset = match written_blank(program) {
        Some((min, max)) => top - DVec3::new(0.5 * (min.x + max.x), 0.5 * (min.y + max.y), min.z),
        None => top + DVec3::new(0.0, 0.0, unconfirmed::DATUM_ABOVE_TABLE),
    };
    if preset == machine.geometry.preset {
        return Cow::Borrowed(machine);
    }
    let mut m = machine.clone();
    m.geometry.preset = preset;
    Cow::Owned(m)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn program(src: &str) -> Program {
        crate::parse(src).0
    }

    #[test]
    fn the_blank_as_written_in_numbers() {
        let p = program(
            "0 BEGIN PGM P INCH\n1 BLK FORM 0.1 Z X-1 Y+0 Z-2\n2 BLK FORM 0.2 IX+4 Y+3 Z+0\n3 END PGM P INCH\n",
        );
        let (min, max) = written_blank(&p).expect("written");
        assert!(min.abs_diff_eq(DVec3::new(-25.4, 0.0, -50.8), 1e-12), "{min}");
        assert!(max.abs_diff_eq(DVec3::new(76.2, 76.2, 0.0), 1e-12), "{max}");
        let q = program(
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-Q1\n2 BLK FORM 0.2 X+1 Y+1 Z+0\n3 END PGM P MM\n",
        );
        assert_eq!(written_blank(&q), None, "a parameter is known only while running");
        let h = program("(Quader: QX100 QY90 QZ20)\n0 BEGIN PGM P MM\n1 END PGM P MM\n");
        assert_eq!(written_blank(&h), Some((DVec3::new(0.0, 0.0, -20.0), DVec3::new(100.0, 90.0, 0.0))));
    }

    #[test]
    fn the_blank_sits_centred_on_the_table() {
        let mut m = Machine::builtin("ac-table").expect("machine");
        assert!(
            matches!(placed(&m, &program("0 BEGIN PGM P MM\n")), Cow::Borrowed(_)),
            "no table top: as it is"
        );
        m.geometry.table_top = Some(DVec3::new(10.0, 20.0, -500.0));
        let p = program(
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-40\n2 BLK FORM 0.2 X+100 Y+60 Z+0\n3 END PGM P MM\n",
        );
        // Blank centre (50, 30), bottom Z-40 → preset = top − (50, 30, −40).
        assert_eq!(placed(&m, &p).geometry.preset, DVec3::new(-40.0, -10.0, -460.0));
        let none = placed(&m, &program("0 BEGIN PGM P MM\n1 END PGM P MM\n"));
        assert_eq!(none.geometry.preset, DVec3::new(10.0, 20.0, -500.0 + unconfirmed::DATUM_ABOVE_TABLE));
    }
}
