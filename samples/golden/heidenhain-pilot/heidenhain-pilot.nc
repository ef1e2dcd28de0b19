%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program HEIDENHAIN-G31]
[T9 offset 9, first at CL line 5, 0:25.3]
[cycle time 0:25.3, 1 tool change]
[HEIDENHAIN-G31]
N 10 T9
N 20 G97 S1000 M3
N 30 G26 S1000
N 40 G0 X20. Z5.
[thread line 11: 7 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 50 G1 X18.598 Z2. G95 F0.2
N 60 G31 F1.5 U0.92 IC5 V0 H1 A30. D1 Q2 C0. BD0 B0. P0. K0.
N 70 G0 X16. Z2.
N 80 G1 X16. Z-20.
N 90 G80
N 100 G0 X18.598 Z2.
N 110 X20. Z5.
[thread line 18: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 120 G1 X18.598 Z2. G95 F0.2
N 130 G31 F1.5 U0.92 IC4 V1 H3 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 140 G0 X16. Z2.
N 150 G1 X16. Z-20.
N 160 G80
N 170 G0 X18.598 Z2.
N 180 X22. Z-30.
[thread line 25: 5 passes, pitch 2, depth 1.083]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 190 G1 X24.371 Z-26. G95 F0.2
N 200 G31 F2. U1.083 IC5 V0 H2 A30. D1 Q0 C0. BD1 B0. P0. K0.
N 210 G0 X27.835 Z-26.
N 220 G1 X27.835 Z0.
N 230 G80
N 240 G0 X24.371 Z-26.
N 250 X26. Z6.
[thread line 33: 5 passes, pitch 1.814, depth 1.1]
[G31 not used: G31's V1 law does not give the planned depths: pass 1: starts at X20.5523 Z1.8799, plan X20.5519 Z1.8730. G33 loop instead]
[pass 1 depth 0.2200 rough]
N 260 G1 X24.136 Z1.873 G95 F0.2
N 270 X20.552
N 280 G33 X19.217 Z-19.492 F1.814
N 290 G0 X22.797 Z-19.548
[pass 2 depth 0.4400 rough]
N 300 X24.128 Z1.746
N 310 G1 X20.104 F0.2
N 320 G33 X18.768 Z-19.619 F1.814
N 330 G0 X22.788 Z-19.682
[pass 3 depth 0.6600 rough]
N 340 X24.12 Z1.619
N 350 G1 X19.656 F0.2
N 360 G33 X18.32 Z-19.746 F1.814
N 370 G0 X22.78 Z-19.816
[pass 4 depth 0.8800 rough]
N 380 X24.112 Z1.492
N 390 G1 X19.207 F0.2
N 400 G33 X17.872 Z-19.873 F1.814
N 410 G0 X22.772 Z-19.95
[pass 5 depth 1.1000 rough]
N 420 X24.104 Z1.365
N 430 G1 X18.759 F0.2
N 440 G33 X17.424 Z-20. F1.814
N 450 G0 X22.763 Z-20.083
N 460 X24.14 Z1.951
N 470 X20. Z5.
[thread line 40: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31 has no infeed type for OPTION 0, steps decreasing by a constant amount. G33 loop instead]
[pass 1 depth 0.3680 rough]
N 480 G1 X18.598 Z2. F0.2
N 490 X15.264
N 500 G33 Z-20. F1.5
N 510 G0 X18.598
[pass 2 depth 0.6440 rough]
N 520 Z2.
N 530 G1 X14.712 F0.2
N 540 G33 Z-20. F1.5
N 550 G0 X18.598
[pass 3 depth 0.8280 rough]
N 560 Z2.
N 570 G1 X14.344 F0.2
N 580 G33 Z-20. F1.5
N 590 G0 X18.598
[pass 4 depth 0.9200 rough]
N 600 Z2.
N 610 G1 X14.16 F0.2
N 620 G33 Z-20. F1.5
N 630 G0 X18.598
N 640 Z2.
N 650 X120. Z50.
N 660 M5
N 670 M30
END
