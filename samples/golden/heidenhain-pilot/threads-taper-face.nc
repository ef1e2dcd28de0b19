%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-TAPER-FACE]
[T5 offset 5, first at CL line 5, 0:14.7]
[cycle time 0:14.7, 1 tool change]
[THREADS-TAPER-FACE]
N 10 T5
N 20 G97 S500 M3
N 30 G26 S500
N 40 G0 X26. Z6.
[thread line 11: 5 passes, pitch 1.814, depth 1.1]
[G31 not used: G31's V0 law does not give the planned depths: pass 1: starts at X19.9989 Z1.7315, plan X19.9979 Z1.7161. G33 loop instead]
[pass 1 depth 0.4919 rough]
N 50 G1 X24.126 Z1.716 G95 F0.2
N 60 X19.998
N 70 G33 X18.663 Z-19.649 F1.814
N 80 G0 X22.786 Z-19.714
[pass 2 depth 0.6957 rough]
N 90 X24.118 Z1.599
N 100 G1 X19.583 F0.2
N 110 G33 X18.248 Z-19.767 F1.814
N 120 G0 X22.779 Z-19.837
[pass 3 depth 0.8521 rough]
N 130 X24.113 Z1.508
N 140 G1 X19.264 F0.2
N 150 G33 X17.929 Z-19.857 F1.814
N 160 G0 X22.773 Z-19.933
[pass 4 depth 0.9839 rough]
N 170 X24.108 Z1.432
N 180 G1 X18.996 F0.2
N 190 G33 X17.66 Z-19.933 F1.814
N 200 G0 X22.768 Z-20.013
[pass 5 depth 1.1000 rough]
N 210 X24.104 Z1.365
N 220 G1 X18.759 F0.2
N 230 G33 X17.424 Z-20. F1.814
N 240 G0 X22.763 Z-20.083
N 250 X24.14 Z1.951
N 260 X84. Z4.
[thread line 18: 4 passes, pitch 2, depth 1.2]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 270 G1 X80. Z1.732 F0.2
N 280 G31 F2. U1.2 IC4 V1 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 290 G0 X80. Z0.
N 300 G1 X40. Z0.
N 310 G80
N 320 G0 X80. Z1.732
N 330 X120. Z50.
N 340 M5
N 350 M30
END
