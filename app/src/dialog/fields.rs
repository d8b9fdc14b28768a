//! The prompts of each PLANE function in the control's order, with their one-line help
//! (DOMAIN.md §7; the English prompts are the manual's). German: the EULER and VECTOR prompts
//! are the iTNC 530 German user manual's and confirmed (`confirmed: true`); the other German
//! prompts are ours in the manual's abbreviation style, UNCONFIRMED
//! (`unconfirmed::Decision::DialogWording`, said under the prompt).

use schwenkbar_core::plane::Word;

use crate::i18n::Text;

/// One value the dialog asks for.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// The NC word (`SPA`), also the key for the input range.
    pub word: Word,
    pub prompt: Text,
    pub help: Text,
    pub required: bool,
    /// The German prompt is the manual's.
    pub confirmed: bool,
}

const fn field(word: Word, prompt: Text, help: Text) -> Field {
    Field { word, prompt, help, required: true, confirmed: false }
}

/// A field whose German prompt the iTNC 530 German user manual gives.
const fn manual_field(word: Word, prompt: Text, help: Text) -> Field {
    Field { word, prompt, help, required: true, confirmed: true }
}

pub(super) const fn t(de: &'static str, en: &'static str) -> Text {
    Text::new(de, en)
}

pub(super) static SPATIAL: [Field; 3] = [
    field(
        Word::Spa,
        t("Raumwinkel A?", "Spatial angle A?"),
        t(
            "Drehung um die maschinenfeste X-Achse, −359,9999…+359,9999°. Positiv: Daumen der rechten Hand in +X, die Finger zeigen die Drehrichtung.",
            "Rotation about the machine-fixed X axis, −359.9999…+359.9999°. Positive: right thumb along +X, the fingers show the direction.",
        ),
    ),
    field(
        Word::Spb,
        t("Raumwinkel B?", "Spatial angle B?"),
        t(
            "Drehung um die maschinenfeste Y-Achse, −359,9999…+359,9999°. Positiv kippt die Werkzeugachse von +Z nach +X.",
            "Rotation about the machine-fixed Y axis, −359.9999…+359.9999°. Positive tips the tool axis from +Z towards +X.",
        ),
    ),
    field(
        Word::Spc,
        t("Raumwinkel C?", "Spatial angle C?"),
        t(
            "Drehung um die maschinenfeste Z-Achse, −359,9999…+359,9999°. Alle drei Raumwinkel sind Pflicht, auch wenn sie 0 sind.",
            "Rotation about the machine-fixed Z axis, −359.9999…+359.9999°. All three spatial angles are required, even when 0.",
        ),
    ),
];

pub(super) static PROJECTED: [Field; 3] = [
    field(
        Word::Propr,
        t("Proj.-Winkel 1. Koordinatenebene?", "Proj. angle 1st coordinate plane?"),
        t(
            "Winkel der Ebene in der Z/X-Ebene (0°-Achse = X), −89,9999…+89,9999°.",
            "Angle of the plane's trace in the Z/X plane (0° axis = X), −89.9999…+89.9999°.",
        ),
    ),
    field(
        Word::Promin,
        t("Proj.-Winkel 2. Koordinatenebene?", "Proj. angle 2nd coordinate plane?"),
        t(
            "Winkel der Ebene in der Y/Z-Ebene (0°-Achse = Y), −89,9999…+89,9999°.",
            "Angle of the plane's trace in the Y/Z plane (0° axis = Y), −89.9999…+89.9999°.",
        ),
    ),
    field(
        Word::Rot,
        t("ROT-Winkel der geschw. Ebene?", "ROT angle of the tilted plane?"),
        t(
            "Drehung um die geschwenkte Werkzeugachse, 0…360°.",
            "Rotation about the tilted tool axis, 0…360°.",
        ),
    ),
];

