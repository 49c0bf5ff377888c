set terminal pngcairo size 1280,900 noenhanced
set output 'radiance-peer-two-rooms.png'
set logscale xy
set format xy '%g'
set grid
set key outside right top
set xlabel 'seconds'
set ylabel 'RMS relative error'
set title 'radiant-bench: error against time'
$d0 << EOD
5.43956 0.00133278
12.1114 0.0015486
35.1286 0.00186065
285.341 0.0017868
EOD
$d1 << EOD
0.286598 0.00742616
0.333082 0.00742616
0.529375 0.00401016
3.22322 0.00162351
EOD
$d2 << EOD
2.62555 0.0532057
5.12025 0.0243342
8.19548 0.00917895
15.0274 0.00897855
32.1557 0.00244664
99.0204 0.00200711
99.5966 0.0023049
EOD
plot $d0 with linespoints title 'two-rooms-doorway hierarchical', \
     $d1 with linespoints title 'two-rooms-doorway monte-carlo', \
     $d2 with linespoints title 'two-rooms-doorway radiance'
