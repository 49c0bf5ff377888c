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
0.436948 0.000640155
1.11882 0.000830725
2.30948 0.00141504
19.7151 0.00130908
EOD
$d1 << EOD
0.0339642 0.00685215
0.0425212 0.00685215
0.0533043 0.00432911
0.338124 0.00161976
EOD
$d2 << EOD
0.186485 0.0530322
0.364402 0.0249809
0.605291 0.00876505
1.11866 0.00921523
2.22007 0.00226429
6.9946 0.00181095
9.0721 0.00204131
EOD
plot $d0 with linespoints title 'two-rooms-doorway hierarchical', \
     $d1 with linespoints title 'two-rooms-doorway monte-carlo', \
     $d2 with linespoints title 'two-rooms-doorway radiance'
