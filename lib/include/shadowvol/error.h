// Bad input from a user (the second error tier): a file, a scene field, a command-line value.
// Caught at the boundary (the command line), printed, exit code 1, nothing partial written.
#pragma once

#include <stdexcept>
#include <string>

namespace shadowvol {

/// An input the user can fix. what() is a complete sentence naming the source (file or option),
/// the field (a JSON pointer such as "/light/fov" or an option name) and the offending value.
/// The library names its own terms (a file and JSON pointer, or an options struct and its member,
/// such as source "RenderOptions", field "imageWidth x imageHeight"); a front end that spells them
/// differently (the command line's flags) rethrows with source(), field() and problem() mapped.
class InputError : public std::runtime_error {
 public:
  InputError(std::string source, std::string field, std::string value, const std::string& problem)
      : std::runtime_error(compose(source, field, value, problem)),
        source_(std::move(source)),
        field_(std::move(field)),
        value_(std::move(value)),
        problem_(problem) {}

  const std::string& source() const { return source_; }  ///< file path, options struct or "command line"
  const std::string& field() const { return field_; }    ///< JSON pointer, member or option; may be empty
  const std::string& value() const { return value_; }    ///< offending value as text; may be empty
  const std::string& problem() const { return problem_; }  ///< what is wrong with it

 private:
  static std::string compose(const std::string& source, const std::string& field, const std::string& value,
                             const std::string& problem) {
    std::string s = source;
    if (!field.empty()) s += ": " + field;
    if (!value.empty()) s += " = " + value;
    s += ": " + problem;
    return s;
  }
  std::string source_, field_, value_, problem_;
};

}  // namespace shadowvol
