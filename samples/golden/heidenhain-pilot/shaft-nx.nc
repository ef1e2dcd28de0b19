%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program shaft-nx]
[T1 offset 1, OD_80_L, first at CL line 8, 0:23.3]
[cycle time 0:23.3, 1 tool change]
[operation FACING_OD TOOL OD_80_L]
N 10 T1
N 20 G97 S1200 M3
N 30 G26 S1200
N 40 M8
N 50 G0 X44. Z2.
N 60 Z0.
N 70 G1 X-0.8 G95 F0.2
N 80 Z1.
N 90 G0 X30.
N 100 G1 Z-20. F0.15
N 110 G2 X34. Z-22. I2. K0.
N 120 G1 X40.
N 130 Z-40.
N 140 X44.
N 150 G0 Z2.
N 160 M5
N 170 M9
N 180 M30
END
