%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-CHAIN-MULTISTART]
[T5 offset 5, first at CL line 6, 0:13.6]
[cycle time 0:13.6, 1 tool change]
[THREADS-CHAIN-MULTISTART]
N 10 T5
N 20 G97 S400 M3
N 30 G0 X40. Z6.
[thread line 11: 8 passes, pitch 1.5, depth 0.92]
[G31 not used: a chained thread: clpost writes G31 for one straight thread line only. G33 loop instead]
[pass 1 start 1 depth 0.3680 rough]
N 40 G1 Z0. G95 F0.2
N 50 X23.264
N 60 G33 Z-15. F3.
N 70 X27.264 Z-25. F3.
N 80 G0 X40.
[pass 1 start 2 depth 0.3680 rough]
N 90 Z1.5
N 100 G1 X23.264 F0.2
N 110 G33 Z-15. F3.
N 120 X27.264 Z-25. F3.
N 130 G0 X40.
[pass 2 start 1 depth 0.6440 rough]
N 140 Z0.
N 150 G1 X22.712 F0.2
N 160 G33 Z-15. F3.
N 170 X26.712 Z-25. F3.
N 180 G0 X40.
[pass 2 start 2 depth 0.6440 rough]
N 190 Z1.5
N 200 G1 X22.712 F0.2
N 210 G33 Z-15. F3.
N 220 X26.712 Z-25. F3.
N 230 G0 X40.
[pass 3 start 1 depth 0.8280 rough]
N 240 Z0.
N 250 G1 X22.344 F0.2
N 260 G33 Z-15. F3.
N 270 X26.344 Z-25. F3.
N 280 G0 X40.
[pass 3 start 2 depth 0.8280 rough]
N 290 Z1.5
N 300 G1 X22.344 F0.2
N 310 G33 Z-15. F3.
N 320 X26.344 Z-25. F3.
N 330 G0 X40.
[pass 4 start 1 depth 0.9200 rough]
N 340 Z0.
N 350 G1 X22.16 F0.2
N 360 G33 Z-15. F3.
N 370 X26.16 Z-25. F3.
N 380 G0 X40.
[pass 4 start 2 depth 0.9200 rough]
N 390 Z1.5
N 400 G1 X22.16 F0.2
N 410 G33 Z-15. F3.
N 420 X26.16 Z-25. F3.
N 430 G0 X40.
N 440 Z0.
N 450 X100. Z50.
N 460 M5
N 470 M30
END
