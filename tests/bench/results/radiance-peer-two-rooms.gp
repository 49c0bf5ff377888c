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
0.402475 0.00107397
0.961566 0.00135642
2.22682 0.000599895
5.78287 0.000618858
EOD
$d1 << EOD
0.0163511 0.0211041
0.0184515 0.00745096
0.046252 0.00419018
0.297861 0.00179739
EOD
$d2 << EOD
0.159879 0.0540335
0.326371 0.0261651
0.539634 0.00941661
0.973291 0.00865608
2.02675 0.00258647
5.94078 0.00253523
6.175 0.00209179
EOD
plot $d0 with linespoints title 'two-rooms-doorway hierarchical', \
     $d1 with linespoints title 'two-rooms-doorway monte-carlo', \
     $d2 with linespoints title 'two-rooms-doorway radiance'
