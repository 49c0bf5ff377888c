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
0.389472 0.00107397
0.959761 0.00135642
2.30421 0.000599895
5.61994 0.000618858
EOD
$d1 << EOD
0.00890939 0.0239056
0.0155978 0.00774209
0.0490007 0.00349635
0.287132 0.00184494
EOD
$d2 << EOD
0.155242 0.0529
0.31897 0.0259585
0.541147 0.00948684
0.959792 0.00878759
1.93863 0.00258977
5.69441 0.00258526
5.86631 0.00204221
EOD
plot $d0 with linespoints title 'two-rooms-doorway hierarchical', \
     $d1 with linespoints title 'two-rooms-doorway monte-carlo', \
     $d2 with linespoints title 'two-rooms-doorway radiance'
