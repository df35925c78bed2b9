// Axisymmetric (r-z) powder compact under a concave upper punch, SI units.
//
// The upper punch face is a spherical cup of depth h_c and radius of
// curvature R_c (cup diameter 2a, a = sqrt(2 R_c h_c - h_c^2) <= D/2) with a
// flat land from r = a to the die wall; the powder fills the cup, so the
// compact is H high at the die wall and H + h_c on the axis. The lower punch
// is flat. Physical ids match fem/tablet_geometry.h: axis 0, die wall 1,
// lower punch 2, upper punch 3 (cup and land); the compact is surface 10.
// `compax tablet` needs the same h_c and R_c in Geometry/Cup depth and
// Geometry/Cup radius of curvature.
//
// Regenerate the shipped mesh (ASCII, quadrilaterals) with
//   gmsh -2 -format msh41 concave_punch_rz.geo -o concave_punch_rz.msh
// and change any parameter with e.g. -setnumber cup_depth 0.5e-3.
DefineConstant[
  D = {10e-3, Name "die diameter D [m]"},
  H = {7e-3, Name "fill height at the die wall H [m]"},
  cup_depth = {0.7e-3, Name "cup depth h_c [m]"},
  cup_radius = {16e-3, Name "cup radius of curvature R_c [m]"},
  n_cup = {12, Name "cells across the cup"},
  n_land = {1, Name "cells across the land"},
  n_axial = {18, Name "cells along the height"}
];
R = D / 2;
a = Sqrt(2 * cup_radius * cup_depth - cup_depth^2);  // cup radius [m]
If (a > R * (1 + 1e-12))
  Error("cup wider than the die: need 2 R_c h_c - h_c^2 <= (D/2)^2");
EndIf

Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {R, 0, 0};
Point(4) = {R, H, 0};
Point(5) = {a, H, 0};
Point(6) = {0, H + cup_depth, 0};
Point(7) = {0, H + cup_depth - cup_radius, 0};  // centre of the cup sphere
Line(1) = {1, 2};       // lower punch under the cup
Line(2) = {2, 3};       // lower punch under the land
Line(3) = {3, 4};       // die wall
Line(4) = {4, 5};       // land of the upper punch
Circle(5) = {5, 7, 6};  // cup of the upper punch
Line(6) = {6, 1};       // axis
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Transfinite Curve{1, 5} = n_cup + 1;
Transfinite Curve{2, 4} = n_land + 1;
Transfinite Curve{3, 6} = n_axial + 1;
Transfinite Surface{1} = {1, 3, 4, 6};
Recombine Surface{1};

Physical Curve(0) = {6};
Physical Curve(1) = {3};
Physical Curve(2) = {1, 2};
Physical Curve(3) = {4, 5};
Physical Surface(10) = {1};
