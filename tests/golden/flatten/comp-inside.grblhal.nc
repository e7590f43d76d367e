(flattened by ngc from comp-inside.ngc for grblhal, curves within 0.002 mm)
G21 G90 G91.1 G94 G40 G49 G17
G54
(cutter compensation inside a pocket outline, with G42 and a G41.1 diameter)
G0 X20 Y20 Z5
(tool change: put in tool 3, diameter 10, then resume)
M0
S6000
M3
G43.1 Z35.25
G1 F250 X20 Y20 Z-3
G1 X15 Y22.071
G1 Y35
G1 X50
G2 X55 Y30 Z-3 I0 J-5
G1 Y15
G1 X10
G1 X20 Y20
G1 X19.828 Y17
G1 X43
G1 Y25
G1 X20 Y20
G0 Z5
M5
M2
