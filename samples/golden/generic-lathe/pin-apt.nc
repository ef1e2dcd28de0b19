%
O0001
N10 G18 G21 G40 G90
(machine generic-lathe, program PIN-01 turned pin, 25 mm stock)
(T3 offset 3, first at CL line 5, 0:15.5)
(cycle time 0:15.5, 1 tool change)
N20 (PIN-01 turned pin, 25 mm stock)
N30 T0303
N40 (ROUGH AND FINISH OD)
N50 G50 S2500
N60 G96 S180 M3
N70 M7
N80 G0 X26. Z2.
N90 G1 X25. Z-30. G95 F0.25
N100 X26.
N110 G0 Z2.
N120 G1 X24.
N130 X23. Z-30. F0.1
N140 X26.
N150 G4 X1.5
M19 (orient spindle)
N160 M1
N170 G0 X100. Z50.
N180 M9
N190 M5
N200 M30
%
