//! The decisions of [`super`] as the UI and the explanation cite them: a stable id and what the
//! trainer assumes, in German and English.

use serde::Serialize;

use crate::lang::Text;

/// A decision made here, as the UI and the explanation record cite it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Decision {
    /// [`projected_traces`](super::projected_traces): sign of PROPR/PROMIN.
    ProjectedSign,
    /// [`vector_frame`](super::vector_frame): keep N, correct B.
    VectorGramSchmidt,
    /// [`RELATIV_UNTILTED_REFERENCE`](super::RELATIV_UNTILTED_REFERENCE): RELATIV without an active tilt starts from the W-CS.
    RelativUntilted,
    /// [`path_length`](super::path_length): sum of the axis travels.
    PathMetric,
    /// [`tie_prefers`](super::tie_prefers): equal paths → larger master value.
    TieRule,
    /// [`coord_rot_free_axis`](super::coord_rot_free_axis): COORD ROT leaves the free axis where it is.
    CoordRotFreeAxis,
    /// [`TABLE_ROT_SIGN`](super::TABLE_ROT_SIGN): TABLE ROT turns the free table axis by +γ.
    TableRotSign,
    /// [`TABLE_ROT_ON_HEAD_AXIS`](super::TABLE_ROT_ON_HEAD_AXIS): TABLE ROT with a free head axis acts like COORD ROT.
    TableRotHeadAxis,
    /// [`DEFAULT_TABLE_ROT`](super::DEFAULT_TABLE_ROT): neither COORD ROT nor TABLE ROT programmed.
    DefaultTransform,
    /// [`ZERO_COUNTS_AS_PLUS`](super::ZERO_COUNTS_AS_PLUS): SEQ/SYM with the master exactly on the reference.
    ZeroIsPlus,
    /// [`SEQ_NEAREST_BEFORE_LIMITS`](super::SEQ_NEAREST_BEFORE_LIMITS): SEQ with both solutions on the requested side.
    SeqSameSide,
    /// [`SYMMETRY_POINT_CODIRECTIONAL`](super::SYMMETRY_POINT_CODIRECTIONAL): which of the two symmetry positions is "the" one.
    SymmetryPoint,
    /// [`PREFER_CANONICAL_VALUE`](super::PREFER_CANONICAL_VALUE): how a non-endless axis writes a solution.
    AxisRepresentation,
    /// [`AXIAL_MISSING_AXIS_KEEPS_POSITION`](super::AXIAL_MISSING_AXIS_KEEPS_POSITION).
    AxialMissingAxis,
    /// [`RESET_TARGET_DEG`](super::RESET_TARGET_DEG).
    ResetTarget,
    /// [`UNREACHABLE_IS_SEPARATE_ERROR`](super::UNREACHABLE_IS_SEPARATE_ERROR): German text of "Angle cannot be calculated".
    UnreachableMessage,
    /// [`EULPR_LIMIT`](super::EULPR_LIMIT), [`VECTOR_COMPONENT_LIMIT`](super::VECTOR_COMPONENT_LIMIT), [`POINTS_COORD_LIMIT`](super::POINTS_COORD_LIMIT), [`AXIAL_LIMIT`](super::AXIAL_LIMIT),
    /// [`POSITIONING_LENGTH_LIMIT`](super::POSITIONING_LENGTH_LIMIT); RELATIV uses
    /// the spatial range.
    InputRanges,
    /// Simulator: [`SIM_MESSAGES_UNCONFIRMED`](super::SIM_MESSAGES_UNCONFIRMED).
    SimMessages,
    /// Simulator: [`TRANSFORM_LEVELS`](super::TRANSFORM_LEVELS).
    TransformLevels,
    /// Simulator: [`COMPENSATION_ONLY_WHEN_TILTED`](super::COMPENSATION_ONLY_WHEN_TILTED).
    CompensationOnlyWhenTilted,
    /// Simulator: [`MOVE_DEFAULT_DIST`](super::MOVE_DEFAULT_DIST).
    MoveDefaultDist,
    /// Simulator: [`TCPM_FROM_BLOCK_START`](super::TCPM_FROM_BLOCK_START).
    TcpmTiming,
    /// Simulator: [`TCPM_REFUSES_TOOL_CALL_M91_M92`](super::TCPM_REFUSES_TOOL_CALL_M91_M92) and the `FUNCTION TCPM` modes the simulator
    /// does not tell apart (its text).
    TcpmFunction,
    /// Simulator: `FUNCTION TCPM … AXIS SPAT`, how spatial angles in a positioning block become
    /// axis positions (`sim::interp::tcpm`, its text).
    TcpmAxisSpat,
    /// Simulator: [`MB_RETRACT_AT_RAPID`](super::MB_RETRACT_AT_RAPID), [`MB_MAX_CLEARANCE`](super::MB_MAX_CLEARANCE).
    MbRetractRapid,
    /// Simulator: [`M140_FEED_AFTER_MB`](super::M140_FEED_AFTER_MB).
    M140Feed,
    /// Simulator: [`M92_AT_MACHINE_DATUM`](super::M92_AT_MACHINE_DATUM).
    M92Datum,
    /// Simulator: [`ROTARY_FEED_DEG_PER_MIN`](super::ROTARY_FEED_DEG_PER_MIN).
    RotaryFeed,
    /// Collision check: [`holder`](super::holder), the tool holder's size.
    /// Also [`ZERO_TOOL_DIFFERENCE_BELOW`](super::ZERO_TOOL_DIFFERENCE_BELOW), [`ZERO_TOOL_LENGTH`](super::ZERO_TOOL_LENGTH).
    ToolHolder,
    /// Simulator: [`CYCLE19_INPUT_SPATIAL`](super::CYCLE19_INPUT_SPATIAL).
    Cycle19Spatial,
    /// Simulator: [`CYCLE19_MOVES_AXES`](super::CYCLE19_MOVES_AXES).
    Cycle19NoMotion,
    /// Simulator: [`MAX_CALL_DEPTH`](super::MAX_CALL_DEPTH).
    CallDepth,
    /// Simulator: [`REP_IS_SECTION_REPEAT`](super::REP_IS_SECTION_REPEAT).
    RepSectionRepeat,
    /// Simulator: [`LIST_BLOCKS_AFTER_END`](super::LIST_BLOCKS_AFTER_END).
    ListAfterEnd,
    /// Simulator: [`CYCLE_POSITIVE_DEPTH_IS_ERROR`](super::CYCLE_POSITIVE_DEPTH_IS_ERROR).
    PositiveDepthError,
    /// Simulator: [`cycle232_stepover`](super::cycle232_stepover).
    Cycle232Stepover,
    /// Simulator: [`CYCLE232_STRATEGY`](super::CYCLE232_STRATEGY).
    Cycle232Strategy,
    /// Simulator: [`DATUM_ABSOLUTE_REPLACES`](super::DATUM_ABSOLUTE_REPLACES).
    DatumAbsoluteReplaces,
    /// Simulator: [`Q120_ONLY_FOR_SPATIAL_TILTS`](super::Q120_ONLY_FOR_SPATIAL_TILTS).
    Q120OnlySpatial,
    /// Simulator: the machining cycles' open points ([`decremented_infeed`](super::decremented_infeed),
    /// [`CHIP_BREAK_AT_RETRACTION_FEED`](super::CHIP_BREAK_AT_RETRACTION_FEED), [`advanced_stop_distance`](super::advanced_stop_distance),
    /// [`CYCLE205_Q208_ZERO_IS_Q206`](super::CYCLE205_Q208_ZERO_IS_Q206), [`BORE_MILL_STEPOVER`](super::BORE_MILL_STEPOVER), [`POCKET_HELIX`](super::POCKET_HELIX),
    /// [`POCKET_RECIPROCATING_AS_VERTICAL`](super::POCKET_RECIPROCATING_AS_VERTICAL), [`SLOT_STEPOVER`](super::SLOT_STEPOVER), [`CIRCULAR_SLOT_REFERENCE`](super::CIRCULAR_SLOT_REFERENCE),
    /// [`CYCLE233_AS_232`](super::CYCLE233_AS_232), [`CYCLE205_WITHOUT_Q208_FEED`](super::CYCLE205_WITHOUT_Q208_FEED)).
    CycleConventions,
    /// Simulator: the patterns and cycle calls ([`PATTERN_GRID_ORDER`](super::PATTERN_GRID_ORDER), [`cycle220_step`](super::cycle220_step),
    /// [`PATTERN_CYCLE_END`](super::PATTERN_CYCLE_END), [`CYCL_CALL_POS_CLEARANCE`](super::CYCL_CALL_POS_CLEARANCE), [`M89_CALLS_AT_ITS_BLOCK`](super::M89_CALLS_AT_ITS_BLOCK),
    /// [`CYCL_CALL_PAT_FEED_BETWEEN_POINTS`](super::CYCL_CALL_PAT_FEED_BETWEEN_POINTS)).
    PatternConventions,
    /// Reading programs written elsewhere: [`IMPORT_BLOCK_NUMBERS_ARE_WARNINGS`](super::IMPORT_BLOCK_NUMBERS_ARE_WARNINGS),
    /// [`IMPORT_LENIENT_SPELLINGS`](super::IMPORT_LENIENT_SPELLINGS),
    /// [`CYCLE_FMAX_FEED`](super::CYCLE_FMAX_FEED), [`predef`](super::predef),
    /// [`HEADER_BLANK_AT_DATUM`](super::HEADER_BLANK_AT_DATUM),
    /// [`INCH_FEED_MM_PER_MIN`](super::INCH_FEED_MM_PER_MIN), [`REP_FROM_PARAMETER`](super::REP_FROM_PARAMETER),
    /// [`DATUM_ABOVE_TABLE`](super::DATUM_ABOVE_TABLE), [`TABREAD_ASSUMES_ZERO`](super::TABREAD_ASSUMES_ZERO),
    /// [`END_PGM_NAME_IS_BOOKKEEPING`](super::END_PGM_NAME_IS_BOOKKEEPING),
    /// [`CYCLE_PARAMS_FROM_GLOBAL_Q`](super::CYCLE_PARAMS_FROM_GLOBAL_Q).
    ImportReadings,
    /// Simulator: [`ARC_DIRECTION_WITHOUT_DR`](super::ARC_DIRECTION_WITHOUT_DR), [`CIRCLE_END_TOLERANCE`](super::CIRCLE_END_TOLERANCE),
    /// [`ARC_TOOL_AXIS_LINEAR`](super::ARC_TOOL_AXIS_LINEAR), [`CP_IPA_DIRECTION_FROM_DR`](super::CP_IPA_DIRECTION_FROM_DR),
    /// [`ARC_PLANE_OF_CC`](super::ARC_PLANE_OF_CC).
    ArcConventions,
    /// Simulator: [`COMP_CORNER_ARC_WITH_NEXT_BLOCK`](super::COMP_CORNER_ARC_WITH_NEXT_BLOCK), [`APPR_DEP_RADIUS_OF_CENTRE_PATH`](super::APPR_DEP_RADIUS_OF_CENTRE_PATH) and the
    /// conventions of the radius compensation and APPR/DEP the manuals do not state (its text).
    CompensationConventions,
    /// The dialog's German wording where no manual gives it (DOMAIN.md §7): the prompts of
    /// SPATIAL, PROJECTED, POINTS, RELATIV, AXIAL, DIST, MB and the positioning step, and the
    /// softkey labels other than SPATIAL/RESET. Confirmed, from the iTNC 530 German user
    /// manual: the EULER and VECTOR prompts.
    DialogWording,
}

