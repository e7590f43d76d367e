(flattened by ngc from units.ngc for fluidnc, curves within 0.002 mm)
G21 G90 G91.1 G94 G40 G49 G17
G54
(a program in inches that switches to millimetres and back)
G0 X0 Y0 Z5.08
G1 F254 Z-1.27
G1 X25.4 Y12.7
G1 F6350 X50 Y25
G2 X60 Y15 Z-1.27 I0 J-10
G1 X25.4 Y0
G0 Z5.08
M2
