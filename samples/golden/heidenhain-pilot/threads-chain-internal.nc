%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-CHAIN-INTERNAL]
[T9 offset 9, first at CL line 6, 0:09.7]
[cycle time 0:09.7, 1 tool change]
[THREADS-CHAIN-INTERNAL]
N 10 T9
N 20 G97 S500 M3
N 30 G26 S500
N 40 G0 X20. Z5.
[thread line 11: 4 passes, pitch 1.5, depth 0.812]
[G31 not used: a chained thread: clpost writes G31 for one straight thread line only. G33 loop instead]
[pass 1 depth 0.2030 rough]
N 50 G1 Z1.883 G95 F0.2
N 60 X28.406
N 70 G33 Z-10.117 F1.5
N 80 X30.312 Z-19.648 F1.5
N 90 X27.626 Z-21.29 F1.5
N 100 G0 X20.
[pass 2 depth 0.4060 rough]
N 110 Z1.766
N 120 G1 X28.812 F0.2
N 130 G33 Z-10.234 F1.5
N 140 X30.718 Z-19.766 F1.5
N 150 X28.032 Z-21.407 F1.5
N 160 G0 X20.
[pass 3 depth 0.6090 rough]
N 170 Z1.648
N 180 G1 X29.218 F0.2
N 190 G33 Z-10.352 F1.5
N 200 X31.124 Z-19.883 F1.5
N 210 X28.438 Z-21.525 F1.5
N 220 G0 X20.
[pass 4 depth 0.8120 rough]
N 230 Z1.531
N 240 G1 X29.624 F0.2
N 250 G33 Z-10.469 F1.5
N 260 X31.53 Z-20. F1.5
N 270 X28.844 Z-21.642 F1.5
N 280 G0 X20.
N 290 Z2.
N 300 Z50.
N 310 M5
N 320 M30
END
