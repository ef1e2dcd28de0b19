%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program M20X2.5]
[T7 offset 7, first at CL line 4, 0:14.0]
[cycle time 0:14.0, 1 tool change]
[M20X2.5]
N 10 T7
N 20 G97 S600 M3
N 30 M8
N 40 G0 X30. Z5.
[thread line 11: 5 passes, pitch 2.5, depth 1.534]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.7170 rough]
N 50 X24.33 Z1.586
N 60 X18.566
N 70 G33 Z-29.528 F2.5
N 80 X23.566 Z-32.028 F2.5
N 90 G0 X24.33
[pass 2 depth 1.0140 rough]
N 100 Z1.415
N 110 X17.972
N 120 G33 Z-29.7 F2.5
N 130 X22.972 Z-32.2 F2.5
N 140 G0 X24.33
[pass 3 depth 1.2419 rough]
N 150 Z1.283
N 160 X17.516
N 170 G33 Z-29.831 F2.5
N 180 X22.516 Z-32.331 F2.5
N 190 G0 X24.33
[pass 4 depth 1.4340 rough]
N 200 Z1.172
N 210 X17.132
N 220 G33 Z-29.942 F2.5
N 230 X22.132 Z-32.442 F2.5
N 240 G0 X24.33
[pass 5 depth 1.5340 finish]
N 250 Z1.114
N 260 X16.932
N 270 G33 Z-30. F2.5
N 280 X21.932 Z-32.5 F2.5
N 290 G0 X24.33
N 300 Z2.
N 310 G1 X18.4 G95 F0.2
N 320 G33 Z-20. F1.5
N 330 G0 X30.
N 340 Z2.
N 350 X18.2
N 360 G33 Z-20. F1.5
N 370 X21.2 Z-21.5 F1.5
N 380 G0 X100. Z50.
N 390 M9
N 400 M5
N 410 M30
END
