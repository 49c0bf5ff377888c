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
1.4251 0.00242769
1.79621 0.00111346
3.21445 0.000707366
EOD
$d1 << EOD
33.7901 0.00357976
EOD
$d2 << EOD
7.68955 0.0048367
9.87728 0.00366557
15.2819 0.00133158
EOD
$d3 << EOD
194.109 0.0104176
EOD
$d4 << EOD
2.3158 0.00285931
2.99305 0.00172832
5.41185 0.000827662
EOD
$d5 << EOD
300.196 0.00381756
EOD
$d6 << EOD
26.55 0.0161552
34.3713 0.0107555
58.6366 0.00477581
EOD
$d7 << EOD
304.999 0.105084
EOD
plot $d0 with linespoints title 'office-x1 hierarchical', \
     $d1 with linespoints title 'office-x1 shooting', \
     $d2 with linespoints title 'office-x16 hierarchical', \
     $d3 with linespoints title 'office-x16 shooting', \
     $d4 with linespoints title 'office-x4 hierarchical', \
     $d5 with linespoints title 'office-x4 shooting', \
     $d6 with linespoints title 'office-x64 hierarchical', \
     $d7 with linespoints title 'office-x64 shooting'
