0 BEGIN PGM STAY_Q120 MM
1 ; STAY schwenkt nur das Koordinatensystem; L A+Q120 C+Q122 positioniert die Drehachsen
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 TOOL CALL 8 Z S4000 F800
5 L Z+0 R0 FMAX M91 M3 ; Sichere Position in Z
6 L X-600 Y+500 R0 FMAX M91 ; Sichere Position in X/Y
7 PLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY SEQ- TABLE ROT ; Achsen bleiben stehen
8 L A+Q120 C+Q122 R0 FMAX M126 ; erst jetzt schwenken die Drehachsen
9 L X+50 Y+50 Z+50 R0 FMAX
10 L Z+5 R0 FMAX
11 L Z-2 F800
12 L Z+50 R0 FMAX
13 L Z+0 R0 FMAX M91
14 PLANE RESET STAY ; Rechnung zurueckgesetzt, Achsen noch geschwenkt
15 L A+0 C+0 R0 FMAX ; Drehachsen zurueck
16 M30
17 END PGM STAY_Q120 MM
