%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program PIN-01 turned pin, 25 mm stock]
[T3 offset 3, first at CL line 5, 0:15.5]
[cycle time 0:15.5, 1 tool change]
[PIN-01 turned pin, 25 mm stock]
N 10 T3
[ROUGH AND FINISH OD]
N 20 G26 S2500
N 30 G96 S180 M3
N 40 M7
N 50 G0 X26. Z2.
N 60 G1 X25. Z-30. G95 F0.25
N 70 X26.
N 80 G0 Z2.
N 90 G1 X24.
N 100 X23. Z-30. F0.1
N 110 X26.
N 120 G4 F1.5
M19 (orient spindle)
N 130 M1
N 140 G0 X100. Z50.
N 150 M9
N 160 M5
N 170 M30
END
