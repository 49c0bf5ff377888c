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
0.989913 0.00238825
1.50772 0.00111645
2.86002 0.000668879
EOD
$d1 << EOD
31.1694 0.00360961
EOD
$d2 << EOD
7.4482 0.00468618
8.77211 0.00387303
14.1984 0.00123423
EOD
$d3 << EOD
187.806 0.0104806
EOD
$d4 << EOD
1.92388 0.00288718
2.57753 0.00165608
4.41478 0.00083843
EOD
$d5 << EOD
300.14 0.00378121
EOD
$d6 << EOD
25.0388 0.0161542
31.7534 0.0109903
52.2986 0.00452275
EOD
$d7 << EOD
304.212 0.103941
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x1 shooting', \
     $d2 with linespoints title 'office-x16 hierarchical', \
     $d3 with linespoints title 'office-x16 shooting', \
     $d4 with linespoints title 'office-x4 hierarchical', \
     $d5 with linespoints title 'office-x4 shooting', \
     $d6 with linespoints title 'office-x64 hierarchical', \
     $d7 with linespoints title 'office-x64 shooting'