impl Decision {
    /// Every decision, for a UI list "what this trainer assumes".
    pub const ALL: [Decision; 45] = [
        Decision::ProjectedSign,
        Decision::VectorGramSchmidt,
        Decision::RelativUntilted,
        Decision::PathMetric,
        Decision::TieRule,
        Decision::CoordRotFreeAxis,
        Decision::TableRotSign,
        Decision::TableRotHeadAxis,
        Decision::DefaultTransform,
        Decision::ZeroIsPlus,
        Decision::SeqSameSide,
        Decision::SymmetryPoint,
        Decision::AxisRepresentation,
        Decision::AxialMissingAxis,
        Decision::ResetTarget,
        Decision::UnreachableMessage,
        Decision::InputRanges,
        Decision::SimMessages,
        Decision::TransformLevels,
        Decision::CompensationOnlyWhenTilted,
        Decision::MoveDefaultDist,
        Decision::TcpmTiming,
        Decision::TcpmFunction,
        Decision::TcpmAxisSpat,
        Decision::MbRetractRapid,
        Decision::M140Feed,
        Decision::M92Datum,
        Decision::RotaryFeed,
        Decision::Cycle19Spatial,
        Decision::Cycle19NoMotion,
        Decision::CallDepth,
        Decision::RepSectionRepeat,
        Decision::ListAfterEnd,
        Decision::PositiveDepthError,
        Decision::Cycle232Stepover,
        Decision::Cycle232Strategy,
        Decision::DatumAbsoluteReplaces,
        Decision::Q120OnlySpatial,
        Decision::ArcConventions,
        Decision::CycleConventions,
        Decision::ImportReadings,
        Decision::PatternConventions,
        Decision::CompensationConventions,
        Decision::DialogWording,
        Decision::ToolHolder,
    ];

