camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
#declare I = 1;
#while (I > 0)
  #declare I = I + 1;
#end
