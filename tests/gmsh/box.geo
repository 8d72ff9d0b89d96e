// A box 2 x 1 x 1 with its six faces as physical groups (conduction_box.inp uses them): unstructured tetrahedra by
// default (-setnumber ORDER 2: tetra10), or -setnumber HEX 1: a transfinite grid of hexahedra (4 x 2 x 2).
If (!Exists(ORDER))
  ORDER = 1;
EndIf
If (!Exists(HEX))
  HEX = 0;
EndIf
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1, 1};
Mesh.CharacteristicLengthMax = 0.4;
If (HEX == 1)
  Transfinite Curve{:} = 3;
  Transfinite Curve{Curve{:}} = 3;
  Transfinite Surface{:};
  Transfinite Volume{1};
  Recombine Surface{:};
  Mesh.Recombine3DAll = 1;
EndIf
Mesh.ElementOrder = ORDER;
Mesh.SecondOrderIncomplete = 1;
// Box faces: 1 x = 0, 2 x = 2, 3 y = 0, 4 y = 1, 5 z = 0, 6 z = 1
Physical Volume("BODY") = {1};
Physical Surface("COLD") = {1}; Physical Surface("HOT") = {2};
Physical Surface("YSYM") = {3}; Physical Surface("ZSYM") = {5};
