// Shader compilation and linking; failures carry the driver's info log.
#include "client/render/shader.h"

#include <glad/gl.h>

#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <vector>

namespace pool::render {

namespace {

GLuint compile(GLenum type, const std::string& source) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  std::vector<char> log(4096);
  glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  glDeleteShader(shader);
  throw std::runtime_error(std::string("shader compile error: ") + log.data());
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& vertex_source, const std::string& fragment_source) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex_source);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_source);
  id_ = glCreateProgram();
  glAttachShader(id_, vs);
  glAttachShader(id_, fs);
  glLinkProgram(id_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok == GL_TRUE) return;
  std::vector<char> log(4096);
  glGetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
  glDeleteProgram(id_);
  throw std::runtime_error(std::string("shader link error: ") + log.data());
}

ShaderProgram::~ShaderProgram() {
  glDeleteProgram(id_);
}

void ShaderProgram::use() const {
  glUseProgram(id_);
}

int ShaderProgram::location(const char* name) const {
  return glGetUniformLocation(id_, name);
}

void ShaderProgram::set(const char* name, const glm::mat4& value) const {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}

void ShaderProgram::set(const char* name, const glm::mat3& value) const {
  glUniformMatrix3fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}

void ShaderProgram::set(const char* name, const glm::vec2& value) const {
  glUniform2fv(location(name), 1, glm::value_ptr(value));
}

void ShaderProgram::set(const char* name, const glm::vec3& value) const {
  glUniform3fv(location(name), 1, glm::value_ptr(value));
}

void ShaderProgram::set(const char* name, const glm::vec4& value) const {
  glUniform4fv(location(name), 1, glm::value_ptr(value));
}

void ShaderProgram::set(const char* name, float value) const {
  glUniform1f(location(name), value);
}

void ShaderProgram::set(const char* name, int value) const {
  glUniform1i(location(name), value);
}

}  // namespace pool::render
