// A linked GLSL program with uniform setters by name.
#pragma once

#include <glm/glm.hpp>
#include <string>

namespace pool::render {

/// Compiles and links a vertex and a fragment shader; throws std::runtime_error with the log.
class ShaderProgram {
 public:
  ShaderProgram(const std::string& vertex_source, const std::string& fragment_source);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  /// Makes this the current program.
  void use() const;
  /// Uniform setters (the program must be in use).
  void set(const char* name, const glm::mat4& value) const;
  void set(const char* name, const glm::mat3& value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, float value) const;
  void set(const char* name, int value) const;

 private:
  int location(const char* name) const;
  unsigned id_ = 0;
};

}  // namespace pool::render
