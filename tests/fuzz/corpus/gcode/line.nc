(spifit: the line-test tool path A-B-C-D-E of thesis 4.1.1 as G-code, tool TIP coordinates, mm)
(z = 0 is the sheet's initial top surface; A -> B -> C -> D -> E)
%
N10 G21 G90 G17
N20 G00 X-50 Y0 Z0      (A: first touch)
N30 G01 Z-5 F600        (B: 5 mm depth, 10 mm/s)
N40 G01 X50             (C)
N50 G01 Z-10            (D: 10 mm depth)
N60 G01 X-50            (E)
N70 M30
%
