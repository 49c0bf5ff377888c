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
1.12203 0.00245686
1.72958 0.00108134
3.69367 0.00063297
EOD
$d1 << EOD
33.9688 0.00360739
EOD
$d2 << EOD
7.92726 0.00465677
9.51545 0.00389582
14.8503 0.00122454
EOD
$d3 << EOD
209.52 0.0104841
EOD
$d4 << EOD
2.91314 0.00284799
3.78042 0.00165021
5.77178 0.000837635
EOD
$d5 << EOD
300.207 0.00378518
EOD
$d6 << EOD
29.1051 0.0162913
36.4383 0.0109773
60.3145 0.00456955
EOD
$d7 << EOD
304.784 0.105612
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x1 shooting', \
     $d2 with linespoints title 'office-x16 hierarchical', \
     $d3 with linespoints title 'office-x16 shooting', \
     $d4 with linespoints title 'office-x4 hierarchical', \
     $d5 with linespoints title 'office-x4 shooting', \
     $d6 with linespoints title 'office-x64 hierarchical', \
     $d7 with linespoints title 'office-x64 shooting'
