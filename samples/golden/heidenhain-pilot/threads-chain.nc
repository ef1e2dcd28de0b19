%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-CHAIN]
[T6 offset 6, first at CL line 7, 0:52.1]
[cycle time 0:52.1, 1 tool change]
[THREADS-CHAIN]
N 10 T6
N 20 G97 S300 M3
N 30 G0 X60. Z5.
[thread line 12: 6 passes, pitch 2, depth 0.92]
[G31 not used: a chained thread: clpost writes G31 for one straight thread line only. G33 loop instead]
[pass 1 depth 0.4114 rough]
N 40 G1 Z-0.238 G95 F0.2
N 50 X29.177
N 60 G33 Z-30.238 F2.
N 70 X35.177 Z-60.238 F2.
N 80 X48.805 Z-79.706 F2.
N 90 G0 X60.
[pass 2 depth 0.5819 rough]
N 100 Z-0.336
N 110 G1 X28.836 F0.2
N 120 G33 Z-30.336 F2.
N 130 X34.836 Z-60.336 F2.
N 140 X48.464 Z-79.805 F2.
N 150 G0 X60.
[pass 3 depth 0.7126 rough]
N 160 Z-0.411
N 170 G1 X28.575 F0.2
N 180 G33 Z-30.411 F2.
N 190 X34.575 Z-60.411 F2.
N 200 X48.203 Z-79.88 F2.
N 210 G0 X60.
[pass 4 depth 0.8229 rough]
N 220 Z-0.475
N 230 G1 X28.354 F0.2
N 240 G33 Z-30.475 F2.
N 250 X34.354 Z-60.475 F2.
N 260 X47.982 Z-79.944 F2.
N 270 G0 X60.
[pass 5 depth 0.9200 rough]
N 280 Z-0.531
N 290 G1 X28.16 F0.2
N 300 G33 Z-30.531 F2.
N 310 X34.16 Z-60.531 F2.
N 320 X47.788 Z-80. F2.
N 330 G0 X60.
[pass 6 depth 0.9200 spring]
N 340 Z-0.531
N 350 G1 X28.16 F0.2
N 360 G33 Z-30.531 F2.
N 370 X34.16 Z-60.531 F2.
N 380 X47.788 Z-80. F2.
N 390 G0 X60.
N 400 Z0.
N 410 X100. Z50.
N 420 M5
N 430 M30
END
