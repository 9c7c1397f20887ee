#pragma once
/// \file
/// GLSL 330 core sources of the renderer's two programs: `surface` (cloth, obstacles and
/// ground, lit) and
/// `flat` (wireframe lines and pin points, one colour).

namespace tissu::shaders {

/// Attributes: 0 position (m), 1 normal (unnormalised), 2 face strain.
inline constexpr const char* surface_vertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_strain;
uniform mat4 u_view_projection;
out vec3 v_position;
out vec3 v_normal;
out float v_strain;
void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_strain = a_strain;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

/// u_mode: 0 two-sided colours (front or back by gl_FrontFacing), 1 strain colour map, 2 ground
/// (fades into the background away from u_ground_center), 3 refinement level, 4 sizing term. Lights
/// are unit world directions towards the light; the normal is flipped on back faces so both sides
/// are lit.
inline constexpr const char* surface_fragment = R"(#version 330 core
in vec3 v_position;
in vec3 v_normal;
in float v_strain;
uniform int u_mode;
uniform vec3 u_front_color;
uniform vec3 u_back_color;
uniform vec3 u_background_color;
uniform vec3 u_eye;
uniform vec3 u_key_light;
uniform vec3 u_fill_light;
uniform float u_strain_range;
uniform vec3 u_ground_center;
uniform float u_ground_fade_radius;
out vec4 frag_color;

// blue (compressed) - white (rest) - red (stretched), after Moreland's cool-warm end points
vec3 strain_color(float strain) {
  float t = clamp(strain / u_strain_range, -1.0, 1.0);
  vec3 blue = vec3(0.23, 0.30, 0.75);
  vec3 white = vec3(0.93, 0.93, 0.93);
  vec3 red = vec3(0.71, 0.02, 0.15);
  return t < 0.0 ? mix(white, blue, -t) : mix(white, red, t);
}

// refinement level: input faces light, each bisection darker (the viewer's palette, viewer/)
vec3 level_color(float level) {
  const vec3 colors[6] = vec3[6](vec3(0.95, 0.83, 0.63), vec3(0.91, 0.63, 0.38),
                                 vec3(0.78, 0.39, 0.24), vec3(0.55, 0.24, 0.35),
                                 vec3(0.29, 0.24, 0.47), vec3(0.12, 0.24, 0.39));
  return colors[int(clamp(floor(level + 0.5), 0.0, 5.0))];
}

// sizing term (SizingTerm): none light grey, curvature blue, velocity (curvature ahead) sky blue,
// strain vermillion, obstacles bluish green, maximum edge length reddish purple (Okabe & Ito's
// colour-blind-safe palette)
vec3 term_color(float term) {
  const vec3 colors[6] = vec3[6](vec3(0.85, 0.85, 0.85), vec3(0.00, 0.45, 0.70),
                                 vec3(0.34, 0.71, 0.91), vec3(0.84, 0.37, 0.00),
                                 vec3(0.00, 0.62, 0.45), vec3(0.80, 0.47, 0.65));
  return colors[int(clamp(floor(term + 0.5), 0.0, 5.0))];
}

void main() {
  vec3 n = v_normal;
  if (dot(n, n) < 1e-24) n = cross(dFdx(v_position), dFdy(v_position));
  n = normalize(n);
  if (!gl_FrontFacing) n = -n;
  vec3 view = normalize(u_eye - v_position);
  float key = max(dot(n, u_key_light), 0.0);
  float fill = max(dot(n, u_fill_light), 0.0);
  if (u_mode == 2) {
    vec3 lit = u_front_color * (0.82 + 0.18 * key);
    float fade = smoothstep(0.35, 1.0, distance(v_position.xy, u_ground_center.xy) /
                                           u_ground_fade_radius);
    frag_color = vec4(mix(lit, u_background_color, fade), 1.0);
    return;
  }
  vec3 base = u_mode == 1   ? strain_color(v_strain)
              : u_mode == 3 ? level_color(v_strain)
              : u_mode == 4 ? term_color(v_strain)
                            : (gl_FrontFacing ? u_front_color : u_back_color);
  float specular = pow(max(dot(n, normalize(u_key_light + view)), 0.0), 40.0);
  vec3 color = base * (0.30 + 0.60 * key + 0.15 * fill) + vec3(0.07 * specular);
  frag_color = vec4(min(color, vec3(1.0)), 1.0);
}
)";

/// Attribute 0: position (m). Blended by u_opacity where blending is on.
inline constexpr const char* flat_vertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
void main() { gl_Position = u_view_projection * vec4(a_position, 1.0); }
)";

inline constexpr const char* flat_fragment = R"(#version 330 core
uniform vec3 u_color;
uniform float u_opacity;
out vec4 frag_color;
void main() { frag_color = vec4(u_color, u_opacity); }
)";

}  // namespace tissu::shaders
