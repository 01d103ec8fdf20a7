camera { location <0, 1, -5> look_at 0 }
light_source { <5, 5, -5> color rgb 1 }
#declare S = "ÿþÀ¯";
sphere { 0, 1 }
#error S
