%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-OPTIONS]
[T5 offset 5, first at CL line 5, 0:48.2]
[cycle time 0:48.2, 1 tool change]
[THREADS-OPTIONS]
N 10 T5
N 20 G97 S800 M3
N 30 G26 S800
N 40 M8
N 50 G0 X20. Z5.
[thread line 12: 5 passes, pitch 1.5, depth 0.92]
[G31 not used: G31 has no infeed type for OPTION 0, steps decreasing by a constant amount. G33 loop instead]
[pass 1 depth 0.3067 rough]
N 60 G1 X18.598 Z2. G95 F0.2
N 70 X15.387
N 80 G33 Z-20. F1.5
N 90 G0 X18.598
[pass 2 depth 0.5520 rough]
N 100 Z2.
N 110 G1 X14.896 F0.2
N 120 G33 Z-20. F1.5
N 130 G0 X18.598
[pass 3 depth 0.7360 rough]
N 140 Z2.
N 150 G1 X14.528 F0.2
N 160 G33 Z-20. F1.5
N 170 G0 X18.598
[pass 4 depth 0.8587 rough]
N 180 Z2.
N 190 G1 X14.283 F0.2
N 200 G33 Z-20. F1.5
N 210 G0 X18.598
[pass 5 depth 0.9200 rough]
N 220 Z2.
N 230 G1 X14.16 F0.2
N 240 G33 Z-20. F1.5
N 250 G0 X18.598
N 260 Z2.
N 270 X20. Z5.
[thread line 19: 6 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 280 G1 X18.598 Z2. F0.2
N 290 G31 F1.5 U0.92 IC6 V0 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 300 G0 X16. Z2.
N 310 G1 X16. Z-20.
N 320 G80
N 330 G0 X18.598 Z2.
N 340 X20. Z5.
[thread line 26: 6 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 350 G1 X18.598 Z2. G95 F0.2
N 360 G31 F1.5 U0.92 IC6 V0 H3 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 370 G0 X16. Z2.
N 380 G1 X16. Z-20.
N 390 G80
N 400 G0 X18.598 Z2.
N 410 X20. Z5.
[thread line 33: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 420 G1 X18.598 Z2. G95 F0.2
N 430 G31 F1.5 U0.92 IC4 V1 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 440 G0 X16. Z2.
N 450 G1 X16. Z-20.
N 460 G80
N 470 G0 X18.598 Z2.
N 480 X20. Z5.
[thread line 40: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 490 G1 X18.598 Z2. G95 F0.2
N 500 G31 F1.5 U0.92 IC4 V1 H3 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 510 G0 X16. Z2.
N 520 G1 X16. Z-20.
N 530 G80
N 540 G0 X18.598 Z2.
N 550 X20. Z5.
[thread line 47: 10 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's V0 law does not give the planned depths: pass 1: depth 0.2909, plan 0.3000. G33 loop instead]
[pass 1 depth 0.3000 rough]
N 560 G1 X18.598 Z1.827 G95 F0.2
N 570 X15.4
N 580 G33 Z-19.642 F1.5
N 590 G0 X18.598
[pass 2 depth 0.4243 rough]
N 600 Z1.755
N 610 G1 X15.151 F0.2
N 620 G33 Z-19.714 F1.5
N 630 G0 X18.598
[pass 3 depth 0.5196 rough]
N 640 Z1.7
N 650 G1 X14.961 F0.2
N 660 G33 Z-19.769 F1.5
N 670 G0 X18.598
[pass 4 depth 0.6000 rough]
N 680 Z1.654
N 690 G1 X14.8 F0.2
N 700 G33 Z-19.815 F1.5
N 710 G0 X18.598
[pass 5 depth 0.6708 rough]
N 720 Z1.613
N 730 G1 X14.658 F0.2
N 740 G33 Z-19.856 F1.5
N 750 G0 X18.598
[pass 6 depth 0.7348 rough]
N 760 Z1.576
N 770 G1 X14.53 F0.2
N 780 G33 Z-19.893 F1.5
N 790 G0 X18.598
[pass 7 depth 0.7937 rough]
N 800 Z1.542
N 810 G1 X14.413 F0.2
N 820 G33 Z-19.927 F1.5
N 830 G0 X18.598
[pass 8 depth 0.8485 rough]
N 840 Z1.51
N 850 G1 X14.303 F0.2
N 860 G33 Z-19.959 F1.5
N 870 G0 X18.598
[pass 9 depth 0.9000 rough]
N 880 Z1.48
N 890 G1 X14.2 F0.2
N 900 G33 Z-19.988 F1.5
N 910 G0 X18.598
[pass 10 depth 0.9200 rough]
N 920 Z1.469
N 930 G1 X14.16 F0.2
N 940 G33 Z-20. F1.5
N 950 G0 X18.598
N 960 Z2.
N 970 X20. Z5.
[thread line 54: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 980 G1 X18.598 Z2. F0.2
N 990 G31 F1.5 U0.92 IC4 V1 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 1000 G0 X16. Z2.
N 1010 G1 X16. Z-20.
N 1020 G80
N 1030 G0 X18.598 Z2.
N 1040 X100. Z50.
N 1050 M9
N 1060 M5
N 1070 M30
END
