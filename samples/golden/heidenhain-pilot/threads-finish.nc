%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-FINISH]
[T7 offset 7, first at CL line 5, 0:40.2]
[cycle time 0:40.2, 1 tool change]
[THREADS-FINISH]
N 10 T7
N 20 G97 S600 M3
N 30 G0 X24. Z5.
[thread line 11: 6 passes, pitch 2.5, depth 1.534]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.6263, plan 0.6413. G33 loop instead]
[pass 1 depth 0.6413 rough]
N 40 G1 X24.33 Z-0.37 G95 F0.2
N 50 X18.717
N 60 G33 Z-29.485 F2.5
N 70 G0 X24.33
[pass 2 depth 0.9069 rough]
N 80 Z-0.524
N 90 G1 X18.186 F0.2
N 100 G33 Z-29.638 F2.5
N 110 G0 X24.33
[pass 3 depth 1.1108 rough]
N 120 Z-0.641
N 130 G1 X17.778 F0.2
N 140 G33 Z-29.756 F2.5
N 150 G0 X24.33
[pass 4 depth 1.2826 rough]
N 160 Z-0.741
N 170 G1 X17.435 F0.2
N 180 G33 Z-29.855 F2.5
N 190 G0 X24.33
[pass 5 depth 1.4340 rough]
N 200 Z-0.828
N 210 G1 X17.132 F0.2
N 220 G33 Z-29.942 F2.5
N 230 G0 X24.33
[pass 6 depth 1.5340 finish]
N 240 Z-0.886
N 250 G1 X16.932 F0.2
N 260 G33 Z-30. F2.5
N 270 G0 X24.33
N 280 Z0.
N 290 X24. Z5.
[thread line 18: 7 passes, pitch 2.5, depth 1.534]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 300 G1 X24.33 Z0. F0.2
N 310 G31 F2.5 U1.534 IC5 V0 H1 A30. D1 Q2 C0. BD0 B0. P0. K0.
N 320 G0 X20. Z0.
N 330 G1 X20. Z-30.
N 340 G80
N 350 G0 X24.33 Z0.
N 360 X24. Z5.
[thread line 25: 7 passes, pitch 2.5, depth 1.534]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.2557, plan 0.2868. G33 loop instead]
[pass 1 depth 0.2868 rough]
N 370 G1 X24.33 Z-0.166 G95 F0.2
N 380 X19.426
N 390 G33 Z-29.28 F2.5
N 400 G0 X24.33
[pass 2 depth 0.5736 rough]
N 410 Z-0.331
N 420 G1 X18.853 F0.2
N 430 G33 Z-29.446 F2.5
N 440 G0 X24.33
[pass 3 depth 0.8604 rough]
N 450 Z-0.497
N 460 G1 X18.279 F0.2
N 470 G33 Z-29.611 F2.5
N 480 G0 X24.33
[pass 4 depth 1.1472 rough]
N 490 Z-0.662
N 500 G1 X17.706 F0.2
N 510 G33 Z-29.777 F2.5
N 520 G0 X24.33
[pass 5 depth 1.4340 rough]
N 530 Z-0.828
N 540 G1 X17.132 F0.2
N 550 G33 Z-29.942 F2.5
N 560 G0 X24.33
[pass 6 depth 1.5340 finish]
N 570 Z-0.886
N 580 G1 X16.932 F0.2
N 590 G33 Z-30. F2.5
N 600 G0 X24.33
[pass 7 depth 1.5340 spring]
N 610 Z-0.886
N 620 G1 X16.932 F0.2
N 630 G33 Z-30. F2.5
N 640 G0 X24.33
N 650 Z0.
N 660 X24. Z5.
[thread line 32: 8 passes, pitch 2.5, depth 1.534]
[G31 not used: G31 has no finish allowance, FINCUT: pass 1: depth 0.1918, plan 0.3000. G33 loop instead]
[pass 1 depth 0.3000 rough]
N 670 G1 X24.33 Z-0.173 F0.2
N 680 X19.4
N 690 G33 Z-29.288 F2.5
N 700 G0 X24.33
[pass 2 depth 0.6000 rough]
N 710 Z-0.346
N 720 G1 X18.8 F0.2
N 730 G33 Z-29.461 F2.5
N 740 G0 X24.33
[pass 3 depth 0.9000 rough]
N 750 Z-0.52
N 760 G1 X18.2 F0.2
N 770 G33 Z-29.634 F2.5
N 780 G0 X24.33
[pass 4 depth 1.0500 rough]
N 790 Z-0.606
N 800 G1 X17.9 F0.2
N 810 G33 Z-29.721 F2.5
N 820 G0 X24.33
[pass 5 depth 1.2000 rough]
N 830 Z-0.693
N 840 G1 X17.6 F0.2
N 850 G33 Z-29.807 F2.5
N 860 G0 X24.33
[pass 6 depth 1.3500 rough]
N 870 Z-0.779
N 880 G1 X17.3 F0.2
N 890 G33 Z-29.894 F2.5
N 900 G0 X24.33
[pass 7 depth 1.5000 rough]
N 910 Z-0.866
N 920 G1 X17. F0.2
N 930 G33 Z-29.98 F2.5
N 940 G0 X24.33
[pass 8 depth 1.5340 finish]
N 950 Z-0.886
N 960 G1 X16.932 F0.2
N 970 G33 Z-30. F2.5
N 980 G0 X24.33
N 990 Z0.
N 1000 X24. Z5.
[thread line 39: 1 passes, pitch 2.5, depth 0.3]
[G31 not used: G31 has no infeed type for OPTION 0, steps decreasing by a constant amount. G33 loop instead]
[pass 1 depth 0.3000 rough]
N 1010 G1 X24.33 Z0. F0.2
N 1020 X19.4
N 1030 G33 Z-30. F2.5
N 1040 G0 X24.33
N 1050 Z0.
N 1060 X100. Z50.
N 1070 M5
N 1080 M30
END
