#pragma once
/// \file
/// The OpenGL 3.3 core functions the renderer calls, loaded through the context's proc_address so
/// that nothing links against a GL library directly. Members keep the GL names without the "gl"
/// prefix: gl.DrawArrays(...) calls glDrawArrays.

#include <GL/glcorearb.h>

#include "lib/render/gl_context.hpp"

namespace tissu {

#define TISSU_GL_FUNCTIONS(X)                                                \
  X(PFNGLGETERRORPROC, GetError)                                             \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                       \
  X(PFNGLGETFLOATVPROC, GetFloatv)                                           \
  X(PFNGLVIEWPORTPROC, Viewport)                                             \
  X(PFNGLCLEARCOLORPROC, ClearColor)                                         \
  X(PFNGLCLEARPROC, Clear)                                                   \
  X(PFNGLENABLEPROC, Enable)                                                 \
  X(PFNGLDISABLEPROC, Disable)                                               \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                                           \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                                           \
  X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                                   \
  X(PFNGLLINEWIDTHPROC, LineWidth)                                           \
  X(PFNGLPOINTSIZEPROC, PointSize)                                           \
  X(PFNGLCREATESHADERPROC, CreateShader)                                     \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                                     \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                                   \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                       \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                             \
  X(PFNGLDELETESHADERPROC, DeleteShader)                                     \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                   \
  X(PFNGLATTACHSHADERPROC, AttachShader)                                     \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                       \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                     \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                           \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                   \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                         \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                         \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                           \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                                           \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                         \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                             \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                               \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                               \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                         \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                         \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                         \
  X(PFNGLBUFFERDATAPROC, BufferData)                                         \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                   \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                       \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)               \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                         \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                               \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                               \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)               \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                 \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                         \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                             \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                             \
  X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample) \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                       \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)

/// A table of OpenGL entry points; every member is non-null once loaded.
struct GlFunctions {
#define TISSU_GL_MEMBER(type, name) type name = nullptr;
  TISSU_GL_FUNCTIONS(TISSU_GL_MEMBER)
#undef TISSU_GL_MEMBER
};

/// Loads every function through `context` (which must be current). Throws std::runtime_error
/// naming the first missing function.
GlFunctions load_gl_functions(OffscreenContext& context);

}  // namespace tissu
