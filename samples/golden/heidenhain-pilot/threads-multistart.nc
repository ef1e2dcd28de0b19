%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-MULTISTART]
[T5 offset 5, first at CL line 5, 0:29.7]
[cycle time 0:29.7, 1 tool change]
[THREADS-MULTISTART]
N 10 T5
N 20 G97 S400 M3
N 30 G0 X30. Z6.
[thread line 10: 8 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's multi-start order and spacing, D and C, are not documented; the thread has 2 starts. G33 loop instead]
[pass 1 start 1 depth 0.4600 rough]
N 40 G1 X26.598 Z-0.266 G95 F0.2
N 50 X23.08
N 60 G33 Z-24.734 F3.
N 70 G0 X26.598
[pass 1 start 2 depth 0.4600 rough]
N 80 Z1.234
N 90 G1 X23.08 F0.2
N 100 G33 Z-24.734 F3.
N 110 G0 X26.598
[pass 2 start 1 depth 0.6505 rough]
N 120 Z-0.376
N 130 G1 X22.699 F0.2
N 140 G33 Z-24.844 F3.
N 150 G0 X26.598
[pass 2 start 2 depth 0.6505 rough]
N 160 Z1.124
N 170 G1 X22.699 F0.2
N 180 G33 Z-24.844 F3.
N 190 G0 X26.598
[pass 3 start 1 depth 0.7967 rough]
N 200 Z-0.46
N 210 G1 X22.407 F0.2
N 220 G33 Z-24.929 F3.
N 230 G0 X26.598
[pass 3 start 2 depth 0.7967 rough]
N 240 Z1.04
N 250 G1 X22.407 F0.2
N 260 G33 Z-24.929 F3.
N 270 G0 X26.598
[pass 4 start 1 depth 0.9200 rough]
N 280 Z-0.531
N 290 G1 X22.16 F0.2
N 300 G33 Z-25. F3.
N 310 G0 X26.598
[pass 4 start 2 depth 0.9200 rough]
N 320 Z0.969
N 330 G1 X22.16 F0.2
N 340 G33 Z-25. F3.
N 350 G0 X26.598
N 360 Z0.
N 370 X30. Z6.
[thread line 16: 12 passes, pitch 1, depth 0.613]
[G31 not used: G31's multi-start order and spacing, D and C, are not documented; the thread has 3 starts. G33 loop instead]
[pass 1 start 1 depth 0.1877 rough]
N 380 G1 X25.732 Z-0.108 F0.2
N 390 X23.625
N 400 G33 Z-24.754 F3.
N 410 G0 X25.732
[pass 1 start 2 depth 0.1877 rough]
N 420 Z0.892
N 430 G1 X23.625 F0.2
N 440 G33 Z-24.754 F3.
N 450 G0 X25.732
[pass 1 start 3 depth 0.1877 rough]
N 460 Z1.892
N 470 G1 X23.625 F0.2
N 480 G33 Z-24.754 F3.
N 490 G0 X25.732
[pass 2 start 1 depth 0.3753 rough]
N 500 Z-0.217
N 510 G1 X23.249 F0.2
N 520 G33 Z-24.863 F3.
N 530 G0 X25.732
[pass 2 start 2 depth 0.3753 rough]
N 540 Z0.783
N 550 G1 X23.249 F0.2
N 560 G33 Z-24.863 F3.
N 570 G0 X25.732
[pass 2 start 3 depth 0.3753 rough]
N 580 Z1.783
N 590 G1 X23.249 F0.2
N 600 G33 Z-24.863 F3.
N 610 G0 X25.732
[pass 3 start 1 depth 0.5630 rough]
N 620 Z-0.325
N 630 G1 X22.874 F0.2
N 640 G33 Z-24.971 F3.
N 650 G0 X25.732
[pass 3 start 2 depth 0.5630 rough]
N 660 Z0.675
N 670 G1 X22.874 F0.2
N 680 G33 Z-24.971 F3.
N 690 G0 X25.732
[pass 3 start 3 depth 0.5630 rough]
N 700 Z1.675
N 710 G1 X22.874 F0.2
N 720 G33 Z-24.971 F3.
N 730 G0 X25.732
[pass 4 start 1 depth 0.6130 finish]
N 740 Z-0.354
N 750 G1 X22.774 F0.2
N 760 G33 Z-25. F3.
N 770 G0 X25.732
[pass 4 start 2 depth 0.6130 finish]
N 780 Z0.646
N 790 G1 X22.774 F0.2
N 800 G33 Z-25. F3.
N 810 G0 X25.732
[pass 4 start 3 depth 0.6130 finish]
N 820 Z1.646
N 830 G1 X22.774 F0.2
N 840 G33 Z-25. F3.
N 850 G0 X25.732
N 860 Z0.
N 870 X100. Z50.
N 880 M5
N 890 M30
END
