%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program PART-TURNED]
[T1 offset 1, first at CL line 6, 0:25.8]
[T2 offset 2, first at CL line 24, 0:06.2]
[T3 offset 3, first at CL line 32, 0:16.5]
[T4 offset 4, first at CL line 40, 0:07.1]
[T5 offset 5, first at CL line 48, 0:11.7]
[T6 offset 6, first at CL line 60, 0:30.3]
[cycle time 1:37.6, 6 tool changes]
[PART-TURNED]
N 10 T1
N 20 G97 S800 M3
N 30 G26 S800
N 40 M8
N 50 G0 X32. Z2.
N 60 Z0.
N 70 G1 X0. G95 F0.2
N 80 G0 Z2.
N 90 X24.
N 100 G1 Z-42.
N 110 X32.
N 120 G0 Z2.
N 130 T2
N 140 G97 S1500 M3
N 150 G26 S1500
N 160 G0 X0. Z10.
[hole at CL line 29: drilling to Z-3.]
N 170 G0 Z2.
N 180 G95 F0.05
N 190 G71 Z-3. E0.5
N 200 G0 Z10.
N 210 T3
N 220 G97 S900 M3
N 230 G26 S900
N 240 G0 X0. Z10.
[hole at CL line 37: peck drilling to Z-22.]
N 250 G0 Z2.
N 260 G95 F0.12
N 270 G74 Z-22. P5.
N 280 G0 Z10.
N 290 T4
N 300 G97 S300 M3
N 310 G26 S300
N 320 G0 X0. Z10.
[hole at CL line 45: tapping to Z-16.]
N 330 G0 Z5.
N 340 G73 Z-16. F1.5
N 350 G0 Z10.
N 360 T5
N 370 G97 S600 M3
N 380 G26 S600
N 390 G0 X32. Z5.
[thread line 53: 6 passes, pitch 2, depth 1.227]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.5264 rough]
N 400 X27.464 Z3.696
N 410 X22.947
N 420 G33 Z-24.595 F2.
N 430 X26.947 Z-26.595 F2.
N 440 G0 X27.464
[pass 2 depth 0.7444 rough]
N 450 Z3.57
N 460 X22.511
N 470 G33 Z-24.721 F2.
N 480 X26.511 Z-26.721 F2.
N 490 G0 X27.464
[pass 3 depth 0.9117 rough]
N 500 Z3.474
N 510 X22.177
N 520 G33 Z-24.818 F2.
N 530 X26.177 Z-26.818 F2.
N 540 G0 X27.464
[pass 4 depth 1.0527 rough]
N 550 Z3.392
N 560 X21.895
N 570 G33 Z-24.899 F2.
N 580 X25.895 Z-26.899 F2.
N 590 G0 X27.464
[pass 5 depth 1.1770 rough]
N 600 Z3.32
N 610 X21.646
N 620 G33 Z-24.971 F2.
N 630 X25.646 Z-26.971 F2.
N 640 G0 X27.464
[pass 6 depth 1.2270 finish]
N 650 Z3.292
N 660 X21.546
N 670 G33 Z-25. F2.
N 680 X25.546 Z-27. F2.
N 690 G0 X27.464
N 700 Z4.
N 710 X40. Z-44.
N 720 T6
N 730 G97 S700 M3
N 740 G26 S700
N 750 G0 X32. Z-44.
N 760 G1 X-1. G95 F0.05
N 770 G0 X32.
N 780 X100. Z50.
N 790 M9
N 800 M5
N 810 M30
END
