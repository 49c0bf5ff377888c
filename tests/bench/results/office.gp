set terminal pngcairo size 1280,900 noenhanced
set output 'tests/bench/results/office.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
1.53456 0.00246421
2.1483 0.00116099
4.54566 0.000679479
EOD
$d1 << EOD
41.6995 0.00358444
EOD
$d2 << EOD
8.51639 0.00499808
10.3723 0.00372016
16.6541 0.00132274
EOD
$d3 << EOD
215.67 0.010439
EOD
$d4 << EOD
2.96708 0.00294999
3.73208 0.00174709
6.88335 0.000828661
EOD
$d5 << EOD
300.169 0.00382037
EOD
$d6 << EOD
27.3564 0.0162825
34.7395 0.0108294
55.1649 0.0047962
EOD
$d7 << EOD
304.619 0.105695
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x1 shooting', \
     $d2 with linespoints title 'office-x16 hierarchical', \
     $d3 with linespoints title 'office-x16 shooting', \
     $d4 with linespoints title 'office-x4 hierarchical', \
     $d5 with linespoints title 'office-x4 shooting', \
     $d6 with linespoints title 'office-x64 hierarchical', \
     $d7 with linespoints title 'office-x64 shooting'
