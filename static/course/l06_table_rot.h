0 BEGIN PGM L06_TABLE_ROT MM
1 ; Nur SPC ist ungleich 0: TABLE ROT entscheidet, wie gedreht wird
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 TOOL CALL 8 Z S4000 F800
5 L Z+0 R0 FMAX M91 M3 ; Sichere Position in Z
6 PLANE SPATIAL SPA+0 SPB+0 SPC+30 TURN FMAX TABLE ROT ; der C-Rundtisch dreht um 30 Grad
7 L X+10 Y+10 Z+5 R0 FMAX ; Start der Nut in der gedrehten Ebene
8 L Z-2 F800
9 L X+60 F800 ; Nut entlang der gedrehten X-Achse
10 L Z+5 R0 FMAX
11 L Z+0 R0 FMAX M91 ; Sichere Position in Z
12 PLANE RESET TURN FMAX ; Schwenken ruecksetzen
13 M30
14 END PGM L06_TABLE_ROT MM
