// Bad input from a user (the second error tier): a file, a scene field, a command-line value.
// Caught at the boundary (the command line), printed, exit code 1, nothing partial written.
#pragma once

#include <charconv>
#include <cmath>
#include <concepts>
#include <stdexcept>
#include <string>

namespace shadowvol {

/// A number as a message shows it: the shortest text that reads back as the same value of its type
/// (std::to_chars): 2e-07, 0.1 (a float's 0.1 too, not the double 0.10000000149011612), 1e+30,
/// nan, inf. (std::to_string's six decimals print 2e-7 as 0.000000.)
template <std::floating_point T>
std::string numberText(T v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

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

/// An option that contradicts another, or changes nothing without another (refinement's options
/// without refinement, blur's offset without blur): a usage error, exit 2 on the command line,
/// where an InputError about one option's value is bad input, exit 1.
class OptionConflict : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace shadowvol
