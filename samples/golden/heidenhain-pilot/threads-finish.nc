%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-FINISH]
[T7 offset 7, first at CL line 5, 0:40.2]
[cycle time 0:40.2, 1 tool change]
[THREADS-FINISH]
N 10 T7
N 20 G97 S600 M3
N 30 G26 S600
N 40 G0 X24. Z5.
[thread line 11: 6 passes, pitch 2.5, depth 1.534]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.6263, plan 0.6413. G33 loop instead]
[pass 1 depth 0.6413 rough]
N 50 G1 X24.33 Z-0.37 G95 F0.2
N 60 X18.717
N 70 G33 Z-29.485 F2.5
N 80 G0 X24.33
[pass 2 depth 0.9069 rough]
N 90 Z-0.524
N 100 G1 X18.186 F0.2
N 110 G33 Z-29.638 F2.5
N 120 G0 X24.33
[pass 3 depth 1.1108 rough]
N 130 Z-0.641
N 140 G1 X17.778 F0.2
N 150 G33 Z-29.756 F2.5
N 160 G0 X24.33
[pass 4 depth 1.2826 rough]
N 170 Z-0.741
N 180 G1 X17.435 F0.2
N 190 G33 Z-29.855 F2.5
N 200 G0 X24.33
[pass 5 depth 1.4340 rough]
N 210 Z-0.828
N 220 G1 X17.132 F0.2
N 230 G33 Z-29.942 F2.5
N 240 G0 X24.33
[pass 6 depth 1.5340 finish]
N 250 Z-0.886
N 260 G1 X16.932 F0.2
N 270 G33 Z-30. F2.5
N 280 G0 X24.33
N 290 Z0.
N 300 X24. Z5.
[thread line 18: 7 passes, pitch 2.5, depth 1.534]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 310 G1 X24.33 Z0. F0.2
N 320 G31 F2.5 U1.534 IC5 V0 H1 A30. D1 Q2 C0. BD0 B0. P0. K0.
N 330 G0 X20. Z0.
N 340 G1 X20. Z-30.
N 350 G80
N 360 G0 X24.33 Z0.
N 370 X24. Z5.
[thread line 25: 7 passes, pitch 2.5, depth 1.534]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.2557, plan 0.2868. G33 loop instead]
[pass 1 depth 0.2868 rough]
N 380 G1 X24.33 Z-0.166 G95 F0.2
N 390 X19.426
N 400 G33 Z-29.28 F2.5
N 410 G0 X24.33
[pass 2 depth 0.5736 rough]
N 420 Z-0.331
N 430 G1 X18.853 F0.2
N 440 G33 Z-29.446 F2.5
N 450 G0 X24.33
[pass 3 depth 0.8604 rough]
N 460 Z-0.497
N 470 G1 X18.279 F0.2
N 480 G33 Z-29.611 F2.5
N 490 G0 X24.33
[pass 4 depth 1.1472 rough]
N 500 Z-0.662
N 510 G1 X17.706 F0.2
N 520 G33 Z-29.777 F2.5
N 530 G0 X24.33
[pass 5 depth 1.4340 rough]
N 540 Z-0.828
N 550 G1 X17.132 F0.2
N 560 G33 Z-29.942 F2.5
N 570 G0 X24.33
[pass 6 depth 1.5340 finish]
N 580 Z-0.886
N 590 G1 X16.932 F0.2
N 600 G33 Z-30. F2.5
N 610 G0 X24.33
[pass 7 depth 1.5340 spring]
N 620 Z-0.886
N 630 G1 X16.932 F0.2
N 640 G33 Z-30. F2.5
N 650 G0 X24.33
N 660 Z0.
N 670 X24. Z5.
[thread line 32: 8 passes, pitch 2.5, depth 1.534]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.1918, plan 0.3000. G33 loop instead]
[pass 1 depth 0.3000 rough]
N 680 G1 X24.33 Z-0.173 F0.2
N 690 X19.4
N 700 G33 Z-29.288 F2.5
N 710 G0 X24.33
[pass 2 depth 0.6000 rough]
N 720 Z-0.346
N 730 G1 X18.8 F0.2
N 740 G33 Z-29.461 F2.5
N 750 G0 X24.33
[pass 3 depth 0.9000 rough]
N 760 Z-0.52
N 770 G1 X18.2 F0.2
N 780 G33 Z-29.634 F2.5
N 790 G0 X24.33
[pass 4 depth 1.0500 rough]
N 800 Z-0.606
N 810 G1 X17.9 F0.2
N 820 G33 Z-29.721 F2.5
N 830 G0 X24.33
[pass 5 depth 1.2000 rough]
N 840 Z-0.693
N 850 G1 X17.6 F0.2
N 860 G33 Z-29.807 F2.5
N 870 G0 X24.33
[pass 6 depth 1.3500 rough]
N 880 Z-0.779
N 890 G1 X17.3 F0.2
N 900 G33 Z-29.894 F2.5
N 910 G0 X24.33
[pass 7 depth 1.5000 rough]
N 920 Z-0.866
N 930 G1 X17. F0.2
N 940 G33 Z-29.98 F2.5
N 950 G0 X24.33
[pass 8 depth 1.5340 finish]
N 960 Z-0.886
N 970 G1 X16.932 F0.2
N 980 G33 Z-30. F2.5
N 990 G0 X24.33
N 1000 Z0.
N 1010 X24. Z5.
[thread line 39: 1 passes, pitch 2.5, depth 0.3]
[G31 not used: G31 has no infeed type for OPTION 0, steps decreasing by a constant amount. G33 loop instead]
[pass 1 depth 0.3000 rough]
N 1020 G1 X24.33 Z0. F0.2
N 1030 X19.4
N 1040 G33 Z-30. F2.5
N 1050 G0 X24.33
N 1060 Z0.
N 1070 X100. Z50.
N 1080 M5
N 1090 M30
END
