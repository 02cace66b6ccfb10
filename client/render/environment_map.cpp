// The environment cube map: its texture, the faces' cameras and the capture.
#include "client/render/environment_map.h"

#include <glad/gl.h>

#include <array>
#include <stdexcept>

namespace pool::render {

EnvironmentMap::EnvironmentMap() {
  glGenTextures(1, &texture_);
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_);
  for (int face = 0; face < 6; ++face) {
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA8, kSize,
                 kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glGenFramebuffers(1, &fbo_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kSize, kSize);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
}

EnvironmentMap::~EnvironmentMap() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteTextures(1, &texture_);
}

Camera EnvironmentMap::faceCamera(glm::vec3 centre, int face) {
  // OpenGL's cube faces (the specification's table of major axes): the face's image has its s
  // axis and t axis along these directions, which a view with these up vectors gives.
  static const std::array<std::pair<glm::vec3, glm::vec3>, 6> kFaces{{
      {{1, 0, 0}, {0, -1, 0}},
      {{-1, 0, 0}, {0, -1, 0}},
      {{0, 1, 0}, {0, 0, 1}},
      {{0, -1, 0}, {0, 0, -1}},
      {{0, 0, 1}, {0, -1, 0}},
      {{0, 0, -1}, {0, -1, 0}},
  }};
  const auto& [forward, up] = kFaces[static_cast<std::size_t>(face)];
  return {centre, centre + forward, 90.0f, up};
}

void EnvironmentMap::capture(glm::vec3 centre, const std::function<void(const Camera&)>& draw) {
  GLint previous = 0;
  std::array<GLint, 4> viewport{};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous);
  glGetIntegerv(GL_VIEWPORT, viewport.data());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  glViewport(0, 0, kSize, kSize);
  for (int face = 0; face < 6; ++face) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                           static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), texture_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw std::runtime_error("environment map framebuffer incomplete");
    }
    draw(faceCamera(centre, face));
  }
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_);
  glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  captured_ = true;
}

void EnvironmentMap::bind(int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace pool::render
