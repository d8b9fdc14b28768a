0 BEGIN PGM L04_STAY MM
1 ; Positionierverhalten STAY: derselbe Satz, nur MOVE/TURN/STAY verschieden
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 TOOL CALL 8 Z S4000 F800
5 L Z+0 R0 FMAX M91 M3 ; Sichere Position in Z
6 L X+50 Y+50 R0 FMAX ; ueber die Rohteilmitte
7 L Z+50 R0 FMAX ; Spitze 50 mm ueber der Oberflaeche
8 PLANE SPATIAL SPA+0 SPB+45 SPC+0 STAY ; nur das Koordinatensystem schwenkt
9 L Z+0 R0 FMAX M91 ; Sichere Position in Z
10 L A+Q120 C+Q122 R0 FMAX ; erst jetzt schwenken die Drehachsen
11 PLANE RESET TURN FMAX ; Drehachsen zurueck auf 0
12 M30
13 END PGM L04_STAY MM
