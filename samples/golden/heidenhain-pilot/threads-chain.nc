%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-CHAIN]
[T6 offset 6, first at CL line 7, 0:52.1]
[cycle time 0:52.1, 1 tool change]
[THREADS-CHAIN]
N 10 T6
N 20 G97 S300 M3
N 30 G26 S300
N 40 G0 X60. Z5.
[thread line 12: 6 passes, pitch 2, depth 0.92]
[G31 not used: a chained thread: clpost writes G31 for one straight thread line only. G33 loop instead]
[pass 1 depth 0.4114 rough]
N 50 G1 Z-0.238 G95 F0.2
N 60 X29.177
N 70 G33 Z-30.238 F2.
N 80 X35.177 Z-60.238 F2.
N 90 X48.805 Z-79.706 F2.
N 100 G0 X60.
[pass 2 depth 0.5819 rough]
N 110 Z-0.336
N 120 G1 X28.836 F0.2
N 130 G33 Z-30.336 F2.
N 140 X34.836 Z-60.336 F2.
N 150 X48.464 Z-79.805 F2.
N 160 G0 X60.
[pass 3 depth 0.7126 rough]
N 170 Z-0.411
N 180 G1 X28.575 F0.2
N 190 G33 Z-30.411 F2.
N 200 X34.575 Z-60.411 F2.
N 210 X48.203 Z-79.88 F2.
N 220 G0 X60.
[pass 4 depth 0.8229 rough]
N 230 Z-0.475
N 240 G1 X28.354 F0.2
N 250 G33 Z-30.475 F2.
N 260 X34.354 Z-60.475 F2.
N 270 X47.982 Z-79.944 F2.
N 280 G0 X60.
[pass 5 depth 0.9200 rough]
N 290 Z-0.531
N 300 G1 X28.16 F0.2
N 310 G33 Z-30.531 F2.
N 320 X34.16 Z-60.531 F2.
N 330 X47.788 Z-80. F2.
N 340 G0 X60.
[pass 6 depth 0.9200 spring]
N 350 Z-0.531
N 360 G1 X28.16 F0.2
N 370 G33 Z-30.531 F2.
N 380 X34.16 Z-60.531 F2.
N 390 X47.788 Z-80. F2.
N 400 G0 X60.
N 410 Z0.
N 420 X100. Z50.
N 430 M5
N 440 M30
END
