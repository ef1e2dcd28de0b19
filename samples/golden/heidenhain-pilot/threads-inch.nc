%1.nc
[INCH]
MACHINING
[machine heidenhain-pilot, program THREADS-INCH]
[T5 offset 5, first at CL line 5, 0:13.1]
[cycle time 0:13.1, 1 tool change]
[THREADS-INCH]
N 10 T5
N 20 G97 S700 M3
N 30 G0 X0.7 Z0.2
[thread line 10: 5 passes, pitch 0.0769231, depth 0.0472]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 40 G1 X0.6332 Z0.1 G95 F0.008
N 50 G31 F0.076923 U0.0472 IC5 V0 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 60 G0 X0.5 Z0.1
N 70 G1 X0.5 Z-0.75
N 80 G80
N 90 G0 X0.6332 Z0.1
N 100 X1. Z0.2
[thread line 16: 7 passes, pitch 0.1, depth 0.0613]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.0238 rough]
N 110 G1 X0.9232 Z0.0863 G95 F0.008
N 120 X0.7024
N 130 G33 Z-0.9783 F0.1
N 140 X0.9024 Z-1.0783 F0.1
N 150 G0 X0.9232
[pass 2 depth 0.0337 rough]
N 160 Z0.0806
N 170 G1 X0.6827 F0.008
N 180 G33 Z-0.984 F0.1
N 190 X0.8827 Z-1.084 F0.1
N 200 G0 X0.9232
[pass 3 depth 0.0412 rough]
N 210 Z0.0762
N 220 G1 X0.6676 F0.008
N 230 G33 Z-0.9884 F0.1
N 240 X0.8676 Z-1.0884 F0.1
N 250 G0 X0.9232
[pass 4 depth 0.0476 rough]
N 260 Z0.0725
N 270 G1 X0.6548 F0.008
N 280 G33 Z-0.9921 F0.1
N 290 X0.8548 Z-1.0921 F0.1
N 300 G0 X0.9232
[pass 5 depth 0.0532 rough]
N 310 Z0.0693
N 320 G1 X0.6436 F0.008
N 330 G33 Z-0.9953 F0.1
N 340 X0.8436 Z-1.0953 F0.1
N 350 G0 X0.9232
[pass 6 depth 0.0583 rough]
N 360 Z0.0663
N 370 G1 X0.6334 F0.008
N 380 G33 Z-0.9983 F0.1
N 390 X0.8334 Z-1.0983 F0.1
N 400 G0 X0.9232
[pass 7 depth 0.0613 finish]
N 410 Z0.0646
N 420 G1 X0.6274 F0.008
N 430 G33 Z-1. F0.1
N 440 X0.8274 Z-1.1 F0.1
N 450 G0 X0.9232
N 460 Z0.1
N 470 X4. Z2.
N 480 M5
N 490 M30
END
