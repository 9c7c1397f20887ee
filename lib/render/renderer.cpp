#include "lib/render/renderer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "lib/render/cloth_geometry.hpp"
#include "lib/render/gl_context.hpp"
#include "lib/render/gl_functions.hpp"
#include "lib/render/gl_program.hpp"
#include "lib/render/obstacle_geometry.hpp"
#include "lib/render/shader_sources.hpp"

namespace tissu {
namespace {

/// A vertex buffer and the vertex array that reads it.
struct VertexArray {
  GLuint array = 0;
  GLuint buffer = 0;
  GLsizei count = 0;  ///< vertices uploaded last
};

/// Layout of a vertex: the surface program's (position, normal, strain) or the flat program's
/// (position).
enum class Layout { surface, flat };

VertexArray make_vertex_array(const GlFunctions& gl, Layout layout) {
  VertexArray va;
  gl.GenVertexArrays(1, &va.array);
  gl.GenBuffers(1, &va.buffer);
  gl.BindVertexArray(va.array);
  gl.BindBuffer(GL_ARRAY_BUFFER, va.buffer);
  const GLsizei floats = layout == Layout::surface ? cloth_vertex_floats : 3;
  const GLsizei stride = floats * sizeof(float);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  if (layout == Layout::surface) {
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(3 * sizeof(float)));
    gl.EnableVertexAttribArray(2);
    gl.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(6 * sizeof(float)));
  }
  gl.BindVertexArray(0);
  return va;
}

void upload(const GlFunctions& gl, VertexArray& va, const std::vector<float>& data,
            int floats_per_vertex) {
  gl.BindBuffer(GL_ARRAY_BUFFER, va.buffer);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(),
                GL_STREAM_DRAW);
  va.count = static_cast<GLsizei>(data.size() / floats_per_vertex);
}

void draw(const GlFunctions& gl, const VertexArray& va, GLenum mode) {
  if (va.count == 0) return;
  gl.BindVertexArray(va.array);
  gl.DrawArrays(mode, 0, va.count);
}

/// The ground: a horizontal square of half side `radius` (m) centred at `centre`.
struct Ground {
  Eigen::Vector3d centre;
  double radius = 1.0;
};

/// Two surface triangles covering a horizontal square of half side `half_size` (m) around
/// `centre`, facing +z.
std::vector<float> ground_quad(const Eigen::Vector3d& centre, double half_size) {
  std::vector<float> data;
  const double xs[] = {-1, 1, 1, -1, 1, -1}, ys[] = {-1, -1, 1, -1, 1, 1};
  for (int i = 0; i < 6; ++i) {
    data.insert(data.end(), {static_cast<float>(centre.x() + xs[i] * half_size),
                             static_cast<float>(centre.y() + ys[i] * half_size),
                             static_cast<float>(centre.z()), 0.0f, 0.0f, 1.0f, 0.0f});
  }
  return data;
}

/// Near and far clip distances (m) that hold every point of `box` in front of the eye, or
/// nothing when the box is empty or behind the eye.
std::optional<std::pair<double, double>> clip_distances(const Eigen::AlignedBox3d& box,
                                                        const Camera& camera) {
  if (box.isEmpty()) return std::nullopt;
  const Eigen::Vector3d forward = (camera.target - camera.position).normalized();
  double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
  for (int i = 0; i < 8; ++i) {
    const double depth =
        (box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)) - camera.position)
            .dot(forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  if (!(farthest > 0.0)) return std::nullopt;
  const double far_m = 1.02 * farthest + 1e-6;
  return std::pair{std::max(0.98 * nearest, 1e-4 * far_m), far_m};
}

std::string hex(unsigned value) {
  std::ostringstream out;
  out << "0x" << std::hex << value;
  return out.str();
}

}  // namespace

struct Renderer::State {
  RenderOptions options;
  std::unique_ptr<OffscreenContext> context;
  GlFunctions gl;
  GLuint surface_program = 0;
  GLuint flat_program = 0;
  VertexArray cloth, ground, obstacles, edges, pins;
  GLuint multisample_framebuffer = 0;  ///< 0: draw straight into the context's framebuffer
  std::array<GLuint, 2> multisample_renderbuffers{};  ///< colour, depth
  float max_line_width = 1.0f;
  float max_point_size = 1.0f;

  explicit State(const RenderOptions& opts) : options(opts) {
    validate_render_options(options);
    context = create_offscreen_context(options.width, options.height);
    gl = load_gl_functions(*context);
    surface_program =
        build_program(gl, "surface", shaders::surface_vertex, shaders::surface_fragment);
    flat_program = build_program(gl, "flat", shaders::flat_vertex, shaders::flat_fragment);
    cloth = make_vertex_array(gl, Layout::surface);
    ground = make_vertex_array(gl, Layout::surface);
    obstacles = make_vertex_array(gl, Layout::surface);
    edges = make_vertex_array(gl, Layout::flat);
    pins = make_vertex_array(gl, Layout::flat);
    float range[2] = {1.0f, 1.0f};
    gl.GetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    max_line_width = range[1];
    gl.GetFloatv(GL_POINT_SIZE_RANGE, range);
    max_point_size = range[1];
    if (options.samples > 1) make_multisample_framebuffer();
    if (const GLenum error = gl.GetError(); error != GL_NO_ERROR)
      throw std::runtime_error("render: OpenGL error " + hex(error) + " while setting up");
  }

