(flattened by ngc from toolchange.ngc for grbl, curves within 0.002 mm)
G21 G90 G91.1 G94 G40 G49 G17
G54
(two tools from the table with their lengths, a coolant and a dwell)
G0 X0 Y0 Z50
(tool change: put in tool 1, diameter 6, then resume)
M0
G43.1 Z12.5
S9000
M3
M8
G0 X10 Y10 Z2
G1 F400 Z-1
G1 X30
G4 P1.5
G0 Z50
M9
M5
(tool change: put in tool 2, diameter 3, then resume)
M0
G43.1 Z20
S3000
M3
G0 X20 Y20 Z2
G1 F120 Z-8
G0 Z50
M5
M30
