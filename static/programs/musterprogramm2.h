0 BEGIN PGM Musterprogramm2 MM
1 ; Trainer-Beispiel (das Handbuch bricht nach der Ueberschrift ab)
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 ;
5 TOOL CALL 8 Z S4000 F800
6 ;
7 L Z+0 R0 FMAX M91 M3 ; Sichere Position in Z
8 L X-600 Y+500 R0 FMAX M91 ; Sichere Position in X/Y
9 ;
10 TRANS DATUM AXIS X+50 Y+50 Z+0 ; Nullpunkt in die Mitte der Oberseite
11 ;
12 PLANE SPATIAL SPA+0 SPB+15 SPC+0 TURN MB MAX FMAX ; Einschwenken um den neuen Nullpunkt
13 ;
14 CYCL DEF 200 BOHREN ~
  Q200=+2          ;SICHERHEITS-ABST. ~
  Q201=-20         ;TIEFE ~
  Q206=+150        ;VORSCHUB TIEFENZ. ~
  Q202=+5          ;ZUSTELL-TIEFE ~
  Q210=+0          ;VERWEILZEIT OBEN ~
  Q203=+0          ;KOOR. OBERFLAECHE ~
  Q204=+50         ;2. SICHERHEITS-ABST. ~
  Q211=+0          ;VERWEILZEIT UNTEN
15 L X+0 Y-25 Z+50 R0 FMAX M99 ; Bohrung 1
16 L X+0 Y+0 R0 FMAX M99 ; Bohrung 2 im Nullpunkt
17 L X+0 Y+25 R0 FMAX M99 ; Bohrung 3
18 ;
19 L Z+0 R0 FMAX M91 ; Sichere Position in Z
20 L X-600 Y+500 R0 FMAX M91 ; Sichere Position in X/Y
21 ;
22 PLANE RESET TURN FMAX ; Schwenken ruecksetzen
23 TRANS DATUM RESET ; Nullpunktverschiebung aufheben
24 ;
25 M30
26 ;
27 END PGM Musterprogramm2 MM
