camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
#declare S = "ab";
#declare I = 0;
#while (I < 64)
  #declare S = concat(S, S);
  #declare I = I + 1;
#end
