%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-PULLOUTS]
[T5 offset 5, first at CL line 4, 0:31.1]
[cycle time 0:31.1, 1 tool change]
[THREADS-PULLOUTS]
N 10 T5
N 20 G97 S800 M3
N 30 G26 S800
N 40 G0 X20. Z5.
[thread line 10: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 50 G1 X18.598 Z1.734 G95 F0.2
N 60 X15.08
N 70 G33 Z-19.734 F1.5
N 80 X18.08 Z-21.234 F1.5
N 90 G0 X18.598
[pass 2 depth 0.6505 rough]
N 100 Z1.624
N 110 G1 X14.699 F0.2
N 120 G33 Z-19.844 F1.5
N 130 X17.699 Z-21.344 F1.5
N 140 G0 X18.598
[pass 3 depth 0.7967 rough]
N 150 Z1.54
N 160 G1 X14.407 F0.2
N 170 G33 Z-19.929 F1.5
N 180 X17.407 Z-21.429 F1.5
N 190 G0 X18.598
[pass 4 depth 0.9200 rough]
N 200 Z1.469
N 210 G1 X14.16 F0.2
N 220 G33 Z-20. F1.5
N 230 X17.16 Z-21.5 F1.5
N 240 G0 X18.598
N 250 Z2.
N 260 X20. Z5.
[thread line 17: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 270 G1 X18.598 Z1.734 F0.2
N 280 X15.08
N 290 G33 Z-18.234 F1.5
N 300 X18.08 Z-19.734 F1.5
N 310 G0 X18.598
[pass 2 depth 0.6505 rough]
N 320 Z1.624
N 330 G1 X14.699 F0.2
N 340 G33 Z-18.344 F1.5
N 350 X17.699 Z-19.844 F1.5
N 360 G0 X18.598
[pass 3 depth 0.7967 rough]
N 370 Z1.54
N 380 G1 X14.407 F0.2
N 390 G33 Z-18.429 F1.5
N 400 X17.407 Z-19.929 F1.5
N 410 G0 X18.598
[pass 4 depth 0.9200 rough]
N 420 Z1.469
N 430 G1 X14.16 F0.2
N 440 G33 Z-18.5 F1.5
N 450 X17.16 Z-20. F1.5
N 460 G0 X18.598
N 470 Z2.
N 480 X20. Z5.
[thread line 24: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 490 G1 X18.598 Z1.734 F0.2
N 500 X15.08
N 510 G33 Z-19.734 F1.5
N 520 G1 X17.48 F0.2
N 530 G0 X18.598
[pass 2 depth 0.6505 rough]
N 540 Z1.624
N 550 G1 X14.699
N 560 G33 Z-19.844 F1.5
N 570 G1 X17.099 F0.2
N 580 G0 X18.598
[pass 3 depth 0.7967 rough]
N 590 Z1.54
N 600 G1 X14.407
N 610 G33 Z-19.929 F1.5
N 620 G1 X16.807 F0.2
N 630 G0 X18.598
[pass 4 depth 0.9200 rough]
N 640 Z1.469
N 650 G1 X14.16
N 660 G33 Z-20. F1.5
N 670 G1 X16.56 F0.2
N 680 G0 X18.598
N 690 Z2.
N 700 X20. Z5.
[thread line 31: 4 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's run-out K geometry is not documented; the plan has a pull-out. G33 loop instead]
[pass 1 depth 0.4600 rough]
N 710 G1 X18.598 Z1.734
N 720 X15.08
N 730 G33 Z-19.734 F1.5
N 740 X18.08 Z-20.734 F1.5
N 750 G0 X18.598
[pass 2 depth 0.6505 rough]
N 760 Z1.624
N 770 G1 X14.699 F0.2
N 780 G33 Z-19.844 F1.5
N 790 X17.699 Z-20.844 F1.5
N 800 G0 X18.598
[pass 3 depth 0.7967 rough]
N 810 Z1.54
N 820 G1 X14.407 F0.2
N 830 G33 Z-19.929 F1.5
N 840 X17.407 Z-20.929 F1.5
N 850 G0 X18.598
[pass 4 depth 0.9200 rough]
N 860 Z1.469
N 870 G1 X14.16 F0.2
N 880 G33 Z-20. F1.5
N 890 X17.16 Z-21. F1.5
N 900 G0 X18.598
N 910 Z2.
N 920 X20. Z5.
[thread line 39: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 930 G1 Z2. F0.2
N 940 G31 F1.5 U0.92 IC4 V0 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 950 G0 X16. Z2.
N 960 G1 X16. Z-20.
N 970 G80
N 980 G0 X20. Z2.
N 990 Z5.
[thread line 46: 4 passes, pitch 1.5, depth 0.92]
[G31 infeed law and flank offsets as clpost assumes them, unverified]
N 1000 G1 Z2. G95 F0.2
N 1010 G31 F1.5 U0.92 IC4 V0 H1 A30. D1 Q0 C0. BD0 B0. P0. K0.
N 1020 G0 X16. Z2.
N 1030 G1 X16. Z-20.
N 1040 G80
N 1050 G0 X20. Z2.
N 1060 X100. Z50.
N 1070 M5
N 1080 M30
END
