// GLSL programs built from the shaders/ sources: embedded at build time, or read from an override
// directory at run time (a file there replaces the embedded file of the same name).
#pragma once

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shadowvol/gl/gl_objects.h"

namespace shadowvol::gl {

/// The embedded text of shaders/<name>, or nullopt (generated at build time).
std::optional<std::string> embeddedShader(const std::string& name);

/// Finds shader sources: `overrideDir`/<name> when that file exists, else the embedded copy.
/// An empty overrideDir uses the SHADOWVOL_SHADER_DIR environment variable when it is set.
class ShaderLibrary {
 public:
  explicit ShaderLibrary(std::filesystem::path overrideDir = {});
  /// The source text and where it came from ("shaders/<name> (embedded)" or the file path).
  /// Throws GlError if the name is neither in the directory nor embedded.
  std::pair<std::string, std::string> load(const std::string& name) const;
  const std::filesystem::path& overrideDir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

/// A linked program. Compile and link logs are reported in GlError with the file names.
class Program {
 public:
  Program() = default;
  Program(const ShaderLibrary& library, const std::string& vertexFile, const std::string& fragmentFile);
  /// Each stage from several files concatenated in order (glShaderSource with one string per
  /// file; the first holds #version). Driver logs number lines "string:line", string = file index.
  Program(const ShaderLibrary& library, const std::vector<std::string>& vertexFiles,
          const std::vector<std::string>& fragmentFiles);
  /// With a geometry stage (empty geometryFiles = none; empty fragmentFiles = none, for a program
  /// whose output is only captured), and the outputs that transform feedback captures, interleaved
  /// in this order (set before linking; empty = none).
  Program(const ShaderLibrary& library, const std::vector<std::string>& vertexFiles,
          const std::vector<std::string>& geometryFiles, const std::vector<std::string>& fragmentFiles,
          const std::vector<std::string>& feedbackVaryings = {});

  /// A compute program (GL 4.3+) from several files concatenated in order.
  static Program compute(const ShaderLibrary& library, const std::vector<std::string>& files);

  GLuint id() const { return program_.id(); }
  void use() const;
  /// Uniform location (cached); -1 for a uniform the compiler removed (setting it is a no-op).
  GLint location(const char* name) const;
  void set(const char* name, int v) const;
  void set(const char* name, float v) const;
  void set(const char* name, const glm::vec2& v) const;
  void set(const char* name, const glm::vec3& v) const;
  void set(const char* name, const glm::vec4& v) const;
  void set(const char* name, const glm::ivec2& v) const;
  void set(const char* name, const glm::mat4& v) const;

 private:
  struct Stage {
    GLenum type;
    const std::vector<std::string>* files;
  };
  Program(const ShaderLibrary& library, std::initializer_list<Stage> stages,
          const std::vector<std::string>& feedbackVaryings);
  ProgramName program_;
  mutable std::unordered_map<std::string, GLint> locations_;
};

}  // namespace shadowvol::gl
