%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-INTERNAL]
[T9 offset 9, first at CL line 5, 0:18.2]
[cycle time 0:18.2, 1 tool change]
[THREADS-INTERNAL]
N 10 T9
N 20 G97 S500 M3
N 30 G26 S500
N 40 G0 X22. Z5.
[thread line 10: 6 passes, pitch 2, depth 1.083]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.4421, plan 0.4620. G33 loop instead]
[pass 1 depth 0.4620 rough]
N 50 G1 X24.371 Z1.733 G95 F0.2
N 60 X28.759
N 70 G33 Z-23.641 F2.
N 80 G0 X24.371
[pass 2 depth 0.6533 rough]
N 90 Z1.623
N 100 G1 X29.142 F0.2
N 110 G33 Z-23.752 F2.
N 120 G0 X24.371
[pass 3 depth 0.8002 rough]
N 130 Z1.538
N 140 G1 X29.435 F0.2
N 150 G33 Z-23.837 F2.
N 160 G0 X24.371
[pass 4 depth 0.9239 rough]
N 170 Z1.467
N 180 G1 X29.683 F0.2
N 190 G33 Z-23.908 F2.
N 200 G0 X24.371
[pass 5 depth 1.0330 rough]
N 210 Z1.404
N 220 G1 X29.901 F0.2
N 230 G33 Z-23.971 F2.
N 240 G0 X24.371
[pass 6 depth 1.0830 finish]
N 250 Z1.375
N 260 G1 X30.001 F0.2
N 270 G33 Z-24. F2.
N 280 G0 X24.371
N 290 Z2.
N 300 X22. Z5.
[thread line 16: 4 passes, pitch 2, depth 1.083]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.2707 rough]
N 310 G1 X24.371 Z2. F0.2
N 320 X28.377
N 330 G33 Z-21.375 F2.
N 340 X24.377 Z-23.375 F2.
N 350 G0 X24.371
[pass 2 depth 0.5415 rough]
N 360 Z1.687
N 370 G1 X28.918 F0.2
N 380 G33 Z-21.687 F2.
N 390 X24.918 Z-23.687 F2.
N 400 G0 X24.371
[pass 3 depth 0.8122 rough]
N 410 Z2.
N 420 G1 X29.46 F0.2
N 430 G33 Z-21.375 F2.
N 440 X25.46 Z-23.375 F2.
N 450 G0 X24.371
[pass 4 depth 1.0830 rough]
N 460 Z1.375
N 470 G1 X30.001 F0.2
N 480 G33 Z-22. F2.
N 490 X26.001 Z-24. F2.
N 500 G0 X24.371
N 510 Z2.
N 520 X22. Z50.
N 530 M5
N 540 M30
END
