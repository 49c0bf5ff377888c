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
1.16828 0.00245686
1.81254 0.00108134
3.471 0.00063297
EOD
$d1 << EOD
32.9759 0.00360739
EOD
$d2 << EOD
9.00865 0.00389582
13.0634 0.00237429
34.1619 0.000796317
EOD
$d3 << EOD
185.068 0.0104841
EOD
$d4 << EOD
4.184 0.0017347
4.53666 0.00108752
5.49811 0.00131772
EOD
$d5 << EOD
300.127 0.00371906
EOD
$d6 << EOD
57.5252 0.00549799
75.8276 0.00368404
151.112 0.00254929
EOD
$d7 << EOD
304.291 0.103866
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x1 shooting', \
     $d2 with linespoints title 'office-x16 hierarchical', \
     $d3 with linespoints title 'office-x16 shooting', \
     $d4 with linespoints title 'office-x4 hierarchical', \
     $d5 with linespoints title 'office-x4 shooting', \
     $d6 with linespoints title 'office-x64 hierarchical', \
     $d7 with linespoints title 'office-x64 shooting'
