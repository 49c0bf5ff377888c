set terminal pngcairo size 1280,900 noenhanced
set output 'office-x64-long.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
78.6796 0.00286328
EOD
$d1 << EOD
1504.65 0.0457463
EOD
plot $d0 with linespoints title 'office-x64 hierarchical', \
     $d1 with linespoints title 'office-x64 shooting'
