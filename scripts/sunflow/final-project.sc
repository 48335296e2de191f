% The Sunflow 0.7.3 form of the 137-primitive "final project" scene whose port is
% ../shared/data/sunflow-final-project.xml (8 spheres, a 128-triangle checkerboard as 64 two-triangle
% tiles, a wall, 2 point lights and a directional light, 600x600), written back from that XML with
% its header's unit mapping read the other way:
%   colours      : the XML's linear 0..1 values are the "sRGB nonlinear" values below, decoded
%   point light  : power = color * 4 pi^2 / 255 (color 2.584e4 -> 4000; 1.615e4 1.272e4 9751 -> 2500 x (1 0.9 0.8))
%   directional  : intensity = color * pi / 255 (97.4 -> 1.2), direction -10 -25 -15, beam radius 60
%   phong        : spec = ks / pi (3.14159 -> 1); Sunflow also multiplies by (power + 2) / (2 pi),
%                  which the mapping leaves out: its highlights are brighter than the port's
%   camera       : vp-size 93.26153 at vp-distance 100 -> a 50 degree horizontal field of view
%   kr           : mirror refl = kr, shiny refl = kr / kd (0.5), uber spec = kr (0.2, linear), each
%                  weighted by Schlick's Fresnel term in Sunflow, a constant in the port
%   glass        : eta 1.5, colour white (Fresnel kr/kt in Sunflow, constants 0.1/0.9 in the port)
% Not matchable from this side either: Sunflow's background is seen by camera rays only (a reflected or
% refracted ray that leaves the scene brings back black, in the port the background colour), and its
% phong highlights carry the (power + 2) / (2 pi) factor noted above (spec 0.1013 at power 60 and 0.2856
% at power 20 would give the port's highlights).
% Sunflow's shadows are binary (the glass sphere casts a full shadow; the port attenuates it by kt) and
% its trace depths are the ones below (the port: 10 levels with a 0.001 weight cut-off).
% Rendered by scripts/sunflow_benchmark.py, whose -aa flags override the image block's aa.

image {
  resolution 600 600
  aa 0 0
  samples 1
  filter box
}

background {
  color { "sRGB nonlinear" 0.15 0.2 0.3 }
}

trace-depths {
  diff 1
  refl 4
  refr 4
}

camera {
  type pinhole
  eye 0 6 18
  target 0 1 0
  up 0 1 0
  fov 50
  aspect 1
}

light {
  type point
  color { "sRGB nonlinear" 1 1 1 }
  power 4000
  p -6 10 8
}

light {
  type point
  color { "sRGB nonlinear" 1 0.9 0.8 }
  power 2500
  p 7 8 6
}

light {
  type directional
  source 10 25 15
  target 0 0 0
  radius 60
  emit { "sRGB nonlinear" 1 1 1 }
  intensity 1.2
}

shader {
  name red
  type diffuse
  diff { "sRGB nonlinear" 0.8 0.15 0.1 }
}

shader {
  name green
  type diffuse
  diff { "sRGB nonlinear" 0.2 0.7 0.2 }
}

shader {
  name blue_phong
  type phong
  diff { "sRGB nonlinear" 0.1 0.2 0.8 }
  spec { "sRGB nonlinear" 1 1 1 } 60
  samples 0
}

shader {
  name yellow_phong
  type phong
  diff { "sRGB nonlinear" 0.9 0.8 0.1 }
  spec { "sRGB nonlinear" 1 1 1 } 20
  samples 0
}

shader {
  name chrome
  type mirror
  refl { "sRGB nonlinear" 0.9 0.9 0.9 }
}

shader {
  name gold
  type mirror
  refl { "sRGB nonlinear" 0.95 0.75 0.3 }
}

shader {
  name purple_shiny
  type shiny
  diff { "sRGB nonlinear" 0.6 0.2 0.7 }
  refl 0.5
}

shader {
  name glass
  type glass
  eta 1.5
  color { "sRGB nonlinear" 1 1 1 }
}

shader {
  name wall
  type diffuse
  diff { "sRGB nonlinear" 0.7 0.7 0.65 }
}

shader {
  name tile_light
  type uber
  diff { "sRGB nonlinear" 0.85 0.85 0.85 }
  spec 0.2 0.2 0.2
}

shader {
  name tile_dark
  type uber
  diff { "sRGB nonlinear" 0.08 0.08 0.1 }
  spec 0.2 0.2 0.2
}

object {
  shader red
  type sphere
  c -5 1 2
  r 1
}

object {
  shader green
  type sphere
  c 5 1 3
  r 1
}

object {
  shader blue_phong
  type sphere
  c -2.5 1.2 -2
  r 1.2
}

object {
  shader yellow_phong
  type sphere
  c 2.5 0.8 4
  r 0.8
}

object {
  shader chrome
  type sphere
  c 0 2 -4
  r 2
}

object {
  shader gold
  type sphere
  c 6 1.5 -3
  r 1.5
}

object {
  shader purple_shiny
  type sphere
  c -6 1.5 -4
  r 1.5
}

object {
  shader glass
  type sphere
  c 0 1.3 3
  r 1.3
}

object {
  shader wall
  type plane
  p 0 0 -14
  n 0 0 1
}

% The checkerboard: 8 x 8 tiles of 3.5 x 3.5 on y = 0 from -14 to 14, two triangles each, facing up.
object {
  shader tile_light
  type generic-mesh
  name tile_0_0
  points 4
    -14 0 -14
    -10.5 0 -14
    -10.5 0 -10.5
    -14 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_0_1
  points 4
    -14 0 -10.5
    -10.5 0 -10.5
    -10.5 0 -7
    -14 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_0_2
  points 4
    -14 0 -7
    -10.5 0 -7
    -10.5 0 -3.5
    -14 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_0_3
  points 4
    -14 0 -3.5
    -10.5 0 -3.5
    -10.5 0 0
    -14 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_0_4
  points 4
    -14 0 0
    -10.5 0 0
    -10.5 0 3.5
    -14 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_0_5
  points 4
    -14 0 3.5
    -10.5 0 3.5
    -10.5 0 7
    -14 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_0_6
  points 4
    -14 0 7
    -10.5 0 7
    -10.5 0 10.5
    -14 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_0_7
  points 4
    -14 0 10.5
    -10.5 0 10.5
    -10.5 0 14
    -14 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_1_0
  points 4
    -10.5 0 -14
    -7 0 -14
    -7 0 -10.5
    -10.5 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_1_1
  points 4
    -10.5 0 -10.5
    -7 0 -10.5
    -7 0 -7
    -10.5 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_1_2
  points 4
    -10.5 0 -7
    -7 0 -7
    -7 0 -3.5
    -10.5 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_1_3
  points 4
    -10.5 0 -3.5
    -7 0 -3.5
    -7 0 0
    -10.5 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_1_4
  points 4
    -10.5 0 0
    -7 0 0
    -7 0 3.5
    -10.5 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_1_5
  points 4
    -10.5 0 3.5
    -7 0 3.5
    -7 0 7
    -10.5 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_1_6
  points 4
    -10.5 0 7
    -7 0 7
    -7 0 10.5
    -10.5 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_1_7
  points 4
    -10.5 0 10.5
    -7 0 10.5
    -7 0 14
    -10.5 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_2_0
  points 4
    -7 0 -14
    -3.5 0 -14
    -3.5 0 -10.5
    -7 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_2_1
  points 4
    -7 0 -10.5
    -3.5 0 -10.5
    -3.5 0 -7
    -7 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_2_2
  points 4
    -7 0 -7
    -3.5 0 -7
    -3.5 0 -3.5
    -7 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_2_3
  points 4
    -7 0 -3.5
    -3.5 0 -3.5
    -3.5 0 0
    -7 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_2_4
  points 4
    -7 0 0
    -3.5 0 0
    -3.5 0 3.5
    -7 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_2_5
  points 4
    -7 0 3.5
    -3.5 0 3.5
    -3.5 0 7
    -7 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_2_6
  points 4
    -7 0 7
    -3.5 0 7
    -3.5 0 10.5
    -7 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_2_7
  points 4
    -7 0 10.5
    -3.5 0 10.5
    -3.5 0 14
    -7 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_3_0
  points 4
    -3.5 0 -14
    0 0 -14
    0 0 -10.5
    -3.5 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_3_1
  points 4
    -3.5 0 -10.5
    0 0 -10.5
    0 0 -7
    -3.5 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_3_2
  points 4
    -3.5 0 -7
    0 0 -7
    0 0 -3.5
    -3.5 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_3_3
  points 4
    -3.5 0 -3.5
    0 0 -3.5
    0 0 0
    -3.5 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_3_4
  points 4
    -3.5 0 0
    0 0 0
    0 0 3.5
    -3.5 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_3_5
  points 4
    -3.5 0 3.5
    0 0 3.5
    0 0 7
    -3.5 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_3_6
  points 4
    -3.5 0 7
    0 0 7
    0 0 10.5
    -3.5 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_3_7
  points 4
    -3.5 0 10.5
    0 0 10.5
    0 0 14
    -3.5 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_4_0
  points 4
    0 0 -14
    3.5 0 -14
    3.5 0 -10.5
    0 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_4_1
  points 4
    0 0 -10.5
    3.5 0 -10.5
    3.5 0 -7
    0 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_4_2
  points 4
    0 0 -7
    3.5 0 -7
    3.5 0 -3.5
    0 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_4_3
  points 4
    0 0 -3.5
    3.5 0 -3.5
    3.5 0 0
    0 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_4_4
  points 4
    0 0 0
    3.5 0 0
    3.5 0 3.5
    0 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_4_5
  points 4
    0 0 3.5
    3.5 0 3.5
    3.5 0 7
    0 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_4_6
  points 4
    0 0 7
    3.5 0 7
    3.5 0 10.5
    0 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_4_7
  points 4
    0 0 10.5
    3.5 0 10.5
    3.5 0 14
    0 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_5_0
  points 4
    3.5 0 -14
    7 0 -14
    7 0 -10.5
    3.5 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_5_1
  points 4
    3.5 0 -10.5
    7 0 -10.5
    7 0 -7
    3.5 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_5_2
  points 4
    3.5 0 -7
    7 0 -7
    7 0 -3.5
    3.5 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_5_3
  points 4
    3.5 0 -3.5
    7 0 -3.5
    7 0 0
    3.5 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_5_4
  points 4
    3.5 0 0
    7 0 0
    7 0 3.5
    3.5 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_5_5
  points 4
    3.5 0 3.5
    7 0 3.5
    7 0 7
    3.5 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_5_6
  points 4
    3.5 0 7
    7 0 7
    7 0 10.5
    3.5 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_5_7
  points 4
    3.5 0 10.5
    7 0 10.5
    7 0 14
    3.5 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_6_0
  points 4
    7 0 -14
    10.5 0 -14
    10.5 0 -10.5
    7 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_6_1
  points 4
    7 0 -10.5
    10.5 0 -10.5
    10.5 0 -7
    7 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_6_2
  points 4
    7 0 -7
    10.5 0 -7
    10.5 0 -3.5
    7 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_6_3
  points 4
    7 0 -3.5
    10.5 0 -3.5
    10.5 0 0
    7 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_6_4
  points 4
    7 0 0
    10.5 0 0
    10.5 0 3.5
    7 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_6_5
  points 4
    7 0 3.5
    10.5 0 3.5
    10.5 0 7
    7 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_6_6
  points 4
    7 0 7
    10.5 0 7
    10.5 0 10.5
    7 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_6_7
  points 4
    7 0 10.5
    10.5 0 10.5
    10.5 0 14
    7 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_7_0
  points 4
    10.5 0 -14
    14 0 -14
    14 0 -10.5
    10.5 0 -10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_7_1
  points 4
    10.5 0 -10.5
    14 0 -10.5
    14 0 -7
    10.5 0 -7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_7_2
  points 4
    10.5 0 -7
    14 0 -7
    14 0 -3.5
    10.5 0 -3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_7_3
  points 4
    10.5 0 -3.5
    14 0 -3.5
    14 0 0
    10.5 0 0
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_7_4
  points 4
    10.5 0 0
    14 0 0
    14 0 3.5
    10.5 0 3.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_7_5
  points 4
    10.5 0 3.5
    14 0 3.5
    14 0 7
    10.5 0 7
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_dark
  type generic-mesh
  name tile_7_6
  points 4
    10.5 0 7
    14 0 7
    14 0 10.5
    10.5 0 10.5
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}

object {
  shader tile_light
  type generic-mesh
  name tile_7_7
  points 4
    10.5 0 10.5
    14 0 10.5
    14 0 14
    10.5 0 14
  triangles 2
    0 2 1
    0 3 2
  normals none
  uvs none
}
