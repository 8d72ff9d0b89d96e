// The spec's two blocks (make_decks.py sliding_blocks: a 2 x 0.25 block on a 6 x 1.25 block, 4 x 6 and 12 x 2
// cells), meshed by Gmsh with physical groups named as conductance.inp uses them. -setnumber ORDER 2: quad8 cells,
// half as many each way (the same node spacing, as make_decks.py does for second-order types).
If (!Exists(ORDER))
  ORDER = 1;
EndIf
F = (ORDER == 1) ? 0.5 : 1;  // half the filmed width: two cells of the large block
Point(1) = {0, 0, 0}; Point(2) = {3 - F, 0, 0}; Point(3) = {3 + F, 0, 0}; Point(4) = {6, 0, 0};
Point(5) = {6, 1.25, 0}; Point(6) = {0, 1.25, 0};
Point(7) = {2, 1.25, 0}; Point(8) = {4, 1.25, 0}; Point(9) = {4, 1.5, 0}; Point(10) = {2, 1.5, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Line(7) = {7, 8}; Line(8) = {8, 9}; Line(9) = {9, 10}; Line(10) = {10, 7};
Curve Loop(1) = {1, 2, 3, 4, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {7, 8, 9, 10}; Plane Surface(2) = {2};
// the large block: 12 x 2 cells, its bottom cut around the filmed centre (2 cells, as make_decks.py); the small: 4 x 6
Transfinite Curve{1, 3} = (3 - F) / (0.5 * ORDER) + 1; Transfinite Curve{2} = 3; Transfinite Curve{5} = 12 / ORDER + 1;
Transfinite Curve{4, 6} = 2 / ORDER + 1; Transfinite Curve{7, 9} = 4 / ORDER + 1; Transfinite Curve{8, 10} = 6 / ORDER + 1;
Transfinite Surface{1} = {1, 4, 5, 6}; Transfinite Surface{2};
Recombine Surface{1, 2};
Mesh.ElementOrder = ORDER;
If (!Exists(INCOMPLETE))
  INCOMPLETE = 1;
EndIf
Mesh.SecondOrderIncomplete = INCOMPLETE;
Physical Surface("LARGE") = {1}; Physical Surface("SMALL") = {2};
Physical Curve("BASE") = {1, 2, 3}; Physical Curve("FILMED") = {2}; Physical Curve("MAIN") = {5};
Physical Curve("SECONDARY") = {7}; Physical Curve("TOP") = {9};
