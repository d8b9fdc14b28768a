//! The words of the eleven lessons, German first, then English. Facts from the seed chapters
//! (`../shared/seeds/`) and DOMAIN.md; what each lesson shows and asks is in `super::lessons`.

use crate::i18n::Text;

/// The words of one lesson.
pub struct LessonText {
    /// URL name, lowercase ASCII, e.g. "raumwinkel".
    pub slug: &'static str,
    pub title: Text,
    /// One sentence: what the trainee can do after this lesson.
    pub goal: Text,
    /// 2–5 short paragraphs (each 1–4 sentences).
    pub paragraphs: &'static [Text],
    /// Numbered steps to follow in the live view (empty `&[]` when the lesson has none).
    pub steps: &'static [Text],
    /// One line next to the live view: what to do with it.
    pub widget_caption: Text,
    /// The one sentence to remember ("Merksatz").
    pub summary: Text,
}

pub static LESSONS: [LessonText; 11] = [
    // 1 — seed 000 §2.1, §2.3.2; DOMAIN.md §2.1. Axis values: l01_raumwinkel.h block 7.
    LessonText {
        slug: "raumwinkel",
        title: Text::new("Raumwinkel", "Spatial angles"),
        goal: Text::new(
            "Sie wissen, was SPA, SPB und SPC beschreiben und warum sie nicht von den Achsen Ihrer Maschine abhängen.",
            "You know what SPA, SPB and SPC describe and why they do not depend on your machine's axes.",
        ),
        paragraphs: &[
            Text::new(
                "Raumwinkel beschreiben die Lage der Bearbeitungsebene durch Drehungen um die festen, nicht mitgedrehten Achsen: SPA dreht um X, SPB um Y, SPC um Z. Die Steuerung dreht immer in dieser Reihenfolge: erst A, dann B, dann C.",
                "Spatial angles describe the working plane by rotations about the fixed axes, which do not turn with it: SPA about X, SPB about Y, SPC about Z. The control always rotates in this order: first A, then B, then C.",
            ),
            Text::new(
                "Sie geben immer alle drei Winkel ein, auch wenn einer 0 ist. Schon zwei Raumwinkel legen jede Werkzeuglage im Raum eindeutig fest.",
                "You always enter all three angles, even when one is 0. Two spatial angles are already enough to fix any tool direction in space.",
            ),
            Text::new(
                "Raumwinkel hängen nicht von den Drehachsen ab, die Ihre Maschine hat. Deshalb lesen Sie sie meist direkt aus der Zeichnung ab. Die Steuerung rechnet sie selbst in Achswinkel um, also in die Stellungen der Drehachsen.",
                "Spatial angles do not depend on the rotary axes your machine has, so you can usually read them straight off the drawing. The control converts them into axis angles, the positions of the rotary axes, by itself.",
            ),
            Text::new(
                "Beispiel: PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX. Auf dem A/C-Tisch fährt der Trainer A+30 C+90, auf der Maschine mit B-Kopf und C-Tisch B+30 C+0.",
                "Example: PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX. On the A/C table the trainer moves to A+30 C+90, on the machine with a B head and C table to B+30 C+0.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Wechseln Sie die Maschine (A/C-Tisch oder B-Kopf/C-Tisch) und vergleichen Sie die Achswerte nach dem PLANE-Satz.",
            "Switch the machine (A/C table or B head/C table) and compare the axis values after the PLANE block.",
        ),
        summary: Text::new(
            "Raumwinkel beschreiben die Ebene, nicht die Maschine – die Achswerte rechnet die Steuerung.",
            "Spatial angles describe the plane, not the machine – the control works out the axis values.",
        ),
    },
    // 2 — seed 000 §2.2; DOMAIN.md §2 (sign rule).
    LessonText {
        slug: "drehrichtung",
        title: Text::new("Drehrichtung", "Direction of rotation"),
        goal: Text::new(
            "Sie bestimmen das Vorzeichen eines Raumwinkels mit der Rechte-Hand-Regel.",
            "You find the sign of a spatial angle with the right-hand rule.",
        ),
        paragraphs: &[
            Text::new(
                "Halten Sie die rechte Hand so, dass der Daumen in die positive Richtung der Achse zeigt, um die gedreht wird. Die gekrümmten Finger zeigen die positive Drehrichtung.",
                "Hold your right hand so that the thumb points in the positive direction of the axis you rotate about. The curled fingers show the positive direction of rotation.",
            ),
            Text::new(
                "Bewegen Sie dann den Handrücken von der ungeschwenkten zur geschwenkten Ebene. Geht die Bewegung in Richtung der Fingerspitzen, ist der Raumwinkel positiv, sonst negativ.",
                "Then move the back of your hand from the untilted plane to the tilted one. If it moves towards the fingertips, the spatial angle is positive, otherwise negative.",
            ),
            Text::new(
                "So kippt SPB+15 die Werkzeugachse von +Z nach +X, SPB-15 nach -X. SPA+ kippt sie nach -Y, SPC+ dreht die X-Achse in Richtung +Y.",
                "So SPB+15 tips the tool axis from +Z towards +X, SPB-15 towards -X. SPA+ tips it towards -Y, SPC+ turns the X axis towards +Y.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Wählen Sie X, Y oder Z und drehen Sie die Ebene – der PLANE-SPATIAL-Satz läuft mit. Im Übungsmodus bestimmen Sie das Vorzeichen selbst.",
            "Pick X, Y or Z and turn the plane – the PLANE SPATIAL block follows. In try-it mode you work out the sign yourself.",
        ),
        summary: Text::new(
            "Daumen in die positive Achsrichtung – die Finger zeigen die positive Drehrichtung.",
            "Thumb along the positive axis – the fingers show the positive direction.",
        ),
    },
    // 3 — seed 000 §2.3.1–2.3.3; dialog order as in `crate::dialog` (SPATIAL, keys in `crate::keymap`).
    // The steps enter variant 0 of its first exercise (Spec::DialogTurn: 25° towards +X).
    LessonText {
        slug: "spatial-eingeben",
        title: Text::new("PLANE SPATIAL eingeben", "Entering PLANE SPATIAL"),
        goal: Text::new(
            "Sie geben einen PLANE-SPATIAL-Satz über die Softkeys im Dialog ein.",
            "You enter a PLANE SPATIAL block with the softkeys in the dialog.",
        ),
        paragraphs: &[
            Text::new(
                "In der Betriebsart Programm-Einspeichern/Editieren: Taste SPEC FCT, Softkey BEARB.-EBENE SCHWENKEN, dann SPATIAL. Die Steuerung fragt SPA, SPB und SPC nacheinander ab, dann das Positionierverhalten und seine Werte.",
                "In programming mode: key SPEC FCT, softkey TILT MACHINING PLANE, then SPATIAL. The control asks for SPA, SPB and SPC in turn, then the positioning behaviour and its values.",
            ),
            Text::new(
                "SEQ/SYM und COORD ROT/TABLE ROT sind optional: NO ENT überspringt sie. Der neue Satz kommt hinter den Satz, auf dem der Cursor steht.",
                "SEQ/SYM and COORD ROT/TABLE ROT are optional: NO ENT skips them. The new block goes after the block the cursor is on.",
            ),
            Text::new(
                "Tastatur im Trainer: Enter = ENT, Umschalt+Enter = NO ENT, Ende = END, Esc = DEL (Abbruch), F1–F8 = Softkeys von links.",
                "Keyboard in the trainer: Enter = ENT, Shift+Enter = NO ENT, End = END, Esc = DEL (abort), F1–F8 = softkeys from the left.",
            ),
        ],
        steps: &[
            Text::new("Taste SPEC FCT (F1).", "Key SPEC FCT (F1)."),
            Text::new("Softkey BEARB.-EBENE SCHWENKEN (F3).", "Softkey TILT MACHINING PLANE (F3)."),
            Text::new("Softkey SPATIAL (F1).", "Softkey SPATIAL (F1)."),
            Text::new("SPA: 0 eingeben, ENT.", "SPA: type 0, ENT."),
            Text::new("SPB: 25 eingeben, ENT.", "SPB: type 25, ENT."),
            Text::new("SPC: 0 eingeben, ENT.", "SPC: type 0, ENT."),
            Text::new(
                "Positionierverhalten: Softkey TURN (F2).",
                "Positioning behaviour: softkey TURN (F2).",
            ),
            Text::new("MB (Rückzug): NO ENT – kein Rückzug.", "MB (retract): NO ENT – no retract."),
            Text::new("F: Softkey FMAX (F2).", "F: softkey FMAX (F2)."),
            Text::new("SEQ/SYM: NO ENT.", "SEQ/SYM: NO ENT."),
            Text::new(
                "COORD ROT/TABLE ROT: NO ENT oder END – im Programm steht PLANE SPATIAL SPA+0 SPB+25 SPC+0 TURN FMAX.",
                "COORD ROT/TABLE ROT: NO ENT or END – the program now holds PLANE SPATIAL SPA+0 SPB+25 SPC+0 TURN FMAX.",
            ),
        ],
        widget_caption: Text::new(
            "Geben Sie den Satz Schritt für Schritt am Bildschirm der Steuerung ein.",
            "Enter the block step by step on the control's screen.",
        ),
        summary: Text::new(
            "SPEC FCT → BEARB.-EBENE SCHWENKEN → SPATIAL, dann SPA, SPB, SPC und das Positionierverhalten.",
            "SPEC FCT → TILT MACHINING PLANE → SPATIAL, then SPA, SPB, SPC and the positioning behaviour.",
        ),
    },
    // 4 — seed 000 §2.3.3; DOMAIN.md §4. Programs static/course/l04_{move,turn,stay}.h, PLANE = block 8.
    LessonText {
        slug: "positionierverhalten",
        title: Text::new("MOVE, TURN und STAY", "MOVE, TURN and STAY"),
        goal: Text::new(
            "Sie wählen das passende Positionierverhalten und wissen, was sich dabei bewegt.",
            "You choose the right positioning behaviour and know what moves with it.",
        ),
        paragraphs: &[
            Text::new(
                "Nach den Winkeln legen Sie fest, wie die Drehachsen einschwenken. Die drei Ansichten zeigen denselben Satz PLANE SPATIAL SPA+0 SPB+45 SPC+0, nur mit MOVE, TURN oder STAY.",
                "After the angles you decide how the rotary axes swivel in. The three views show the same block PLANE SPATIAL SPA+0 SPB+45 SPC+0, once with MOVE, TURN and STAY.",
            ),
            Text::new(
                "MOVE: Die Linearachsen gleichen beim Schwenken aus, das Werkzeug schwenkt um einen festen Drehpunkt am Werkstück. DIST ist der Abstand vom Drehpunkt zur Werkzeugspitze, F der Bahnvorschub. Im Beispiel steht die Spitze vorher 50 mm über der Oberfläche; bei MOVE DIST50 F1000 liegt der Drehpunkt also auf ihr.",
                "MOVE: the linear axes compensate while swivelling, the tool swivels about a fixed centre of rotation on the workpiece. DIST is the distance from the centre of rotation to the tool tip, F the path feed. In the example the tip stands 50 mm above the surface first; with MOVE DIST50 F1000 the centre of rotation therefore lies on it.",
            ),
            Text::new(
                "TURN: Nur die Drehachsen bewegen sich, die Linearachsen bleiben stehen. Die Werkzeugspitze fährt dabei einen Bogen um die Drehachsen – je nach Maschine und Lage vom Werkstück weg oder auf es zu. Steht das Werkzeug nah am Werkstück oder noch im Material, kann es beim Schwenken hineinfahren: Kollisionsgefahr. Deshalb vorher freifahren – MB zieht in der Werkzeugachse um den Betrag zurück, MB MAX bis kurz vor den Software-Endschalter.",
                "TURN: only the rotary axes move, the linear axes stand still. The tool tip follows an arc about the rotary axes – away from the workpiece or towards it, depending on the machine and the position. A tool close to the workpiece or still in the material can swivel into it: danger of collision. So retract first – MB retracts along the tool axis by the value, MB MAX to just before the software limit switch.",
            ),
            Text::new(
                "STAY: Nur das Koordinatensystem wird geschwenkt, keine Achse fährt. Die Achswinkel stehen in Q120 bis Q122; Sie fahren sie selbst, z. B. mit L A+Q120 C+Q122 R0 FMAX.",
                "STAY: only the coordinate system is tilted, no axis moves. The axis angles are in Q120 to Q122; you move there yourself, e.g. with L A+Q120 C+Q122 R0 FMAX.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Spielen Sie in allen drei Ansichten Satz 8 ab und vergleichen Sie Werkzeugspitze und Drehachsen.",
            "Play block 8 in all three views and compare the tool tip and the rotary axes.",
        ),
        summary: Text::new(
            "MOVE schwenkt mit Ausgleich, TURN nur die Drehachsen, STAY nur das Koordinatensystem.",
            "MOVE swivels with compensation, TURN only the rotary axes, STAY only the coordinate system.",
        ),
    },
    // 5 — seed 002 (SYM/SEQ, both tables); DOMAIN.md §3.3; core/src/unconfirmed.rs (PathMetric, TieRule).
    LessonText {
        slug: "schwenkloesungen",
        title: Text::new("SEQ und SYM", "SEQ and SYM"),
        goal: Text::new(
            "Sie sagen voraus, welche der zwei Achsstellungen die Steuerung wählt, und erzwingen die andere.",
            "You predict which of the two axis positions the control chooses, and force the other one.",
        ),
        paragraphs: &[
            Text::new(
                "Mit zwei Drehachsen gibt es für eine Ebene meist zwei Lösungen, für SPB+45 auf dem A/C-Tisch A+45 C+90 und A-45 C-90. Die Master-Achse ist die erste Drehachse vom Werkzeug aus bzw. die letzte vom Tisch aus.",
                "With two rotary axes a plane usually has two solutions; for SPB+45 on the A/C table A+45 C+90 and A-45 C-90. The master axis is the first rotary axis seen from the tool, or the last seen from the table.",
            ),
            Text::new(
                "Ohne SEQ/SYM verwirft die Steuerung Lösungen hinter den Endschaltern. Bleiben zwei, nimmt sie die mit dem kürzesten Weg von der aktuellen Stellung; bleibt eine, nimmt sie diese; bleibt keine, meldet sie „Winkel nicht erlaubt“.",
                "Without SEQ/SYM the control drops solutions beyond the limit switches. If two are left, it takes the one with the shortest path from the current position; if one is left, that one; if none, it reports “Entered angle not permitted”.",
            ),
            Text::new(
                "SEQ+ und SEQ- legen die Master-Achse auf die positive oder negative Seite ihrer Grundstellung 0°, SYM+ und SYM- auf eine Seite ihres Symmetriepunkts. Liegt die gewählte Lösung hinter einem Endschalter, kommt ebenfalls „Winkel nicht erlaubt“.",
                "SEQ+ and SEQ- put the master axis on the positive or negative side of its home position 0°, SYM+ and SYM- on one side of its symmetry point. If the chosen solution lies beyond a limit switch, you also get “Entered angle not permitted”.",
            ),
            Text::new(
                "Annahmen des Trainers: Der Weg ist die Summe der Drehachswege; sind beide gleich lang (von A+0 C+0 aus), gewinnt der größere Wert der Master-Achse.",
                "The trainer's assumptions: the path is the sum of the rotary axis travels; if both are equally long (from A+0 C+0), the larger master axis value wins.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Stellen Sie Maschine, Endschalter, Startstellung und Option ein oder laden Sie eine Zeile aus den Handbuchtabellen.",
            "Set machine, limit switches, start position and option, or load a row of the manual's tables.",
        ),
        summary: Text::new(
            "Ohne Option gilt der kürzeste Weg; SEQ und SYM erzwingen eine Seite – notfalls mit „Winkel nicht erlaubt“.",
            "Without an option the shortest path wins; SEQ and SYM force a side – if need be with “Entered angle not permitted”.",
        ),
    },
    // 6 — seed 000 §2.3.3 (transformation types); DOMAIN.md §3.4, oracle 30; unconfirmed.rs
    // (TableRotSign, DefaultTransform). Programs static/course/l06_{table,coord}_rot.h, PLANE = block 6.
    LessonText {
        slug: "coord-table-rot",
        title: Text::new("COORD ROT und TABLE ROT", "COORD ROT and TABLE ROT"),
        goal: Text::new(
            "Sie wissen, wann COORD ROT und TABLE ROT wirken und was jeweils dreht.",
            "You know when COORD ROT and TABLE ROT matter and what turns with each.",
        ),
        paragraphs: &[
            Text::new(
                "Die beiden Eingaben wirken nur, wenn allein SPC ungleich 0 ist. Dann bleibt die Ebene waagrecht, auf dem A/C-Tisch bleibt A auf 0, und die Drehung um Z kann rechnerisch oder mit dem Rundtisch entstehen.",
                "The two options only matter when SPC alone is non-zero. The plane then stays horizontal, on the A/C table A stays at 0, and the turn about Z can be done mathematically or by the rotary table.",
            ),
            Text::new(
                "COORD ROT dreht das Koordinatensystem nur rechnerisch, der Tisch bleibt stehen. Für die Nut entlang der gedrehten X-Achse fahren X und Y gemeinsam.",
                "COORD ROT turns the coordinate system mathematically only; the table stays. For the slot along the turned X axis, X and Y move together.",
            ),
            Text::new(
                "TABLE ROT dreht die C-Achse; für die Nut fährt dann nur X. Dass SPC+30 dabei C+30 ergibt, ist eine Annahme des Trainers: Das Handbuch nennt das Vorzeichen nicht.",
                "TABLE ROT turns the C axis; the slot then needs X alone. That SPC+30 gives C+30 is the trainer's assumption: the manual does not state the sign.",
            ),
            Text::new(
                "Ohne beide Angaben rechnet der Trainer wie mit COORD ROT – ebenfalls eine Annahme.",
                "Without either option the trainer computes as with COORD ROT – also an assumption.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Spielen Sie das Programm ab, ändern Sie in Satz 6 TABLE ROT in COORD ROT und vergleichen Sie C und die Bewegung von X und Y bei der Nut.",
            "Play the program, change TABLE ROT to COORD ROT in block 6, and compare C and the movement of X and Y along the slot.",
        ),
        summary: Text::new(
            "COORD ROT dreht rechnerisch, TABLE ROT dreht den Tisch – beides nur, wenn allein SPC ungleich 0 ist.",
            "COORD ROT turns mathematically, TABLE ROT turns the table – both only when SPC alone is non-zero.",
        ),
    },
    // 7 — seed 000 §2.3.4; DOMAIN.md §2.8; unconfirmed.rs (ResetTarget, CompensationOnlyWhenTilted).
    // Program static/course/l07_reset.h: PLANE = block 7, PLANE RESET STAY = 13, L A+0 C+0 = 14.
    LessonText {
        slug: "plane-reset",
        title: Text::new("PLANE RESET", "PLANE RESET"),
        goal: Text::new(
            "Sie setzen eine Schwenkung zurück und bringen die Drehachsen sicher in die Grundstellung.",
            "You cancel a tilt and bring the rotary axes safely back to their home position.",
        ),
        paragraphs: &[
            Text::new(
                "PLANE RESET schaltet die aktive PLANE-Funktion ab: SPEC FCT → BEARB.-EBENE SCHWENKEN → RESET.",
                "PLANE RESET switches the active PLANE function off: SPEC FCT → TILT MACHINING PLANE → RESET.",
            ),
            Text::new(
                "Mit MOVE oder TURN schwenken die Drehachsen gleich mit zurück (im Trainer auf 0°, eine Annahme). PLANE RESET STAY setzt nur die Rechnung zurück: Die Drehachsen bleiben geschwenkt stehen.",
                "With MOVE or TURN the rotary axes swivel back at the same time (to 0° in the trainer, an assumption). PLANE RESET STAY only resets the calculation: the rotary axes stay tilted.",
            ),
            Text::new(
                "Nach PLANE RESET STAY fahren Sie das Werkzeug frei und die Achsen selbst zurück, z. B. mit L A+0 C+0 R0 FMAX. Bis dahin fährt der Trainer X, Y und Z, als stünde nichts schräg (Annahme).",
                "After PLANE RESET STAY you retract the tool and move the axes back yourself, e.g. with L A+0 C+0 R0 FMAX. Until then the trainer moves X, Y and Z as if nothing were tilted (assumption).",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Gehen Sie Satz für Satz: Nach Satz 13 (PLANE RESET STAY) stehen A und C noch schräg, erst Satz 14 fährt sie auf 0.",
            "Step block by block: after block 13 (PLANE RESET STAY) A and C are still tilted; only block 14 moves them to 0.",
        ),
        summary: Text::new(
            "PLANE RESET STAY löscht nur die Rechnung – die Drehachsen fahren Sie selbst zurück.",
            "PLANE RESET STAY only clears the calculation – you move the rotary axes back yourself.",
        ),
    },
    // 8 — seed 000 §2.3.5; static/programs/musterprogramm1.h on ac-table. Variant 0 of its
    // Spec::ProgramLean is block 10's plane (15° towards +X).
    LessonText {
        slug: "musterprogramm-1",
        title: Text::new("Musterprogramm 1", "Sample program 1"),
        goal: Text::new(
            "Sie lesen ein Programm mit Schwenkung Satz für Satz und wissen, was an jeder Stelle geschieht.",
            "You read a program with a tilt block by block and know what happens at each point.",
        ),
        paragraphs: &[
            Text::new(
                "Das Programm aus dem Handbuch planfräst und bohrt, beide Male in einer um 15° um Y geschwenkten Ebene. Das Handbuch lässt die Parameter der Zyklen 232 und 200 weg; die Kopie im Trainer ist damit ergänzt.",
                "The manual's program face-mills and drills, both times in a plane tilted 15° about Y. The manual leaves out the parameters of cycles 232 and 200; the trainer's copy has them filled in.",
            ),
            Text::new(
                "Für jedes Werkzeug gilt derselbe Ablauf: freifahren, einschwenken, bearbeiten, freifahren, zurückschwenken.",
                "Each tool follows the same pattern: retract, tilt, machine, retract, tilt back.",
            ),
        ],
        steps: &[
            Text::new(
                "Satz 7 und 8: Mit M91 fährt das Werkzeug auf sichere Maschinenpositionen, bevor etwas schwenkt.",
                "Blocks 7 and 8: with M91 the tool goes to safe machine positions before anything swivels.",
            ),
            Text::new(
                "Satz 10: PLANE SPATIAL … TURN FMAX – A fährt auf +15, C auf +90, die Linearachsen stehen.",
                "Block 10: PLANE SPATIAL … TURN FMAX – A moves to +15, C to +90, the linear axes stay.",
            ),
            Text::new(
                "Satz 12 und 13: Zyklus 232 wird definiert und mit M99 aufgerufen; gefräst wird in der geschwenkten Ebene.",
                "Blocks 12 and 13: cycle 232 is defined and called with M99; milling happens in the tilted plane.",
            ),
            Text::new(
                "Satz 15 bis 18: freifahren, dann PLANE RESET TURN FMAX – A und C fahren auf 0.",
                "Blocks 15 to 18: retract, then PLANE RESET TURN FMAX – A and C return to 0.",
            ),
            Text::new(
                "Satz 20 bis 33: dasselbe mit Werkzeug 8 und Zyklus 200; Satz 28 bohrt bei X+50 Y+50 der geschwenkten Ebene.",
                "Blocks 20 to 33: the same with tool 8 and cycle 200; block 28 drills at X+50 Y+50 of the tilted plane.",
            ),
        ],
        widget_caption: Text::new(
            "Spielen Sie das Programm auf der Maschine ac-table Satz für Satz ab und beobachten Sie A, C und das Werkzeug.",
            "Play the program on machine ac-table block by block and watch A, C and the tool.",
        ),
        summary: Text::new(
            "Freifahren, einschwenken, bearbeiten, freifahren, zurückschwenken.",
            "Retract, tilt, machine, retract, tilt back.",
        ),
    },
    // 9 — seed 000 ends after the title of §2.3.6; the program is ours: static/programs/musterprogramm2.h
    // (TRANS DATUM = block 10, PLANE = block 12, A+15 C+90 on ac-table). Pivot = datum: seed 001.
    LessonText {
        slug: "musterprogramm-2",
        title: Text::new("Musterprogramm 2", "Sample program 2"),
        goal: Text::new(
            "Sie verschieben den Nullpunkt vor dem Schwenken und wissen, was er für die Schwenkung bedeutet.",
            "You shift the datum before tilting and know what it means for the tilt.",
        ),
        paragraphs: &[
            Text::new(
                "Das Handbuch kündigt ein Musterprogramm 2 mit Nullpunktverschiebung an, bricht aber nach der Überschrift ab. Dieses Programm stammt daher vom Trainer.",
                "The manual announces a sample program 2 with a datum shift but stops after the heading. This program was therefore written for the trainer.",
            ),
            Text::new(
                "Satz 10 verschiebt mit TRANS DATUM AXIS X+50 Y+50 Z+0 den Nullpunkt in die Mitte der Oberseite. Weil das vor dem Schwenken geschieht, schwenkt die Ebene um diesen Punkt.",
                "Block 10 shifts the datum to the centre of the top face with TRANS DATUM AXIS X+50 Y+50 Z+0. Because this happens before the tilt, the plane tilts about this point.",
            ),
            Text::new(
                "Satz 12 schwenkt mit PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN MB MAX FMAX (A+15 C+90). Zyklus 200 bohrt bei X+0 und Y-25, Y+0, Y+25: Diese Punkte liegen auf der Y-Achse, die beim Schwenken um Y auf der Oberfläche bleibt.",
                "Block 12 tilts with PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN MB MAX FMAX (A+15 C+90). Cycle 200 drills at X+0 and Y-25, Y+0, Y+25: these points lie on the Y axis, which stays on the surface when tilting about Y.",
            ),
            Text::new(
                "Am Ende kommt zuerst PLANE RESET, dann TRANS DATUM RESET.",
                "At the end PLANE RESET comes first, then TRANS DATUM RESET.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Spielen Sie das Programm ab und achten Sie darauf, wo die drei schrägen Bohrungen entstehen.",
            "Play the program and watch where the three inclined holes are drilled.",
        ),
        summary: Text::new(
            "Der Nullpunkt, der vor dem Schwenken gilt, ist der Drehpunkt der Ebene.",
            "The datum active before the tilt is the point the plane tilts about.",
        ),
    },
    // 10 — seed 001 (PLANE EULER, chamfer tip, syntax table); unconfirmed.rs (InputRanges, EULPR_LIMIT);
    // static/programs/euler_fasen.h.
    LessonText {
        slug: "euler",
        title: Text::new("PLANE EULER", "PLANE EULER"),
        goal: Text::new(
            "Sie programmieren eine umlaufende Fase mit Eulerwinkeln.",
            "You program a chamfer all round with Euler angles.",
        ),
        paragraphs: &[
            Text::new(
                "PLANE EULER beschreibt die Ebene mit drei aufeinander aufbauenden Drehungen: EULPR (Präzession) um die ungeschwenkte Z-Achse, EULNU (Nutation) um die gedrehte X-Achse, EULROT (Rotation) um die neue Z-Achse. Alle drei Winkel sind Pflicht, auch wenn sie 0 sind.",
                "PLANE EULER describes the plane by three rotations that build on each other: EULPR (precession) about the untilted Z axis, EULNU (nutation) about the turned X axis, EULROT (rotation) about the new Z axis. All three angles are required, even when 0.",
            ),
            Text::new(
                "Für eine umlaufende 45°-Fase bleibt EULNU45 EULROT0, EULPR wechselt je Kante: +0, +90, +180, +270. Vor jeder Ebene verschieben Sie den Nullpunkt an die nächste Fasenkante.",
                "For a 45° chamfer all round, EULNU45 EULROT0 stays and EULPR changes per edge: +0, +90, +180, +270. Before each plane you shift the datum to the next chamfer edge.",
            ),
            Text::new(
                "Eingabebereiche laut Handbuch: EULPR -180 bis +180, EULNU 0 bis 180, EULROT 0 bis 360. Der Trainer hält sich daran und weist EULPR+270 mit „Winkel nicht erlaubt“ ab; wie die Steuerung 270 behandelt, ist offen. Dieselbe Lage ergibt EULPR-90.",
                "Input ranges in the manual: EULPR -180 to +180, EULNU 0 to 180, EULROT 0 to 360. The trainer keeps to them and refuses EULPR+270 with “Entered angle not permitted”; how the control treats 270 is open. EULPR-90 gives the same plane.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Spielen Sie die vier Fasen ab: EULNU bleibt 45, nur EULPR wechselt – die vierte mit EULPR-90.",
            "Play the four chamfers: EULNU stays 45, only EULPR changes – the fourth with EULPR-90.",
        ),
        summary: Text::new(
            "EULPR dreht um Z, EULNU kippt um die gedrehte X-Achse, EULROT dreht um die neue Z-Achse.",
            "EULPR turns about Z, EULNU tilts about the turned X axis, EULROT turns about the new Z axis.",
        ),
    },
    // 11 — seed 003 (W-CS); DOMAIN.md §1, §6; unconfirmed.rs (TransformLevels).
    // Program static/course/l11_reihenfolge.h: TRANS DATUM = 7, TRANS MIRROR = 8, PLANE = 9.
    LessonText {
        slug: "koordinatensysteme",
        title: Text::new("Koordinatensysteme und Reihenfolge", "Coordinate systems and order"),
        goal: Text::new(
            "Sie unterscheiden W-CS, WPL-CS und I-CS und programmieren Nullpunkt, Spiegelung und Schwenkung in der richtigen Reihenfolge.",
            "You tell W-CS, WPL-CS and I-CS apart and program datum shift, mirror and tilt in the right order.",
        ),
        paragraphs: &[
            Text::new(
                "W-CS ist das Werkstück-Koordinatensystem; sein Ursprung ist der aktive Bezugspunkt. Darin legen Sie mit Transformationen und dem Schwenken die Bearbeitungsebene fest: das WPL-CS. Ihre programmierten Koordinaten gelten im Eingabe-Koordinatensystem I-CS. Ohne Transformationen sind alle drei gleich.",
                "W-CS is the workpiece coordinate system; its origin is the active preset. In it you define the working plane, the WPL-CS, with transformations and the tilt. Your programmed coordinates are in the input coordinate system I-CS. Without transformations all three are the same.",
            ),
            Text::new(
                "Die Reihenfolge ändert das Ergebnis. Vor einem PLANE mit Raumwinkeln verschiebt TRANS DATUM den Drehpunkt der Schwenkung, und TRANS MIRROR spiegelt das ganze Programm samt Raumwinkeln. Nach dem Schwenken programmieren Sie nur noch Transformationen im WPL-CS.",
                "The order changes the result. Before a PLANE with spatial angles, TRANS DATUM moves the point the plane tilts about, and TRANS MIRROR mirrors the whole program including the spatial angles. After the tilt, program only transformations in the WPL-CS.",
            ),
            Text::new(
                "Im Beispiel: Satz 7 TRANS DATUM, Satz 8 TRANS MIRROR AXIS X, Satz 9 PLANE SPATIAL SPA+0 SPB+15 SPC+0 – wirksam wird SPB-15. Falsche Reihenfolgen können zu unerwarteten Bewegungen und Kollisionen führen.",
                "In the example: block 7 TRANS DATUM, block 8 TRANS MIRROR AXIS X, block 9 PLANE SPATIAL SPA+0 SPB+15 SPC+0 – what acts is SPB-15. A wrong order can cause unexpected movements and collisions.",
            ),
            Text::new(
                "Wie sich mehrere Transformationen genau verrechnen, belegt keine Quelle. Der Trainer nimmt an: erst Verschiebung, dann Spiegelung, dann Drehung.",
                "No source states exactly how several transformations combine. The trainer assumes: shift first, then mirror, then rotation.",
            ),
        ],
        steps: &[],
        widget_caption: Text::new(
            "Spielen Sie das Programm ab: Nach Satz 9 zeigt die Anzeige SPB-15, weil die Spiegelung vorher wirkt.",
            "Play the program: after block 9 the display shows SPB-15 because the mirror acts first.",
        ),
        summary: Text::new(
            "Erst Nullpunkt, dann Spiegelung, dann schwenken – die Reihenfolge bestimmt das Ergebnis.",
            "Datum first, then mirror, then tilt – the order decides the result.",
        ),
    },
];
