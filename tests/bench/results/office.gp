set terminal pngcairo size 1280,900 noenhanced
set output 'office.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
1.25 0.00207
1.787 0.00135
3.38 0.00043
EOD
$d1 << EOD
33.322 0.00347
EOD
$d2 << EOD
4.946 0.000923
5.898 0.000565
7.101 0.00065
EOD
$d3 << EOD
297.53 0.00352
EOD
$d4 << EOD
11.774 0.00255
16.402 0.00272
47.345 0.000447
EOD
$d5 << EOD
167.255 0.00873
EOD
$d6 << EOD
75.8 0.00286
101.054 0.00211
EOD
$d7 << EOD
725.275 0.0484
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x1 shooting', \
     $d2 with linespoints title 'office-x4 hierarchical', \
     $d3 with linespoints title 'office-x4 shooting', \
     $d4 with linespoints title 'office-x16 hierarchical', \
     $d5 with linespoints title 'office-x16 shooting', \
     $d6 with linespoints title 'office-x64 hierarchical', \
     $d7 with linespoints title 'office-x64 shooting'
