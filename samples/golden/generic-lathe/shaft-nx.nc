%
O0001
N10 G18 G21 G40 G90
(machine generic-lathe, program shaft-nx)
(T1 offset 1, OD_80_L, first at CL line 8, 0:23.3)
(cycle time 0:23.3, 1 tool change)
N20 (operation FACING_OD TOOL OD_80_L)
N30 T0101
N40 G97 S1200 M3
N50 M8
N60 G0 X44. Z2.
N70 Z0.
N80 G1 X-0.8 G95 F0.2
N90 Z1.
N100 G0 X30.
N110 G1 Z-20. F0.15
N120 G2 X34. Z-22. I2. K0.
N130 G1 X40.
N140 Z-40.
N150 X44.
N160 G0 Z2.
N170 M5
N180 M9
N190 M30
%
