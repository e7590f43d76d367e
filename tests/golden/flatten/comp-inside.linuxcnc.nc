(flattened by ngc from comp-inside.ngc for linuxcnc, curves within 0.002 mm)
G21 G90 G91.1 G94 G40 G49 G80 G17 G97
G54
(cutter compensation inside a pocket outline, with G42 and a G41.1 diameter)
G0 X20 Y20 Z5
T3 M6
S6000
M3
G43 H3
G1 F250 X20 Y20 Z-3
G1 X15 Y22.0711
G1 Y35
G1 X50
G2 X55 Y30 Z-3 I0 J-5
G1 Y15
G1 X10
G1 X20 Y20
G1 X19.8284 Y17
G1 X43
G1 Y25
G1 X20 Y20
G0 Z5
M5
M2
