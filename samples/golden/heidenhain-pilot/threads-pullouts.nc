%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-PULLOUTS]
[T5 offset 5, first at CL line 4, 0:31.1]
[cycle time 0:31.1, 1 tool change]
[THREADS-PULLOUTS]
N 10 T5
N 20 G97 S800 M3
N 30 G0 X20. Z5.
[thread line 10: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 40 G1 X18.598 Z1.734 G95 F0.2
N 50 X15.08
N 60 G33 Z-19.734 F1.5
N 70 X18.08 Z-21.234 F1.5
N 80 G0 X18.598
[pass 2 depth 0.6505 rough]
N 90 Z1.624
N 100 G1 X14.699 F0.2
N 110 G33 Z-19.844 F1.5
N 120 X17.699 Z-21.344 F1.5
N 130 G0 X18.598
[pass 3 depth 0.7967 rough]
N 140 Z1.54
N 150 G1 X14.407 F0.2
N 160 G33 Z-19.929 F1.5
N 170 X17.407 Z-21.429 F1.5
N 180 G0 X18.598
[pass 4 depth 0.9200 rough]
N 190 Z1.469
N 200 G1 X14.16 F0.2
N 210 G33 Z-20. F1.5
N 220 X17.16 Z-21.5 F1.5
N 230 G0 X18.598
N 240 Z2.
N 250 X20. Z5.
[thread line 17: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 260 G1 X18.598 Z1.734 F0.2
N 270 X15.08
N 280 G33 Z-18.234 F1.5
N 290 X18.08 Z-19.734 F1.5
N 300 G0 X18.598
[pass 2 depth 0.6505 rough]
N 310 Z1.624
N 320 G1 X14.699 F0.2
N 330 G33 Z-18.344 F1.5
N 340 X17.699 Z-19.844 F1.5
N 350 G0 X18.598
[pass 3 depth 0.7967 rough]
N 360 Z1.54
N 370 G1 X14.407 F0.2
N 380 G33 Z-18.429 F1.5
N 390 X17.407 Z-19.929 F1.5
N 400 G0 X18.598
[pass 4 depth 0.9200 rough]
N 410 Z1.469
N 420 G1 X14.16 F0.2
N 430 G33 Z-18.5 F1.5
N 440 X17.16 Z-20. F1.5
N 450 G0 X18.598
N 460 Z2.
N 470 X20. Z5.
[thread line 24: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 480 G1 X18.598 Z1.734 F0.2
N 490 X15.08
N 500 G33 Z-19.734 F1.5
N 510 G1 X17.48 F0.2
N 520 G0 X18.598
[pass 2 depth 0.6505 rough]
N 530 Z1.624
N 540 G1 X14.699
N 550 G33 Z-19.844 F1.5
N 560 G1 X17.099 F0.2
N 570 G0 X18.598
[pass 3 depth 0.7967 rough]
N 580 Z1.54
N 590 G1 X14.407
N 600 G33 Z-19.929 F1.5
N 610 G1 X16.807 F0.2
N 620 G0 X18.598
[pass 4 depth 0.9200 rough]
N 630 Z1.469
N 640 G1 X14.16
N 650 G33 Z-20. F1.5
N 660 G1 X16.56 F0.2
N 670 G0 X18.598
N 680 Z2.
N 690 X20. Z5.
[thread line 31: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 700 G1 X18.598 Z1.734
N 710 X15.08
N 720 G33 Z-19.734 F1.5
N 730 X18.08 Z-20.734 F1.5
N 740 G0 X18.598
[pass 2 depth 0.6505 rough]
N 750 Z1.624
N 760 G1 X14.699 F0.2
N 770 G33 Z-19.844 F1.5
N 780 X17.699 Z-20.844 F1.5
N 790 G0 X18.598
[pass 3 depth 0.7967 rough]
N 800 Z1.54
N 810 G1 X14.407 F0.2
N 820 G33 Z-19.929 F1.5
N 830 X17.407 Z-20.929 F1.5
N 840 G0 X18.598
[pass 4 depth 0.9200 rough]
N 850 Z1.469
N 860 G1 X14.16 F0.2
N 870 G33 Z-20. F1.5
N 880 X17.16 Z-21. F1.5
N 890 G0 X18.598
N 900 Z2.
N 910 X20. Z5.
[thread line 39: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 920 G1 Z2. F0.2
N 930 G31 F1.5 U0.92 IC4 V0 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 940 G0 X16. Z2.
N 950 G1 X16. Z-20.
N 960 G80
N 970 G0 X20. Z2.
N 980 Z5.
[thread line 46: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 990 G1 Z2. G95 F0.2
N 1000 G31 F1.5 U0.92 IC4 V0 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 1010 G0 X16. Z2.
N 1020 G1 X16. Z-20.
N 1030 G80
N 1040 G0 X20. Z2.
N 1050 X100. Z50.
N 1060 M5
N 1070 M30
END
