%1.nc
[METRIC]
MACHINING
[machine heidenhain-pilot, program THREADS-MULTISTART]
[T5 offset 5, first at CL line 5, 0:29.7]
[cycle time 0:29.7, 1 tool change]
[THREADS-MULTISTART]
N 10 T5
N 20 G97 S400 M3
N 30 G26 S400
N 40 G0 X30. Z6.
[thread line 10: 8 passes, pitch 1.5, depth 0.92]
[G31 not used: G31's multi-start order and spacing, D and C, are not documented; the thread has 2 starts. G33 loop instead]
[pass 1 start 1 depth 0.4600 rough]
N 50 G1 X26.598 Z-0.266 G95 F0.2
N 60 X23.08
N 70 G33 Z-24.734 F3.
N 80 G0 X26.598
[pass 1 start 2 depth 0.4600 rough]
N 90 Z1.234
N 100 G1 X23.08 F0.2
N 110 G33 Z-24.734 F3.
N 120 G0 X26.598
[pass 2 start 1 depth 0.6505 rough]
N 130 Z-0.376
N 140 G1 X22.699 F0.2
N 150 G33 Z-24.844 F3.
N 160 G0 X26.598
[pass 2 start 2 depth 0.6505 rough]
N 170 Z1.124
N 180 G1 X22.699 F0.2
N 190 G33 Z-24.844 F3.
N 200 G0 X26.598
[pass 3 start 1 depth 0.7967 rough]
N 210 Z-0.46
N 220 G1 X22.407 F0.2
N 230 G33 Z-24.929 F3.
N 240 G0 X26.598
[pass 3 start 2 depth 0.7967 rough]
N 250 Z1.04
N 260 G1 X22.407 F0.2
N 270 G33 Z-24.929 F3.
N 280 G0 X26.598
[pass 4 start 1 depth 0.9200 rough]
N 290 Z-0.531
N 300 G1 X22.16 F0.2
N 310 G33 Z-25. F3.
N 320 G0 X26.598
[pass 4 start 2 depth 0.9200 rough]
N 330 Z0.969
N 340 G1 X22.16 F0.2
N 350 G33 Z-25. F3.
N 360 G0 X26.598
N 370 Z0.
N 380 X30. Z6.
[thread line 16: 12 passes, pitch 1, depth 0.613]
[G31 not used: G31's multi-start order and spacing, D and C, are not documented; the thread has 3 starts. G33 loop instead]
[pass 1 start 1 depth 0.1877 rough]
N 390 G1 X25.732 Z-0.108 F0.2
N 400 X23.625
N 410 G33 Z-24.754 F3.
N 420 G0 X25.732
[pass 1 start 2 depth 0.1877 rough]
N 430 Z0.892
N 440 G1 X23.625 F0.2
N 450 G33 Z-24.754 F3.
N 460 G0 X25.732
[pass 1 start 3 depth 0.1877 rough]
N 470 Z1.892
N 480 G1 X23.625 F0.2
N 490 G33 Z-24.754 F3.
N 500 G0 X25.732
[pass 2 start 1 depth 0.3753 rough]
N 510 Z-0.217
N 520 G1 X23.249 F0.2
N 530 G33 Z-24.863 F3.
N 540 G0 X25.732
[pass 2 start 2 depth 0.3753 rough]
N 550 Z0.783
N 560 G1 X23.249 F0.2
N 570 G33 Z-24.863 F3.
N 580 G0 X25.732
[pass 2 start 3 depth 0.3753 rough]
N 590 Z1.783
N 600 G1 X23.249 F0.2
N 610 G33 Z-24.863 F3.
N 620 G0 X25.732
[pass 3 start 1 depth 0.5630 rough]
N 630 Z-0.325
N 640 G1 X22.874 F0.2
N 650 G33 Z-24.971 F3.
N 660 G0 X25.732
[pass 3 start 2 depth 0.5630 rough]
N 670 Z0.675
N 680 G1 X22.874 F0.2
N 690 G33 Z-24.971 F3.
N 700 G0 X25.732
[pass 3 start 3 depth 0.5630 rough]
N 710 Z1.675
N 720 G1 X22.874 F0.2
N 730 G33 Z-24.971 F3.
N 740 G0 X25.732
[pass 4 start 1 depth 0.6130 finish]
N 750 Z-0.354
N 760 G1 X22.774 F0.2
N 770 G33 Z-25. F3.
N 780 G0 X25.732
[pass 4 start 2 depth 0.6130 finish]
N 790 Z0.646
N 800 G1 X22.774 F0.2
N 810 G33 Z-25. F3.
N 820 G0 X25.732
[pass 4 start 3 depth 0.6130 finish]
N 830 Z1.646
N 840 G1 X22.774 F0.2
N 850 G33 Z-25. F3.
N 860 G0 X25.732
N 870 Z0.
N 880 X100. Z50.
N 890 M5
N 900 M30
END
