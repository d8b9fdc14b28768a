0 BEGIN PGM L07_RESET MM
1 ; PLANE RESET STAY setzt nur die Rechnung zurueck, die Drehachsen bleiben geschwenkt
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 TOOL CALL 8 Z S4000 F800
5 L Z+0 R0 FMAX M91 M3 ; Sichere Position in Z
6 L X-600 Y+500 R0 FMAX M91 ; Sichere Position in X/Y
7 PLANE SPATIAL SPA+0 SPB-30 SPC+0 TURN FMAX ; Einschwenken: Drehachsen fahren
8 L X+3 Y-10 Z+20 R0 FMAX ; vor die Kante X+0
9 L Z-5 F800 ; 5 mm unter die geschwenkte Ebene
10 L Y+110 F800 ; 30-Grad-Fase entlang der Kante
11 L Z+20 R0 FMAX
12 L Z+0 R0 FMAX M91 ; erst freifahren
13 PLANE RESET STAY ; nur die Rechnung: A und C bleiben stehen
14 L A+0 C+0 R0 FMAX ; Drehachsen selbst zurueckfahren
15 M30
16 END PGM L07_RESET MM
