(flattened by ngc from comp-outside.ngc for grbl, curves within 0.002 mm)
G21 G90 G91.1 G94 G40 G49 G17
G54
(cutter compensation outside a square with a round corner: tool 1, 6 mm)
G0 X-10 Y-10 Z5
(tool change: put in tool 1, diameter 6, then resume)
M0
S8000
M3
G43.1 Z12.5
G1 F300 X-10 Y-10 Z-2
G1 X-2.121 Y2.121
G2 X0 Y3 Z-2 I2.121 J-2.121
G1 X40
G3 X47 Y10 Z-2 I0 J7
G1 Y27
G1 X3
G1 Y0
G1 X-10 Y-10
G0 Z5
M5
M2
