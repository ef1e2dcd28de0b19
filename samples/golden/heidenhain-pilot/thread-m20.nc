%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program M20X2.5]
[T7 offset 7, first at CL line 4, 0:14.0]
[cycle time 0:14.0, 1 tool change]
[M20X2.5]
N 10 T7
N 20 G97 S600 M3
N 30 G26 S600
N 40 M8
N 50 G0 X30. Z5.
[thread line 11: 5 passes, pitch 2.5, depth 1.534]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.7170 rough]
N 60 X24.33 Z1.586
N 70 X18.566
N 80 G33 Z-29.528 F2.5
N 90 X23.566 Z-32.028 F2.5
N 100 G0 X24.33
[pass 2 depth 1.0140 rough]
N 110 Z1.415
N 120 X17.972
N 130 G33 Z-29.7 F2.5
N 140 X22.972 Z-32.2 F2.5
N 150 G0 X24.33
[pass 3 depth 1.2419 rough]
N 160 Z1.283
N 170 X17.516
N 180 G33 Z-29.831 F2.5
N 190 X22.516 Z-32.331 F2.5
N 200 G0 X24.33
[pass 4 depth 1.4340 rough]
N 210 Z1.172
N 220 X17.132
N 230 G33 Z-29.942 F2.5
N 240 X22.132 Z-32.442 F2.5
N 250 G0 X24.33
[pass 5 depth 1.5340 finish]
N 260 Z1.114
N 270 X16.932
N 280 G33 Z-30. F2.5
N 290 X21.932 Z-32.5 F2.5
N 300 G0 X24.33
N 310 Z2.
N 320 G1 X18.4 G95 F0.2
N 330 G33 Z-20. F1.5
N 340 G0 X30.
N 350 Z2.
N 360 X18.2
N 370 G33 Z-20. F1.5
N 380 X21.2 Z-21.5 F1.5
N 390 G0 X100. Z50.
N 400 M9
N 410 M5
N 420 M30
END