pub(super) static EULER: [Field; 3] = [
    manual_field(
        Word::Eulpr,
        t("Drehw. Haupt-Koordinatenebene?", "Rot. angle main coordinate plane?"),
        t(
            "Präzession: Drehung um die ungeschwenkte Z-Achse, −180…+180°.",
            "Precession: rotation about the untilted Z axis, −180…+180°.",
        ),
    ),
    manual_field(
        Word::Eulnu,
        t("Schwenkwinkel Werkzeug-Achse?", "Tilting angle tool axis?"),
        t(
            "Nutation: Drehung um die gedrehte X-Achse, 0…180°.",
            "Nutation: rotation about the rotated X axis, 0…180°.",
        ),
    ),
    manual_field(
        Word::Eulrot,
        t("ROT-Winkel der geschw. Ebene?", "ROT angle of the tilted plane?"),
        t(
            "Rotation: Drehung um die geschwenkte Z-Achse, richtet die geschwenkte X-Achse aus, 0…360°.",
            "Rotation about the tilted Z axis, aligns the tilted X axis, 0…360°.",
        ),
    ),
];

const fn vec_field(word: Word, prompt: Text) -> Field {
    manual_field(
        word,
        prompt,
        t(
            "Komponente, muss nicht normiert sein: die Steuerung normiert selbst.",
            "Component; need not be of unit length: the control normalises.",
        ),
    )
}

pub(super) static VECTOR: [Field; 6] = [
    vec_field(Word::Bx, t("X-Komponente Basisvektor?", "X component of base vector?")),
    vec_field(Word::By, t("Y-Komponente Basisvektor?", "Y component of base vector?")),
    vec_field(Word::Bz, t("Z-Komponente Basisvektor?", "Z component of base vector?")),
    vec_field(Word::Nx, t("X-Komponente Normalenvektor?", "X component of normal vector?")),
    vec_field(Word::Ny, t("Y-Komponente Normalenvektor?", "Y component of normal vector?")),
    vec_field(Word::Nz, t("Z-Komponente Normalenvektor?", "Z component of normal vector?")),
];

const fn point_field(word: Word, prompt: Text) -> Field {
    field(
        word,
        prompt,
        t(
            "P1→P2 gibt die geschwenkte X-Achse, P3 die Seite der Y-Achse. Der Nullpunkt wird nicht verschoben.",
            "P1→P2 gives the tilted X axis, P3 the side of Y. The datum is not moved.",
        ),
    )
}

pub(super) static POINTS: [Field; 9] = [
    point_field(Word::P1x, t("X-Koordinate 1. Ebenenpunkt?", "X coordinate 1st plane point?")),
    point_field(Word::P1y, t("Y-Koordinate 1. Ebenenpunkt?", "Y coordinate 1st plane point?")),
    point_field(Word::P1z, t("Z-Koordinate 1. Ebenenpunkt?", "Z coordinate 1st plane point?")),
    point_field(Word::P2x, t("X-Koordinate 2. Ebenenpunkt?", "X coordinate 2nd plane point?")),
    point_field(Word::P2y, t("Y-Koordinate 2. Ebenenpunkt?", "Y coordinate 2nd plane point?")),
    point_field(Word::P2z, t("Z-Koordinate 2. Ebenenpunkt?", "Z coordinate 2nd plane point?")),
    point_field(Word::P3x, t("X-Koordinate 3. Ebenenpunkt?", "X coordinate 3rd plane point?")),
    point_field(Word::P3y, t("Y-Koordinate 3. Ebenenpunkt?", "Y coordinate 3rd plane point?")),
    point_field(Word::P3z, t("Z-Koordinate 3. Ebenenpunkt?", "Z coordinate 3rd plane point?")),
];

pub(super) static RELATIV: [Field; 1] = [field(
    Word::Spa,
    t("Inkrementaler Raumwinkel?", "Incremental spatial angle?"),
    t(
        "Dreht um die Achse der aktiven geschwenkten Ebene; mehrere RELATIV-Sätze bauen aufeinander auf.",
        "Rotates about the axis of the active tilted plane; several RELATIV blocks build on each other.",
    ),
)];

const fn axial_field(word: Word, prompt: Text) -> Field {
    Field {
        word,
        prompt,
        help: t(
            "Achswinkel der Maschine direkt; nur vorhandene Achsen. NO ENT überspringt die Achse.",
            "Machine axis angle directly; existing axes only. NO ENT skips the axis.",
        ),
        required: false,
        confirmed: false,
    }
}

pub(super) static AXIAL: [Field; 3] = [
    axial_field(Word::A, t("Achswinkel A?", "Axis angle A?")),
    axial_field(Word::B, t("Achswinkel B?", "Axis angle B?")),
    axial_field(Word::C, t("Achswinkel C?", "Axis angle C?")),
];
