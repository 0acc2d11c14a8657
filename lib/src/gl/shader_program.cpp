#include "shadowvol/gl/shader_program.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "shadowvol/error.h"
#include "shadowvol/gl/gl_error.h"

namespace shadowvol::gl {

ShaderLibrary::ShaderLibrary(std::filesystem::path overrideDir) : dir_(std::move(overrideDir)) {
  bool fromEnvironment = false;
  if (dir_.empty()) {
    if (const char* env = std::getenv("SHADOWVOL_SHADER_DIR"); env && *env) dir_ = env, fromEnvironment = true;
  }
  // A folder that is not there would silently mean the embedded shaders (a misspelt variable).
  std::error_code ec;
  if (!dir_.empty() && !std::filesystem::is_directory(dir_, ec))
    throw InputError(fromEnvironment ? "environment" : "RendererOptions",
                     fromEnvironment ? "SHADOWVOL_SHADER_DIR" : "shaderDir", dir_.string(), "not a folder");
}

std::pair<std::string, std::string> ShaderLibrary::load(const std::string& name) const {
  if (!dir_.empty()) {
    const std::filesystem::path p = dir_ / name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(p, ec)) {
      std::ifstream in(p, std::ios::binary);
      std::ostringstream s;
      s << in.rdbuf();
      if (!in.good() && !in.eof()) throw GlError(p.string() + ": cannot read the shader file");
      return {s.str(), p.string()};
    }
  }
  auto text = embeddedShader(name);
  if (!text) throw GlError("shaders/" + name + ": no such shader (neither embedded nor in the override directory)");
  return {*text, "shaders/" + name + " (embedded)"};
}

namespace {

Shader compile(GLenum type, const std::vector<std::string>& texts, const std::string& origin) {
  Shader s(glCreateShader(type));
  if (!s) throw GlError(origin + ": glCreateShader failed");
  std::vector<const char*> src;
  for (const auto& t : texts) src.push_back(t.c_str());
  glShaderSource(s.id(), GLsizei(src.size()), src.data(), nullptr);
  glCompileShader(s.id());
  GLint ok = 0, len = 0;
  glGetShaderiv(s.id(), GL_COMPILE_STATUS, &ok);
  glGetShaderiv(s.id(), GL_INFO_LOG_LENGTH, &len);
  if (!ok) {
    std::string log(std::size_t(std::max(len, 1)), '\0');
    glGetShaderInfoLog(s.id(), len, nullptr, log.data());
    throw GlError(origin + ": compile failed:\n" + log);
  }
  return s;
}

/// Loads the files of one stage; `origin` names them all ("a (embedded) + b (embedded)").
std::vector<std::string> loadAll(const ShaderLibrary& library, const std::vector<std::string>& files,
                                 std::string& origin) {
  std::vector<std::string> texts;
  for (std::size_t k = 0; k < files.size(); ++k) {
    auto [text, from] = library.load(files[k]);
    texts.push_back(std::move(text));
    origin += (k ? " + " : "") + from;
  }
  if (files.size() > 1) origin += " (log lines are string:line, string = index in this list)";
  return texts;
}

}  // namespace

Program::Program(const ShaderLibrary& library, const std::string& vertexFile, const std::string& fragmentFile)
    : Program(library, std::vector<std::string>{vertexFile}, std::vector<std::string>{fragmentFile}) {}

Program::Program(const ShaderLibrary& library, const std::vector<std::string>& vertexFiles,
                 const std::vector<std::string>& fragmentFiles)
    : Program(library, vertexFiles, {}, fragmentFiles) {}

Program::Program(const ShaderLibrary& library, const std::vector<std::string>& vertexFiles,
                 const std::vector<std::string>& geometryFiles, const std::vector<std::string>& fragmentFiles,
                 const std::vector<std::string>& feedbackVaryings)
    : Program(library,
              {{GL_VERTEX_SHADER, &vertexFiles}, {GL_GEOMETRY_SHADER, &geometryFiles}, {GL_FRAGMENT_SHADER, &fragmentFiles}},
              feedbackVaryings) {}

Program Program::compute(const ShaderLibrary& library, const std::vector<std::string>& files) {
  return Program(library, {{GL_COMPUTE_SHADER, &files}}, {});
}

Program::Program(const ShaderLibrary& library, std::initializer_list<Stage> list,
                 const std::vector<std::string>& feedbackVaryings) {
  std::vector<Shader> stages;
  std::string all;
  for (const auto& [type, files] : list) {
    if (files->empty()) continue;
    std::string origin;
    const auto texts = loadAll(library, *files, origin);
    stages.push_back(compile(type, texts, origin));
    all += (all.empty() ? "" : " + ") + origin;
  }
  program_ = ProgramName(glCreateProgram());
  if (!program_) throw GlError(all + ": glCreateProgram failed");
  for (const auto& st : stages) glAttachShader(program_.id(), st.id());
  if (!feedbackVaryings.empty()) {
    std::vector<const char*> names;
    for (const auto& v : feedbackVaryings) names.push_back(v.c_str());
    glTransformFeedbackVaryings(program_.id(), GLsizei(names.size()), names.data(), GL_INTERLEAVED_ATTRIBS);
  }
  glLinkProgram(program_.id());
  GLint ok = 0, len = 0;
  glGetProgramiv(program_.id(), GL_LINK_STATUS, &ok);
  glGetProgramiv(program_.id(), GL_INFO_LOG_LENGTH, &len);
  for (const auto& st : stages) glDetachShader(program_.id(), st.id());
  if (!ok) {
    std::string log(std::size_t(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program_.id(), len, nullptr, log.data());
    throw GlError(all + ": link failed:\n" + log);
  }
}

void Program::use() const {
  SV_GL(glUseProgram(program_.id()));
}

GLint Program::location(const char* name) const {
  auto it = locations_.find(name);
  if (it != locations_.end()) return it->second;
  const GLint loc = glGetUniformLocation(program_.id(), name);
  locations_.emplace(name, loc);
  return loc;
}

void Program::set(const char* name, int v) const {
  SV_GL(glUniform1i(location(name), v));
}
void Program::set(const char* name, float v) const {
  SV_GL(glUniform1f(location(name), v));
}
void Program::set(const char* name, const glm::vec2& v) const {
  SV_GL(glUniform2fv(location(name), 1, glm::value_ptr(v)));
}
void Program::set(const char* name, const glm::vec3& v) const {
  SV_GL(glUniform3fv(location(name), 1, glm::value_ptr(v)));
}
void Program::set(const char* name, const glm::vec4& v) const {
  SV_GL(glUniform4fv(location(name), 1, glm::value_ptr(v)));
}
void Program::set(const char* name, const glm::ivec2& v) const {
  SV_GL(glUniform2iv(location(name), 1, glm::value_ptr(v)));
}
void Program::set(const char* name, const glm::mat4& v) const {
  SV_GL(glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(v)));
}

}  // namespace shadowvol::gl
