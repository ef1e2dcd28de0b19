%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-INTERNAL]
[T9 offset 9, first at CL line 5, 0:18.2]
[cycle time 0:18.2, 1 tool change]
[THREADS-INTERNAL]
N 10 T9
N 20 G97 S500 M3
N 30 G0 X22. Z5.
[thread line 10: 6 passes, pitch 2, depth 1.083]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.4421, plan 0.4620. G33 loop instead]
[pass 1 depth 0.4620 rough]
N 40 G1 X24.371 Z1.733 G95 F0.2
N 50 X28.759
N 60 G33 Z-23.641 F2.
N 70 G0 X24.371
[pass 2 depth 0.6533 rough]
N 80 Z1.623
N 90 G1 X29.142 F0.2
N 100 G33 Z-23.752 F2.
N 110 G0 X24.371
[pass 3 depth 0.8002 rough]
N 120 Z1.538
N 130 G1 X29.435 F0.2
N 140 G33 Z-23.837 F2.
N 150 G0 X24.371
[pass 4 depth 0.9239 rough]
N 160 Z1.467
N 170 G1 X29.683 F0.2
N 180 G33 Z-23.908 F2.
N 190 G0 X24.371
[pass 5 depth 1.0330 rough]
N 200 Z1.404
N 210 G1 X29.901 F0.2
N 220 G33 Z-23.971 F2.
N 230 G0 X24.371
[pass 6 depth 1.0830 finish]
N 240 Z1.375
N 250 G1 X30.001 F0.2
N 260 G33 Z-24. F2.
N 270 G0 X24.371
N 280 Z2.
N 290 X22. Z5.
[thread line 16: 4 passes, pitch 2, depth 1.083]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.2707 rough]
N 300 G1 X24.371 Z2. F0.2
N 310 X28.377
N 320 G33 Z-21.375 F2.
N 330 X24.377 Z-23.375 F2.
N 340 G0 X24.371
[pass 2 depth 0.5415 rough]
N 350 Z1.687
N 360 G1 X28.918 F0.2
N 370 G33 Z-21.687 F2.
N 380 X24.918 Z-23.687 F2.
N 390 G0 X24.371
[pass 3 depth 0.8122 rough]
N 400 Z2.
N 410 G1 X29.46 F0.2
N 420 G33 Z-21.375 F2.
N 430 X25.46 Z-23.375 F2.
N 440 G0 X24.371
[pass 4 depth 1.0830 rough]
N 450 Z1.375
N 460 G1 X30.001 F0.2
N 470 G33 Z-22. F2.
N 480 X26.001 Z-24. F2.
N 490 G0 X24.371
N 500 Z2.
N 510 X22. Z50.
N 520 M5
N 530 M30
END
