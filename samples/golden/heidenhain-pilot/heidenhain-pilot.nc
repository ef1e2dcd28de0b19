%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program HEIDENHAIN-G31]
[T9 offset 9, first at CL line 5, 0:25.3]
[cycle time 0:25.3, 1 tool change]
[HEIDENHAIN-G31]
N 10 T9
N 20 G97 S1000 M3
N 30 G0 X20. Z5.
[thread line 11: 7 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 40 G1 X18.598 Z2. G95 F0.2
N 50 G31 F1.5 U0.92 IC5 V0 H1 A30. D1 Q2 C0. BD0 B0. P0. K0.
N 60 G0 X16. Z2.
N 70 G1 X16. Z-20.
N 80 G80
N 90 G0 X18.598 Z2.
N 100 X20. Z5.
[thread line 18: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 110 G1 X18.598 Z2. G95 F0.2
N 120 G31 F1.5 U0.92 IC4 V1 H3 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 130 G0 X16. Z2.
N 140 G1 X16. Z-20.
N 150 G80
N 160 G0 X18.598 Z2.
N 170 X22. Z-30.
[thread line 25: 5 passes, pitch 2, depth 1.083]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 180 G1 X24.371 Z-26. G95 F0.2
N 190 G31 F2. U1.083 IC5 V0 H2 A30. D1 Q0 C0. BD1 B0. P0. K0.
N 200 G0 X27.835 Z-26.
N 210 G1 X27.835 Z0.
N 220 G80
N 230 G0 X24.371 Z-26.
N 240 X26. Z6.
[thread line 33: 5 passes, pitch 1.814, depth 1.1]
[G31 not used: G31's V1 law does not give the planned depths: pass 1: starts at X20.5523 Z1.8799, plan X20.5519 Z1.8730. G33 loop instead]
[pass 1 depth 0.2200 rough]
N 250 G1 X24.136 Z1.873 G95 F0.2
N 260 X20.552
N 270 G33 X19.217 Z-19.492 F1.814
N 280 G0 X22.797 Z-19.548
[pass 2 depth 0.4400 rough]
N 290 X24.128 Z1.746
N 300 G1 X20.104 F0.2
N 310 G33 X18.768 Z-19.619 F1.814
N 320 G0 X22.788 Z-19.682
[pass 3 depth 0.6600 rough]
N 330 X24.12 Z1.619
N 340 G1 X19.656 F0.2
N 350 G33 X18.32 Z-19.746 F1.814
N 360 G0 X22.78 Z-19.816
[pass 4 depth 0.8800 rough]
N 370 X24.112 Z1.492
N 380 G1 X19.207 F0.2
N 390 G33 X17.872 Z-19.873 F1.814
N 400 G0 X22.772 Z-19.95
[pass 5 depth 1.1000 rough]
N 410 X24.104 Z1.365
N 420 G1 X18.759 F0.2
N 430 G33 X17.424 Z-20. F1.814
N 440 G0 X22.763 Z-20.083
N 450 X24.14 Z1.951
N 460 X20. Z5.
[thread line 40: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31 has no infeed type for OPTION 0, steps decreasing by a constant amount. G33 loop instead]
[pass 1 depth 0.3680 rough]
N 470 G1 X18.598 Z2. F0.2
N 480 X15.264
N 490 G33 Z-20. F1.5
N 500 G0 X18.598
[pass 2 depth 0.6440 rough]
N 510 Z2.
N 520 G1 X14.712 F0.2
N 530 G33 Z-20. F1.5
N 540 G0 X18.598
[pass 3 depth 0.8280 rough]
N 550 Z2.
N 560 G1 X14.344 F0.2
N 570 G33 Z-20. F1.5
N 580 G0 X18.598
[pass 4 depth 0.9200 rough]
N 590 Z2.
N 600 G1 X14.16 F0.2
N 610 G33 Z-20. F1.5
N 620 G0 X18.598
N 630 Z2.
N 640 X120. Z50.
N 650 M5
N 660 M30
END
