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
1.18107 0.00209022
1.65024 0.001328
3.12842 0.000369799
EOD
$d1 << EOD
31.0226 0.00349228
EOD
$d2 << EOD
10.2698 0.00322382
14.9056 0.00166312
39.4741 0.00059031
EOD
$d3 << EOD
250.997 0.00977807
EOD
$d4 << EOD
4.52534 0.00097238
5.20426 0.000519858
6.26712 0.000776331
EOD
$d5 << EOD
298.611 0.00364711
EOD
$d6 << EOD
61.6877 0.00387932
79.2362 0.00356388
321.199 0.0021889
EOD
$d7 << EOD
303.562 0.103705
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x1 shooting', \
     $d2 with linespoints title 'office-x16 hierarchical', \
     $d3 with linespoints title 'office-x16 shooting', \
     $d4 with linespoints title 'office-x4 hierarchical', \
     $d5 with linespoints title 'office-x4 shooting', \
     $d6 with linespoints title 'office-x64 hierarchical', \
     $d7 with linespoints title 'office-x64 shooting'