  ~State() {
    context->make_current();
    for (VertexArray* va : {&cloth, &ground, &obstacles, &edges, &pins}) {
      gl.DeleteBuffers(1, &va->buffer);
      gl.DeleteVertexArrays(1, &va->array);
    }
    gl.DeleteProgram(surface_program);
    gl.DeleteProgram(flat_program);
    if (multisample_framebuffer) {
      gl.DeleteFramebuffers(1, &multisample_framebuffer);
      gl.DeleteRenderbuffers(2, multisample_renderbuffers.data());
    }
  }

  /// Colour and depth renderbuffers of options.samples samples (at most what the driver offers);
  /// without one the image is drawn aliased.
  void make_multisample_framebuffer() {
    GLint max_samples = 1;
    gl.GetIntegerv(GL_MAX_SAMPLES, &max_samples);
    const GLsizei samples = std::min<GLint>(options.samples, max_samples);
    if (samples <= 1) return;
    gl.GenFramebuffers(1, &multisample_framebuffer);
    gl.GenRenderbuffers(2, multisample_renderbuffers.data());
    gl.BindFramebuffer(GL_FRAMEBUFFER, multisample_framebuffer);
    const GLenum formats[] = {GL_RGBA8, GL_DEPTH_COMPONENT24};
    const GLenum attachments[] = {GL_COLOR_ATTACHMENT0, GL_DEPTH_ATTACHMENT};
    for (int i = 0; i < 2; ++i) {
      gl.BindRenderbuffer(GL_RENDERBUFFER, multisample_renderbuffers[i]);
      gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, formats[i], options.width,
                                        options.height);
      gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, attachments[i], GL_RENDERBUFFER,
                                 multisample_renderbuffers[i]);
    }
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      gl.DeleteFramebuffers(1, &multisample_framebuffer);
      gl.DeleteRenderbuffers(2, multisample_renderbuffers.data());
      multisample_framebuffer = 0;
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, context->framebuffer());
  }

  GLint uniform(GLuint program, const char* name) const {
    return gl.GetUniformLocation(program, name);
  }

  void set_color(GLuint program, const char* name, const Eigen::Vector3f& color) const {
    gl.Uniform3fv(uniform(program, name), 1, color.data());
  }

  void set_vector(GLuint program, const char* name, const Eigen::Vector3d& v) const {
    const Eigen::Vector3f f = v.cast<float>();
    gl.Uniform3fv(uniform(program, name), 1, f.data());
  }

  Image render(const RenderScene& scene, const Camera& camera) {
    validate_camera(camera);
    const ClothGeometry geometry = cloth_geometry(scene, options.color_mode);
    const ObstacleGeometry solids = obstacle_geometry(scene.obstacles);
    const RenderOptions& o = options;

    context->make_current();
    gl.BindFramebuffer(GL_FRAMEBUFFER,
                       multisample_framebuffer ? multisample_framebuffer : context->framebuffer());
    gl.Viewport(0, 0, o.width, o.height);
    gl.ClearColor(o.background_color.x(), o.background_color.y(), o.background_color.z(), 1.0f);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    // the ground: a square some cloth sizes wide under the cloth, fading out towards its edge
    std::optional<Ground> ground_plane;
    Eigen::AlignedBox3d visible = geometry.bounds;
    visible.extend(solids.bounds);  // or the clip planes could cut the obstacles
    if (o.show_ground && scene.ground_height_m) {
      const bool empty = geometry.bounds.isEmpty();
      Ground g;
      g.centre = empty ? camera.target : geometry.bounds.center();
      g.centre.z() = *scene.ground_height_m;
      g.radius = 3.0 * std::max(empty ? 0.0 : geometry.bounds.diagonal().norm(), 0.5);
      visible.extend(g.centre - Eigen::Vector3d(g.radius, g.radius, 0.0));
      visible.extend(g.centre + Eigen::Vector3d(g.radius, g.radius, 0.0));
      ground_plane = g;
    }

    if (const auto clip = clip_distances(visible, camera)) {
      const double aspect = static_cast<double>(o.width) / o.height;
      const Eigen::Matrix4f view_projection =
          projection_matrix(camera, aspect, clip->first, clip->second) * view_matrix(camera);
      draw_surfaces(geometry, solids, ground_plane, camera, view_projection);
      draw_overlays(geometry, view_projection);
    }

    if (multisample_framebuffer) {
      gl.BindFramebuffer(GL_READ_FRAMEBUFFER, multisample_framebuffer);
      gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, context->framebuffer());
      gl.BlitFramebuffer(0, 0, o.width, o.height, 0, 0, o.width, o.height, GL_COLOR_BUFFER_BIT,
                         GL_NEAREST);
    }
    if (const GLenum error = gl.GetError(); error != GL_NO_ERROR)
      throw std::runtime_error("render: OpenGL error " + hex(error) + " while drawing");
    return context->read_pixels();
  }

  /// The ground plane, the obstacles, then the cloth, all lit, pushed back in depth so that lines
  /// and points drawn at the same depth show in front of them.
  void draw_surfaces(const ClothGeometry& geometry, const ObstacleGeometry& solids,
                     const std::optional<Ground>& ground_plane, const Camera& camera,
                     const Eigen::Matrix4f& view_projection) {
    const RenderOptions& o = options;
    const Eigen::Vector3d forward = (camera.target - camera.position).normalized();
    const Eigen::Vector3d right = forward.cross(camera.up).normalized();
    const Eigen::Vector3d up = right.cross(forward);

    gl.UseProgram(surface_program);
    gl.UniformMatrix4fv(uniform(surface_program, "u_view_projection"), 1, GL_FALSE,
                        view_projection.data());
    set_vector(surface_program, "u_eye", camera.position);
    // lights fixed to the camera, on its side of the scene: both sides of the cloth get lit
    set_vector(surface_program, "u_key_light",
               (-0.45 * right + 0.6 * up - 0.65 * forward).normalized());
    set_vector(surface_program, "u_fill_light",
               (0.7 * right - 0.1 * up - 0.7 * forward).normalized());
    set_color(surface_program, "u_background_color", o.background_color);
    gl.Uniform1f(uniform(surface_program, "u_strain_range"), static_cast<float>(o.strain_range));
    gl.Enable(GL_POLYGON_OFFSET_FILL);

    if (ground_plane) {
      upload(gl, ground, ground_quad(ground_plane->centre, ground_plane->radius),
             cloth_vertex_floats);
      gl.Uniform1i(uniform(surface_program, "u_mode"), 2);
      set_color(surface_program, "u_front_color", o.ground_color);
      set_vector(surface_program, "u_ground_center", ground_plane->centre);
      gl.Uniform1f(uniform(surface_program, "u_ground_fade_radius"),
                   static_cast<float>(ground_plane->radius));
      gl.PolygonOffset(4.0f, 16.0f);  // behind cloth lying on it
      draw(gl, ground, GL_TRIANGLES);
    }

    // obstacles: lit like the cloth's front, one colour on both sides (only the outside shows on
    // a closed mesh), and no wireframe
    upload(gl, obstacles, solids.triangles, cloth_vertex_floats);
    gl.Uniform1i(uniform(surface_program, "u_mode"), 0);
    set_color(surface_program, "u_front_color", o.obstacle_color);
    set_color(surface_program, "u_back_color", o.obstacle_color);
    gl.PolygonOffset(2.0f, 8.0f);  // behind cloth resting on them, in front of the ground
    draw(gl, obstacles, GL_TRIANGLES);

    upload(gl, cloth, geometry.triangles, cloth_vertex_floats);
    const int mode = o.color_mode == ColorMode::strain        ? 1
                     : o.color_mode == ColorMode::level       ? 3
                     : o.color_mode == ColorMode::sizing_term ? 4
                                                              : 0;
    gl.Uniform1i(uniform(surface_program, "u_mode"), mode);
    set_color(surface_program, "u_front_color", o.front_color);
    set_color(surface_program, "u_back_color", o.back_color);
    gl.PolygonOffset(1.0f, 2.0f);  // behind its own edges and pins
    draw(gl, cloth, GL_TRIANGLES);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
  }

  /// The wireframe (blended) and the pin squares.
  void draw_overlays(const ClothGeometry& geometry, const Eigen::Matrix4f& view_projection) {
    const RenderOptions& o = options;
    gl.UseProgram(flat_program);
    gl.UniformMatrix4fv(uniform(flat_program, "u_view_projection"), 1, GL_FALSE,
                        view_projection.data());
    if (o.wireframe) {
      upload(gl, edges, geometry.edges, 3);
      set_color(flat_program, "u_color", o.wireframe_color);
      gl.Uniform1f(uniform(flat_program, "u_opacity"), o.wireframe_opacity);
      gl.LineWidth(std::min(o.wireframe_width_px, max_line_width));
      gl.Enable(GL_BLEND);
      gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
      draw(gl, edges, GL_LINES);
      gl.Disable(GL_BLEND);
    }
    if (o.show_pins) {
      upload(gl, pins, geometry.pins, 3);
      set_color(flat_program, "u_color", o.pin_color);
      gl.Uniform1f(uniform(flat_program, "u_opacity"), 1.0f);
      gl.PointSize(std::min(o.pin_size_px, max_point_size));
      draw(gl, pins, GL_POINTS);
    }
    gl.BindVertexArray(0);
  }
};

Renderer::Renderer(const RenderOptions& options) : m_state(std::make_unique<State>(options)) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Image Renderer::render(const RenderScene& scene, const Camera& camera) {
  return m_state->render(scene, camera);
}

const RenderOptions& Renderer::options() const {
  return m_state->options;
}

}  // namespace tissu
