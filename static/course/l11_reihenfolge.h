0 BEGIN PGM L11_REIHENFOLGE MM
1 ; Reihenfolge: Nullpunkt, Spiegelung, dann schwenken; zuruecksetzen umgekehrt
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 TOOL CALL 8 Z S4000 F800
5 L Z+0 R0 FMAX M91 M3 ; Sichere Position in Z
6 L X-600 Y+500 R0 FMAX M91 ; Sichere Position in X/Y
7 TRANS DATUM AXIS X+50 Y+50 Z+0 ; 1. Nullpunkt in die Rohteilmitte (W-CS)
8 TRANS MIRROR AXIS X ; 2. Spiegeln an der Y-Achse durch den neuen Nullpunkt
9 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN FMAX ; 3. Schwenken: SPB wirkt gespiegelt
10 L X+0 Y+0 Z+5 R0 FMAX ; ueber dem Nullpunkt
11 L Z-2 F800 ; 2 mm tief
12 L Z+5 R0 FMAX
13 L Z+0 R0 FMAX M91 ; Sichere Position in Z
14 PLANE RESET TURN FMAX ; Schwenken ruecksetzen
15 TRANS MIRROR RESET ; Spiegelung aufheben
16 TRANS DATUM RESET ; Nullpunktverschiebung aufheben
17 M30
18 END PGM L11_REIHENFOLGE MM
