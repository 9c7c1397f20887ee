#include "lib/render/gl_program.hpp"

#include <stdexcept>
#include <string>

namespace tissu {
namespace {

GLuint compile_shader(const GlFunctions& gl, const char* name, GLenum type, const char* source) {
  const GLuint shader = gl.CreateShader(type);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string log(4096, '\0');
    GLsizei length = 0;
    gl.GetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), &length, log.data());
    log.resize(length);
    gl.DeleteShader(shader);
    throw std::runtime_error(std::string("render: the ") + name +
                             (type == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                             " shader does not compile: " + log);
  }
  return shader;
}

}  // namespace

GLuint build_program(const GlFunctions& gl, const char* name, const char* vertex_source,
                     const char* fragment_source) {
  const GLuint vertex = compile_shader(gl, name, GL_VERTEX_SHADER, vertex_source);
  GLuint fragment = 0;
  try {
    fragment = compile_shader(gl, name, GL_FRAGMENT_SHADER, fragment_source);
  } catch (...) {
    gl.DeleteShader(vertex);
    throw;
  }
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vertex);
  gl.AttachShader(program, fragment);
  gl.LinkProgram(program);
  gl.DeleteShader(vertex);  // flagged: freed with the program
  gl.DeleteShader(fragment);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::string log(4096, '\0');
    GLsizei length = 0;
    gl.GetProgramInfoLog(program, static_cast<GLsizei>(log.size()), &length, log.data());
    log.resize(length);
    gl.DeleteProgram(program);
    throw std::runtime_error(std::string("render: the ") + name + " program does not link: " + log);
  }
  return program;
}

}  // namespace tissu