    /// The text for the trainee.
    #[must_use]
    pub fn text(self) -> Text {
        match self {
            Decision::ProjectedSign => Text::new(
                "PROJECTED: Vorzeichen so gewählt, dass ein einzelner Winkel SPATIAL entspricht (PROPR ≙ SPB, PROMIN ≙ SPA).",
                "PROJECTED: sign chosen so that a single angle matches SPATIAL (PROPR ≙ SPB, PROMIN ≙ SPA).",
            ),
            Decision::VectorGramSchmidt => Text::new(
                "VECTOR: Normalenvektor N bleibt, der Basisvektor B wird senkrecht dazu korrigiert.",
                "VECTOR: the normal vector N is kept, the base vector B is made perpendicular to it.",
            ),
            Decision::RelativUntilted => Text::new(
                "PLANE RELATIV ohne aktive Schwenkung bezieht sich auf das ungeschwenkte W-CS.",
                "PLANE RELATIV without an active tilt refers to the untilted W-CS.",
            ),
            Decision::PathMetric => Text::new(
                "Weglänge = Summe der Verfahrwege aller Drehachsen (Endlosachsen auf kurzem Weg).",
                "Path length = sum of the travel of all rotary axes (endless axes the short way round).",
            ),
            Decision::TieRule => Text::new(
                "Gleich lange Wege: die Lösung mit dem größeren Wert der Master-Achse.",
                "Equal paths: the solution with the larger master axis value.",
            ),
            Decision::CoordRotFreeAxis => Text::new(
                "COORD ROT: die freie Drehachse bleibt auf ihrer aktuellen Position.",
                "COORD ROT: the free rotary axis stays at its current position.",
            ),
            Decision::TableRotSign => Text::new(
                "TABLE ROT: die freie Tischachse dreht um +γ (SPC+45 → C+45).",
                "TABLE ROT: the free table axis turns by +γ (SPC+45 → C+45).",
            ),
            Decision::TableRotHeadAxis => Text::new(
                "TABLE ROT wirkt nur auf eine freie Tischachse; eine freie Kopfachse bleibt stehen.",
                "TABLE ROT acts on a free table axis only; a free head axis stays where it is.",
            ),
            Decision::DefaultTransform => Text::new(
                "Ohne COORD ROT/TABLE ROT rechnet die Steuerung wie mit COORD ROT.",
                "Without COORD ROT/TABLE ROT the control computes as with COORD ROT.",
            ),
            Decision::ZeroIsPlus => Text::new(
                "SEQ/SYM: Master-Achse genau auf dem Bezug (0° bzw. Symmetriepunkt) zählt als positiv.",
                "SEQ/SYM: a master axis exactly on the reference (0° or symmetry point) counts as positive.",
            ),
            Decision::SeqSameSide => Text::new(
                "SEQ mit beiden Lösungen auf der gewählten Seite: erst die nähere Lösung, dann die Endschalterprüfung.",
                "SEQ with both solutions on the requested side: the nearer one first, then the limit check.",
            ),
            Decision::SymmetryPoint => Text::new(
                "Symmetriepunkt: die Stellung der Master-Achse, in der die Werkzeugachse in +Richtung der Slave-Achse zeigt.",
                "Symmetry point: the master position where the tool axis points along +slave axis direction.",
            ),
            Decision::AxisRepresentation => Text::new(
                "Achswert einer begrenzten Achse: zuerst im Bereich −180…+180°, sonst ±360° innerhalb der Endschalter.",
                "Value of a limited axis: within −180…+180° first, else ±360° inside the limit switches.",
            ),
            Decision::AxialMissingAxis => Text::new(
                "PLANE AXIAL: nicht programmierte Drehachsen bleiben auf ihrer aktuellen Position.",
                "PLANE AXIAL: rotary axes not programmed stay at their current position.",
            ),
            Decision::ResetTarget => Text::new(
                "PLANE RESET MOVE/TURN fährt alle Drehachsen auf 0°.",
                "PLANE RESET MOVE/TURN moves every rotary axis to 0°.",
            ),
            Decision::UnreachableMessage => Text::new(
                "Werkzeugachse mit der Kinematik nicht erreichbar: eigene Meldung „Winkel nicht berechenbar“.",
                "Tool axis not reachable by the kinematics: separate message \"Angle cannot be calculated\".",
            ),
            Decision::InputRanges => Text::new(
                "Eingabebereiche: EULPR −180…+180 wie angegeben (EULPR+270 aus dem Tipp wird abgewiesen), RELATIV wie SPATIAL ±359,9999, VECTOR ±99,9999999, POINTS und AXIAL ±99999,9999; DIST und MB 0…99999,9999 (nicht negativ).",
                "Input ranges: EULPR −180…+180 as stated (EULPR+270 from the tip is refused), RELATIV like SPATIAL ±359.9999, VECTOR ±99.9999999, POINTS and AXIAL ±99999.9999; DIST and MB 0…99999.9999 (not negative).",
            ),
            Decision::SimMessages => Text::new(
                "Meldungstexte des Simulators außer „Winkel nicht erlaubt“ (z. B. „Q-Parameter nicht definiert“, „Endschalter X+“) sind im Stil der Steuerung formuliert, nicht belegt.",
                "The simulator's messages other than \"Entered angle not permitted\" (e.g. \"Q parameter not defined\", \"Limit switch X+\") are worded in the control's style, not confirmed.",
            ),
            Decision::TransformLevels => Text::new(
                "Nullpunkt und Spiegelung vor dem Schwenken wirken im W-CS, danach im WPL-CS; Drehung immer im WPL-CS; Reihenfolge Verschiebung, Spiegelung, Drehung; RESET löscht beide Ebenen.",
                "Datum shift and mirror before the tilt act in the W-CS, after it in the WPL-CS; rotation always in the WPL-CS; order shift, mirror, rotation; RESET clears both levels.",
            ),
            Decision::CompensationOnlyWhenTilted => Text::new(
                "Ohne aktive Schwenkung ignoriert die Steuerung die Stellung der Drehachsen (3-Achs-Verhalten), auch nach PLANE RESET STAY.",
                "Without an active tilt the control ignores the rotary axis positions (3-axis behaviour), also after PLANE RESET STAY.",
            ),
            Decision::MoveDefaultDist => Text::new(
                "MOVE ohne DIST: Drehpunkt = Werkzeugspitze (DIST 0), die Spitze bleibt auf dem Werkstück stehen.",
                "MOVE without DIST: centre of rotation = tool tip (DIST 0), the tip stays on the workpiece.",
            ),
            Decision::TcpmTiming => Text::new(
                "M128 wirkt ab Satzanfang (eine Drehachsbewegung im selben Satz wird schon ausgeglichen), M129 am Satzende; TCPM gleicht auch ohne Schwenkung aus, die Werkzeugspitze fährt geradlinig zwischen den programmierten Punkten.",
                "M128 acts from the start of its block (a rotary move in the same block is already compensated), M129 at its end; TCPM compensates with or without a tilt, the tool tip runs straight between programmed points.",
            ),
            Decision::TcpmFunction => Text::new(
                "TOOL CALL, M91 und M92 bei aktivem TCPM sind ein Fehler (das Handbuch verlangt, TCPM vorher zurückzusetzen). FUNCTION RESET TCPM und M129 schalten jedes TCPM aus. PATHCTRL VECTOR wird wie PATHCTRL AXIS simuliert (gleiche Werkzeugspitze, nur die Zwischenstellungen der Werkzeugachse weichen ab); F TCP und F CONT werden nicht unterschieden (nur die Animationsdauer hinge davon ab).",
                "TOOL CALL, M91 and M92 with TCPM active are an error (the manual has TCPM reset before them). FUNCTION RESET TCPM and M129 switch off either kind of TCPM. PATHCTRL VECTOR is simulated as PATHCTRL AXIS (the same tool tip, only the tool axis' intermediate orientations differ); F TCP and F CONT are not told apart (only the animation time would depend on them).",
            ),
            Decision::TcpmAxisSpat => Text::new(
                "FUNCTION TCPM mit AXIS SPAT: A, B, C im Positioniersatz sind die Raumwinkel SPA, SPB, SPC bezogen auf das aktive (ggf. geschwenkte) Koordinatensystem, selbsthaltend; nicht programmierte gelten bis zu ihrer ersten Programmierung als 0° (mit Hinweis). Die Drehachsstellung wählt der Simulator wie bei PLANE ohne SEQ (innerhalb der Endschalter, kürzester Weg); die Werkzeugspitze bleibt auf dem programmierten Punkt.",
                "FUNCTION TCPM with AXIS SPAT: A, B, C in a positioning block are the spatial angles SPA, SPB, SPC relative to the active (possibly tilted) coordinate system, modal; unprogrammed ones count as 0° until first programmed (with a note). The simulator chooses the rotary axis positions as for PLANE without SEQ (within the limit switches, shortest path); the tool tip stays on the programmed point.",
            ),
            Decision::MbRetractRapid => Text::new(
                "MB/MB MAX: Rückzug im Eilgang vor dem Schwenken; MB MAX endet 1 mm vor dem Software-Endschalter jeder Linearachse.",
                "MB/MB MAX: retract at rapid traverse before the swivel; MB MAX ends 1 mm before each linear axis's software limit switch.",
            ),
            Decision::M140Feed => Text::new(
                "M140 MB … F: der Vorschub nach MB gilt als Rückzugsvorschub (ohne F Eilgang).",
                "M140 MB … F: the feed after MB is taken as the retraction's feed (without F rapid).",
            ),
            Decision::M92Datum => Text::new(
                "M92: der zusätzliche Maschinen-Nullpunkt des Herstellers wird auf dem Maschinen-Nullpunkt angenommen (M92 wie M91).",
                "M92: the machine tool builder's additional machine datum is taken at the machine datum (M92 as M91).",
            ),
            Decision::ToolHolder => Text::new(
                "Kollisionsprüfung: Werkzeughalter als Zylinder unter der Spindelnase, 35 % der Werkzeuglänge lang (höchstens 50 mm), Radius = Werkzeugradius (mindestens 12 mm) + 14 mm; darunter das Werkzeug mit seinem Radius. Eine Werkzeuglänge L unter 30 mm gilt als Differenz zum Nullwerkzeug, simuliert mit 100 mm + L.",
                "Collision check: tool holder as a cylinder below the spindle nose, 35 % of the tool length long (at most 50 mm), radius = tool radius (at least 12 mm) + 14 mm; below it the tool with its radius. A tool length L under 30 mm counts as the difference to a zero tool, simulated as 100 mm + L.",
            ),
            Decision::RotaryFeed => Text::new(
                "Vorschub F beim Schwenken und bei Drehachsbewegungen als °/min; F AUTO = Vorschub aus dem TOOL CALL (nur für die Animationsdauer).",
                "Feed F of swivels and rotary moves in °/min; F AUTO = feed of the TOOL CALL (animation duration only).",
            ),
            Decision::Cycle19Spatial => Text::new(
                "Zyklus 19: Eingaben als Raumwinkel (OEM-Parameter planeOrientation).",
                "Cycle 19: inputs are spatial angles (OEM parameter planeOrientation).",
            ),
            Decision::Cycle19NoMotion => Text::new(
                "Zyklus 19 fährt die Drehachsen nicht selbst; das Programm positioniert sie (L A+Q120 …). Alle Winkel 0 setzt zurück.",
                "Cycle 19 does not move the rotary axes itself; the program positions them (L A+Q120 …). All angles 0 resets.",
            ),
            Decision::CallDepth => Text::new(
                "Unterprogramme höchstens 19-fach verschachtelt.",
                "Subprograms nested at most 19 deep.",
            ),
            Decision::RepSectionRepeat => Text::new(
                "CALL LBL n REP m wiederholt den Abschnitt ab LBL n m-mal (m+1 Durchläufe); ohne REP Unterprogramm bis LBL 0.",
                "CALL LBL n REP m repeats the section from LBL n m times (m+1 passes); without REP a subprogram up to LBL 0.",
            ),
            Decision::ListAfterEnd => Text::new(
                "Sätze nach M30/M2 werden als „nicht ausgeführt“ aufgelistet.",
                "Blocks after M30/M2 are listed as \"not executed\".",
            ),
            Decision::PositiveDepthError => Text::new(
                "Bearbeitungszyklen mit positiver Tiefe Q201: Fehlermeldung (Maschinenparameter displayDepthErr).",
                "Machining cycles with a positive depth Q201: error message (machine parameter displayDepthErr).",
            ),
            Decision::Cycle232Stepover => Text::new(
                "Zyklus 232: maximale seitliche Zustellung = Q370 × Werkzeugradius.",
                "Cycle 232: maximum stepover = Q370 × tool radius.",
            ),
            Decision::Cycle232Strategy => Text::new(
                "Zyklus 232: Strategien Q389=1 und 2 werden als Mäander simuliert.",
                "Cycle 232: strategies Q389=1 and 2 are simulated as a meander.",
            ),
            Decision::DatumAbsoluteReplaces => Text::new(
                "Nullpunktverschiebung mit absoluten Werten ersetzt die ganze Verschiebung (nicht programmierte Achsen 0); nur inkrementale Werte addieren.",
                "A datum shift with absolute values replaces the whole shift (axes not written 0); only incremental values add.",
            ),
            Decision::Q120OnlySpatial => Text::new(
                "Q120–Q122 werden von Schwenkungen mit Raumwinkeln geschrieben, nicht von PLANE AXIAL und PLANE RESET.",
                "Q120–Q122 are written by tilts with spatial angles, not by PLANE AXIAL and PLANE RESET.",
            ),
            Decision::ArcConventions => Text::new(
                "Kreisbahnen: ohne DR gilt die zuletzt programmierte Drehrichtung (vor dem ersten DR: DR+); der Endpunkt von C darf 0,01 mm neben dem Kreis liegen; eine Werkzeugachs-Koordinate in C/CR/CT fährt linear mit (wie eine Helix); bei CP mit IPA und DR bestimmt DR die Richtung; CC mit den zwei Achsen einer anderen Hauptebene (CC X… Z…) legt C, CP und LP in diese Ebene (Bezugsachse und DR+ wie bei dieser Werkzeugachse), dort ohne Radiuskorrektur.",
                "Arcs: without DR the last programmed direction applies (before the first DR: DR+); the end point of C may be 0.01 mm off the circle; a tool-axis coordinate in C/CR/CT moves linearly along (like a helix); CP with IPA and DR: DR gives the direction; CC with the two axes of another main plane (CC X… Z…) puts C, CP and LP in that plane (reference axis and DR+ as for that tool axis), without radius compensation there.",
            ),
            Decision::CycleConventions => Text::new(
                "Bearbeitungszyklen: Abnahmebetrag Q212 bis zur Mindest-Zustelltiefe Q205, danach der Rest in einem Schritt; Spanbruch-Rückzug Q256 mit dem Rückzugsvorschub Q208; Zyklus 205: Vorhalteabstand von Q258 nach Q259 linear mit der erreichten Tiefe, Q208 = 0 fährt mit Q206 zurück, ohne Q208 (ältere Software) im Eilgang; Zyklus 208 mit Vorbohrung: Zustellung höchstens ein Werkzeugradius je Helix; Taschen und Nuten: konzentrische Bahnen von innen nach außen, gerade An- und Abfahrt, Helix mit Werkzeugradius und einer Umdrehung je Zustellung, pendelndes Eintauchen (Q366 = 2) senkrecht, Nuten 253/254 mit einem Werkzeugradius seitlicher Zustellung; 254 mit Q367 = 1/2/3: Werkzeug am Anfang/in der Mitte/am Ende der Mittellinie; 233 als Mäander wie 232.",
                "Machining cycles: the decrement Q212 down to the minimum infeed Q205, then the rest in one step; chip-breaking retraction Q256 at the retraction feed Q208; cycle 205: advanced stop distance from Q258 to Q259 linear in the depth reached, Q208 = 0 retracts at Q206, without Q208 (older software) at rapid; cycle 208 with a pre-drilled hole: at most one tool radius more per helix; pockets and slots: concentric paths from the inside out, straight approach and departure, a helix of the tool radius with one turn per infeed, reciprocating plunge (Q366 = 2) vertical, slots 253/254 step over by one tool radius; 254 with Q367 = 1/2/3: the tool at the start/middle/end of the centre line; 233 as a meander like 232.",
            ),
            Decision::PatternConventions => Text::new(
                "Muster und Zyklusaufrufe: PATTERN DEF PAT/FRAME Zeile für Zeile, jede zweite rückwärts (wie Zyklus 221); Zyklus 220 mit Q247 = 0: Vollkreis in Q241 gleiche Schritte, sonst Start- und Endwinkel eingeschlossen; nach dem letzten Punkt von 220/221 auf den 2. Sicherheitsabstand; CYCL CALL POS unterhalb der Oberfläche: zuerst auf den 2. Sicherheitsabstand; M89 ruft den Zyklus schon in seinem eigenen Satz auf; der Vorschub von CYCL CALL PAT gilt zwischen den Punkten.",
                "Patterns and cycle calls: PATTERN DEF PAT/FRAME row by row, every other row backwards (like cycle 221); cycle 220 with Q247 = 0: a full circle in Q241 equal steps, otherwise start and stop angle both included; after the last point of 220/221 to the 2nd set-up clearance; CYCL CALL POS below the surface: first to the 2nd set-up clearance; M89 calls the cycle already in its own block; the feed of CYCL CALL PAT applies between the points.",
            ),
            Decision::ImportReadings => Text::new(
                "Programme von anderswo: fehlende, doppelte, nicht aufsteigende oder mit N geschriebene Satznummern und ein Kommentar ohne Leerzeichen nach der Nummer (12;) sind ein Hinweis je Datei, die Sätze laufen in ihrer Reihenfolge; Dezimalkomma und Leerzeichen nach dem Adressbuchstaben werden gelesen (ein Hinweis je Datei); Zyklusparameter FMAX (auch MAX geschrieben) fahren mit 99999 mm/min; PREDEF nimmt angenommene Werte der globalen Programmeinstellungen (Q200 2, Q204 50, Q253 750, Q208 FMAX, Q256 0,2, Q210/Q211 0, Q370 1, Q351 +1, Q366 1), ein Zyklus 208 ohne Q351 (ältere Software) fräst ebenso im Gleichlauf; das Rohteil eines Einrichteblatts (Quader: QX QY QZ) gilt ohne BLK FORM, in mm, mit dem Nullpunkt auf der Oberseite an der Ecke kleinster X und Y; INCH-Programme: Längen in Zoll, F in 1/10 inch/min, Drehachsanteil in °/min; REP Q… nimmt die Anzahl Wiederholungen aus dem Parameter; auf einer Maschine mit Tischmitte steht das Rohteil mittig auf dem Tisch, ohne in Zahlen geschriebenes Rohteil liegt der Nullpunkt 50 mm über der Tischmitte; FN 28: TABREAD einer Tabelle, die die Simulation nicht hat, setzt Parameter ohne Wert auf 0; ein anderer Name in END PGM als in BEGIN PGM ist ein Hinweis; ein Zyklus ohne Parameterzeilen (CYCL DEF 200, dann Q201 = … als eigene Sätze) nimmt beim Aufruf die Q-Parameter Q200 … wie dann gesetzt.",
                "Programs from elsewhere: missing, repeated, non-ascending or N-prefixed block numbers and a comment without a blank after the number (12;) are one note per file, the blocks run in their order; a decimal comma and a blank after the address letter are read (one note per file); cycle parameters FMAX (also written MAX) move at 99999 mm/min; PREDEF takes assumed values of the global program settings (Q200 2, Q204 50, Q253 750, Q208 FMAX, Q256 0.2, Q210/Q211 0, Q370 1, Q351 +1, Q366 1), a cycle 208 without Q351 (older software) climb-mills as well; a setup sheet's blank (cuboid: QX QY QZ) applies without a BLK FORM, in mm, with the datum on the top face at the corner of smallest X and Y; INCH programs: lengths in inches, F in 1/10 inch/min, the rotary share in °/min; REP Q… takes the number of repeats from the parameter; on a machine with a table centre the blank sits centred on the table, and without a blank written in numbers the datum is 50 mm above the table's centre; FN 28: TABREAD of a table the simulation does not have sets parameters without a value to 0; another name in END PGM than in BEGIN PGM is a note; a cycle without parameter lines (CYCL DEF 200, then Q201 = … as blocks of their own) takes the Q parameters Q200 … as set at its call.",
            ),
            Decision::CompensationConventions => Text::new(
                "Radiuskorrektur: der Übergangskreis an einer Außenecke gehört zum Satz nach der Ecke; RL/RR in einem Kreissatz fährt geradlinig senkrecht vor den Konturanfang; R0 in einem Kreissatz fährt geradlinig zum Kreisanfang; ein Satz, der das Werkzeug anders bewegt (Zyklus, M91, Drehachse, TOOL CALL, Transformation), beendet die Korrektur; RL↔RR ohne R0 ist ein Fehler. APPR/DEP: ohne RL/RR ein Fehler; R bei CT/LCT ist der Radius der Werkzeugmittelpunktsbahn; APPR fährt die Werkzeugachse auf der Geraden zum Hilfspunkt; DEP CT dreht wie APPR CT (RL mit R+ gegen den Uhrzeigersinn); alle Teilbahnen mit dem F des Satzes.",
                "Radius compensation: the transition arc at an outside corner belongs to the block after the corner; RL/RR in an arc block moves straight to the point perpendicular to the start of the contour; R0 in an arc block moves straight to the arc's start; a block moving the tool otherwise (cycle, M91, rotary axis, TOOL CALL, transformation) ends the compensation; RL↔RR without R0 is an error. APPR/DEP: without RL/RR an error; R of CT/LCT is the radius of the tool centre path; APPR moves the tool axis on the line to the auxiliary point; DEP CT turns like APPR CT (RL with R+ counter-clockwise); every piece at the block's F.",
            ),
            Decision::DialogWording => Text::new(
                "Wortlaut der Dialogfrage nicht aus einem Handbuch (bestätigt sind nur EULER und VECTOR).",
                "The German wording of this prompt is not from a manual (only EULER and VECTOR are confirmed).",
            ),
        }
    }
}
