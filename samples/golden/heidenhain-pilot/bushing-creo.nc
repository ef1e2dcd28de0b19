%1.nc
[INCH]
MACHINING
[machine heidenhain-pilot, program BUSHING-7]
[T2 offset 2, first at CL line 7, 0:13.0]
[cycle time 0:13.0, 1 tool change]
[BUSHING-7]
N 10 T2
N 20 G26 S2500
N 30 G96 S400 M3
N 40 M8
N 50 G0 X0.6 Z0.1
N 60 G1 Z-1.25 G95 F0.006
N 70 X0.7
N 80 Z-0.05
N 90 G3 X0.8 Z0. I0.05 K0.
N 100 G0 X0.6 Z0.1
N 110 M9
N 120 M5
N 130 M30
END
