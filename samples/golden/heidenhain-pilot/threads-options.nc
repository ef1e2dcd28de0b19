%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-OPTIONS]
[T5 offset 5, first at CL line 5, 0:48.2]
[cycle time 0:48.2, 1 tool change]
[THREADS-OPTIONS]
N 10 T5
N 20 G97 S800 M3
N 30 M8
N 40 G0 X20. Z5.
[thread line 12: 5 passes, pitch 1.5, depth 0.92]
[G31 not used: G31 has no infeed type for OPTION 0, steps decreasing by a constant amount. G33 loop instead]
[pass 1 depth 0.3067 rough]
N 50 G1 X18.598 Z2. G95 F0.2
N 60 X15.387
N 70 G33 Z-20. F1.5
N 80 G0 X18.598
[pass 2 depth 0.5520 rough]
N 90 Z2.
N 100 G1 X14.896 F0.2
N 110 G33 Z-20. F1.5
N 120 G0 X18.598
[pass 3 depth 0.7360 rough]
N 130 Z2.
N 140 G1 X14.528 F0.2
N 150 G33 Z-20. F1.5
N 160 G0 X18.598
[pass 4 depth 0.8587 rough]
N 170 Z2.
N 180 G1 X14.283 F0.2
N 190 G33 Z-20. F1.5
N 200 G0 X18.598
[pass 5 depth 0.9200 rough]
N 210 Z2.
N 220 G1 X14.16 F0.2
N 230 G33 Z-20. F1.5
N 240 G0 X18.598
N 250 Z2.
N 260 X20. Z5.
[thread line 19: 6 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 270 G1 X18.598 Z2. F0.2
N 280 G31 F1.5 U0.92 IC6 V0 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 290 G0 X16. Z2.
N 300 G1 X16. Z-20.
N 310 G80
N 320 G0 X18.598 Z2.
N 330 X20. Z5.
[thread line 26: 6 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 340 G1 X18.598 Z2. G95 F0.2
N 350 G31 F1.5 U0.92 IC6 V0 H3 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 360 G0 X16. Z2.
N 370 G1 X16. Z-20.
N 380 G80
N 390 G0 X18.598 Z2.
N 400 X20. Z5.
[thread line 33: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 410 G1 X18.598 Z2. G95 F0.2
N 420 G31 F1.5 U0.92 IC4 V1 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 430 G0 X16. Z2.
N 440 G1 X16. Z-20.
N 450 G80
N 460 G0 X18.598 Z2.
N 470 X20. Z5.
[thread line 40: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 480 G1 X18.598 Z2. G95 F0.2
N 490 G31 F1.5 U0.92 IC4 V1 H3 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 500 G0 X16. Z2.
N 510 G1 X16. Z-20.
N 520 G80
N 530 G0 X18.598 Z2.
N 540 X20. Z5.
[thread line 47: 10 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's V0 law does not give the planned depths: pass 1: depth 0.2909, plan 0.3000. G33 loop instead]
[pass 1 depth 0.3000 rough]
N 550 G1 X18.598 Z1.827 G95 F0.2
N 560 X15.4
N 570 G33 Z-19.642 F1.5
N 580 G0 X18.598
[pass 2 depth 0.4243 rough]
N 590 Z1.755
N 600 G1 X15.151 F0.2
N 610 G33 Z-19.714 F1.5
N 620 G0 X18.598
[pass 3 depth 0.5196 rough]
N 630 Z1.7
N 640 G1 X14.961 F0.2
N 650 G33 Z-19.769 F1.5
N 660 G0 X18.598
[pass 4 depth 0.6000 rough]
N 670 Z1.654
N 680 G1 X14.8 F0.2
N 690 G33 Z-19.815 F1.5
N 700 G0 X18.598
[pass 5 depth 0.6708 rough]
N 710 Z1.613
N 720 G1 X14.658 F0.2
N 730 G33 Z-19.856 F1.5
N 740 G0 X18.598
[pass 6 depth 0.7348 rough]
N 750 Z1.576
N 760 G1 X14.53 F0.2
N 770 G33 Z-19.893 F1.5
N 780 G0 X18.598
[pass 7 depth 0.7937 rough]
N 790 Z1.542
N 800 G1 X14.413 F0.2
N 810 G33 Z-19.927 F1.5
N 820 G0 X18.598
[pass 8 depth 0.8485 rough]
N 830 Z1.51
N 840 G1 X14.303 F0.2
N 850 G33 Z-19.959 F1.5
N 860 G0 X18.598
[pass 9 depth 0.9000 rough]
N 870 Z1.48
N 880 G1 X14.2 F0.2
N 890 G33 Z-19.988 F1.5
N 900 G0 X18.598
[pass 10 depth 0.9200 rough]
N 910 Z1.469
N 920 G1 X14.16 F0.2
N 930 G33 Z-20. F1.5
N 940 G0 X18.598
N 950 Z2.
N 960 X20. Z5.
[thread line 54: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 970 G1 X18.598 Z2. F0.2
N 980 G31 F1.5 U0.92 IC4 V1 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 990 G0 X16. Z2.
N 1000 G1 X16. Z-20.
N 1010 G80
N 1020 G0 X18.598 Z2.
N 1030 X100. Z50.
N 1040 M9
N 1050 M5
N 1060 M30
END
