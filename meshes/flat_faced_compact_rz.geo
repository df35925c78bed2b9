// Axisymmetric (r-z) powder compact in a flat-faced die, SI units.
// Physical ids match fem/tablet_geometry.h: axis 0, die wall 1,
// lower punch 2, upper punch 3; the compact itself is surface 10.
D  = 10e-3;   // die diameter [m]
H  = 8e-3;    // fill height [m]
lc = D / 16;  // target element size [m]

Point(1) = {0,   0, 0, lc};
Point(2) = {D/2, 0, 0, lc};
Point(3) = {D/2, H, 0, lc};
Point(4) = {0,   H, 0, lc};
Line(1) = {1, 2};  // lower punch
Line(2) = {2, 3};  // die wall
Line(3) = {3, 4};  // upper punch
Line(4) = {4, 1};  // axis
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
Recombine Surface{1};

Physical Curve(0) = {4};
Physical Curve(1) = {2};
Physical Curve(2) = {1};
Physical Curve(3) = {3};
Physical Surface(10) = {1};
