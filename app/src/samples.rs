//! The sample programs that ship in `static/programs/`, compiled in.

use crate::i18n::Text;

#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    pub id: &'static str,
    pub title: Text,
    /// The machine the sample is written for; opening it selects that machine.
    pub machine: &'static str,
    pub text: &'static str,
}

pub const MUSTERPROGRAMM_1: Sample = Sample {
    id: "musterprogramm1",
    title: Text::new("Musterprogramm 1 (ergänzt)", "Sample program 1 (completed)"),
    machine: "ac-table",
    text: include_str!("../../static/programs/musterprogramm1.h"),
};

pub static SAMPLES: [Sample; 6] = [
    MUSTERPROGRAMM_1,
    Sample {
        id: "euler_fasen",
        title: Text::new("PLANE EULER: vier Fasen", "PLANE EULER: four chamfers"),
        machine: "ac-table",
        text: include_str!("../../static/programs/euler_fasen.h"),
    },
    Sample {
        id: "stay_q120",
        title: Text::new("STAY und L A+Q120 C+Q122", "STAY and L A+Q120 C+Q122"),
        machine: "ac-table",
        text: include_str!("../../static/programs/stay_q120.h"),
    },
    Sample {
        id: "winkel_nicht_erlaubt",
        title: Text::new("Winkel nicht erlaubt (SYM−)", "Angle not permitted (SYM−)"),
        machine: "ba-table",
        text: include_str!("../../static/programs/winkel_nicht_erlaubt.h"),
    },
    Sample {
        id: "musterprogramm2",
        title: Text::new(
            "Musterprogramm 2 (Nullpunkt, dann schwenken)",
            "Sample program 2 (datum, then tilt)",
        ),
        machine: "ac-table",
        text: include_str!("../../static/programs/musterprogramm2.h"),
    },
    Sample {
        id: "kollision_schwenken",
        title: Text::new("Kollision beim Schwenken", "Collision while swivelling"),
        machine: "ac-table",
        text: include_str!("../../static/programs/kollision_schwenken.h"),
    },
];

/// The program a first visit starts with.
pub const DEFAULT: Sample = MUSTERPROGRAMM_1;

#[must_use]
pub fn by_id(id: &str) -> Option<&'static Sample> {
    SAMPLES.iter().find(|s| s.id == id)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_sample_parses_without_diagnostics_and_names_a_shipped_machine() {
        for s in &SAMPLES {
            let (_, diags) = schwenkbar_core::parse(s.text);
            assert!(diags.is_empty(), "{}: {diags:?}", s.id);
            assert!(schwenkbar_core::machine::Machine::builtin(s.machine).is_ok(), "{}", s.machine);
        }
    }

    /// The collision sample stops where it says: at its PLANE block, the chosen SEQ− swivel
    /// lifting the table's rim into the tool, with the free SEQ+ named (the geometry worked by
    /// hand in core/tests/collision.rs for the same scene).
    #[test]
    fn the_collision_sample_stops_at_its_swivel_and_names_the_free_solution() {
        use schwenkbar_core::machine::Machine;
        use schwenkbar_core::sim::{SimOptions, simulate};
        let s = by_id("kollision_schwenken").expect("the sample");
        let (program, _) = schwenkbar_core::parse(s.text);
        let sim = simulate(&program, &Machine::builtin(s.machine).expect("machine"), &SimOptions::default());
        let e = sim.error.as_ref().expect("the run stops");
        let block = &program.blocks[e.block];
        assert!(s.text[block.span().start..block.span().end].contains("PLANE SPATIAL SPA-30"), "{e:?}");
        let c = sim.collision().expect("a collision");
        assert_eq!(c.alternative.as_ref().map(|a| a.word.as_str()), Some("SEQ+"));
    }
}
