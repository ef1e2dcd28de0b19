%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-CHAIN-MULTISTART]
[T5 offset 5, first at CL line 6, 0:13.6]
[cycle time 0:13.6, 1 tool change]
[THREADS-CHAIN-MULTISTART]
N 10 T5
N 20 G97 S400 M3
N 30 G26 S400
N 40 G0 X40. Z6.
[thread line 11: 8 passes, pitch 1.5, depth 0.92]
[G31 not used: a chained thread: clpost writes G31 for one straight thread line only. G33 loop instead]
[pass 1 start 1 depth 0.3680 rough]
N 50 G1 Z0. G95 F0.2
N 60 X23.264
N 70 G33 Z-15. F3.
N 80 X27.264 Z-25. F3.
N 90 G0 X40.
[pass 1 start 2 depth 0.3680 rough]
N 100 Z1.5
N 110 G1 X23.264 F0.2
N 120 G33 Z-15. F3.
N 130 X27.264 Z-25. F3.
N 140 G0 X40.
[pass 2 start 1 depth 0.6440 rough]
N 150 Z0.
N 160 G1 X22.712 F0.2
N 170 G33 Z-15. F3.
N 180 X26.712 Z-25. F3.
N 190 G0 X40.
[pass 2 start 2 depth 0.6440 rough]
N 200 Z1.5
N 210 G1 X22.712 F0.2
N 220 G33 Z-15. F3.
N 230 X26.712 Z-25. F3.
N 240 G0 X40.
[pass 3 start 1 depth 0.8280 rough]
N 250 Z0.
N 260 G1 X22.344 F0.2
N 270 G33 Z-15. F3.
N 280 X26.344 Z-25. F3.
N 290 G0 X40.
[pass 3 start 2 depth 0.8280 rough]
N 300 Z1.5
N 310 G1 X22.344 F0.2
N 320 G33 Z-15. F3.
N 330 X26.344 Z-25. F3.
N 340 G0 X40.
[pass 4 start 1 depth 0.9200 rough]
N 350 Z0.
N 360 G1 X22.16 F0.2
N 370 G33 Z-15. F3.
N 380 X26.16 Z-25. F3.
N 390 G0 X40.
[pass 4 start 2 depth 0.9200 rough]
N 400 Z1.5
N 410 G1 X22.16 F0.2
N 420 G33 Z-15. F3.
N 430 X26.16 Z-25. F3.
N 440 G0 X40.
N 450 Z0.
N 460 X100. Z50.
N 470 M5
N 480 M30
END
