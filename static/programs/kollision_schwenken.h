0 BEGIN PGM KOLLISION MM
1 ; Kollision beim Schwenken: das Werkzeug steht tief neben dem Rohteil
2 BLK FORM 0.1 Z X+0 Y+0 Z-40
3 BLK FORM 0.2 X+100 Y+100 Z+0
4 TOOL CALL 1 Z S3000 DL+20
5 L Z+0 R0 FMAX M91 ; Sichere Hoehe
6 L X+50 Y+110 R0 FMAX ; neben das Rohteil
7 L Z-45 R0 FMAX ; tief: die Spitze 5 mm ueber dem Rundtisch
8 ; SEQ- hebt beim Schwenken den Tischrand in das Werkzeug
9 ; Abhilfe: SEQ+ (schwenkt andersherum) oder vorher freifahren (MB MAX)
10 PLANE SPATIAL SPA-30 SPB+0 SPC+0 TURN FMAX SEQ-
11 L Z+50 R0 FMAX
12 PLANE RESET TURN FMAX
13 M30
14 END PGM KOLLISION MM
