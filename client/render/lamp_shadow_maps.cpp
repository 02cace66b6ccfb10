// The lamps' depth maps: their textures, framebuffer, light matrices and depth pass.
#include "client/render/lamp_shadow_maps.h"

#include <glad/gl.h>

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "client/render/shaders.h"

namespace pool::render {

LampShadowMaps::LampShadowMaps() : depth_(shaders::kDepthVertex, shaders::kDepthFragment) {
  glGenTextures(2, textures_.data());
  for (const unsigned texture : textures_) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kSize, kSize, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenFramebuffers(1, &fbo_);
}

LampShadowMaps::~LampShadowMaps() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteTextures(2, textures_.data());
}

glm::mat4 LampShadowMaps::lightMatrix(glm::vec3 lamp) {
  const glm::mat4 projection =
      glm::perspective(glm::radians(2.0f * kHalfAngleDeg), 1.0f, kNear, kFar);
  const glm::mat4 view =
      glm::lookAt(lamp, lamp - glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  return projection * view;
}

void LampShadowMaps::begin(int index, glm::vec3 lamp) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_);
  glGetIntegerv(GL_VIEWPORT, viewport_.data());
  const auto i = static_cast<std::size_t>(index);
  matrices_[i] = lightMatrix(lamp);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, textures_[i], 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("shadow map framebuffer incomplete");
  }
  glViewport(0, 0, kSize, kSize);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glClear(GL_DEPTH_BUFFER_BIT);
  // Slope-scaled offset: a lit surface never shadows itself.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 4.0f);
  depth_.use();
  depth_.set("uLightMatrix", matrices_[i]);
}

void LampShadowMaps::caster(const GpuMesh& mesh, const glm::mat4& model) const {
  depth_.set("uModel", model);
  mesh.draw();
}

void LampShadowMaps::end() {
  glDisable(GL_POLYGON_OFFSET_FILL);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
}

void LampShadowMaps::bind(int index, int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, textures_[static_cast<std::size_t>(index)]);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace pool::render
