0 BEGIN PGM L01_RAUMWINKEL MM
1 ; Raumwinkel: gleiche Winkel, je nach Maschine andere Achswerte
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 TOOL CALL 8 Z S4000 F800
5 L Z+0 R0 FMAX M91 M3 ; Sichere Position in Z
6 L X-600 Y+500 R0 FMAX M91 ; Sichere Position in X/Y
7 PLANE SPATIAL SPA+0 SPB+30 SPC+0 TURN FMAX ; 30 Grad um die Y-Achse
8 L X+50 Y+50 Z+50 R0 FMAX ; Werkzeug steht senkrecht zur geschwenkten Ebene
9 L Z+0 R0 FMAX M91 ; Sichere Position in Z
10 PLANE RESET TURN FMAX ; Schwenken ruecksetzen
11 M30
12 END PGM L01_RAUMWINKEL MM
