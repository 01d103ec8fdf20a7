// Names that nothing declares.
camera { location <0, 1, -5> look_at 0 }
#declare Radius = 1;
sphere { 0, Raduis pigment { Red } }
sphere { 0, Radius pigment { rgb <1, 0, 0> } }
box { -1, 1 pigment { Red } }
