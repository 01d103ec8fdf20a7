// Values the scene model cannot hold: each is reported where it stands.
camera { location <0, 1, -5> look_at 0 }
background { rgb <0.2, 0.3, 0.8> }
light_source { <0, 5, -5> color rgb 1 spotlight point_at 0 radius 15 falloff 20 }
light_source { <5, 5, -5> color rgb 0.5 shadowless }
sphere { 0, 1
  pigment { rgbf <1, 0.5, 0.5, 0.4> }
  finish { ambient rgb <0.1, 0.2, 0.3> specular 0.5 roughness 0.02 brilliance 2 }
  no_shadow
}
cylinder { <-2, -1, 0>, <-2, 1, 0>, 0.5 open pigment { rgb 1 } }
box { -1, 1 scale <1, 0, 1> translate x*3 finish { diffuse 1.5 } }
