(flattened by ngc from offsets.ngc for fluidnc, curves within 0.002 mm)
G21 G90 G91.1 G94 G40 G49 G17
G54
(G52 and G92 offsets set by the program, in a work offset the operator set)
G56
G0 X0 Y0 Z5
G1 F300 Z-1
G1 X20
G1 X30 Y5
G1 X50
G1 X55 Y10
G0 Z5
G54
M2
