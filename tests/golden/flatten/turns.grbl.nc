(flattened by ngc from turns.ngc for grbl, curves within 0.002 mm)
G21 G90 G91.1 G94 G40 G49 G17
G54
(a helix of three turns with P, and a full circle)
G0 X10 Y0 Z1
G1 F200 Z0
G3 X10 Y0 Z-2 I-10 J0
G3 X10 Y0 Z-4 I-10 J0
G3 X10 Y0 Z-6 I-10 J0
G2 X10 Y0 Z-6 I-10 J0
G18 G2 X10 Y0 Z-6 I0 K3
G2 X10 Y0 Z-6 I0 K3
G0 Z5
M2
