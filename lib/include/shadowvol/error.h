// Bad input from a user (the second error tier): a file, a scene field, a command-line value.
// Caught at the boundary (the command line), printed, exit code 1, nothing partial written.
#pragma once

#include <charconv>
#include <cmath>
#include <concepts>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

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
/// A problem that names another field of the same source may write it as ${field} ("needs
/// ${blur}") when it is given as a MarkedProblem, text the library wrote itself (no path, value or
/// other user text in it: those are never read for marks): what() and problem() show the
/// library's name ("needs blur"), a front end its own spelling of it (problemNamed: the command
/// line's "needs --blur"). A mark is a lower-case letter, then letters, digits, dots and spaces.
struct MarkedProblem {
  std::string text;
};

class InputError : public std::runtime_error {
 public:
  /// A field's name in a front end's words; the library's name where it has none.
  using FieldNamer = std::function<std::string(std::string_view field)>;

  InputError(std::string source, std::string field, std::string value, const std::string& problem)
      : std::runtime_error(compose(source, field, value, problem)),
        source_(std::move(source)),
        field_(std::move(field)),
        value_(std::move(value)),
        problem_(problem) {}
  InputError(std::string source, std::string field, std::string value, const MarkedProblem& problem)
      : std::runtime_error(compose(source, field, value, expand(problem.text, nullptr))),
        source_(std::move(source)),
        field_(std::move(field)),
        value_(std::move(value)),
        problem_(problem.text),
        marked_(true) {}

  const std::string& source() const { return source_; }  ///< file path, options struct or "command line"
  const std::string& field() const { return field_; }    ///< JSON pointer, member or option; may be empty
  const std::string& value() const { return value_; }    ///< offending value as text; may be empty
  std::string problem() const { return marked_ ? expand(problem_, nullptr) : problem_; }  ///< what is wrong with it
  /// The problem with each ${field} of a MarkedProblem named by `name` (a front end's flag or
  /// keyword); an unmarked problem as it is.
  std::string problemNamed(const FieldNamer& name) const { return marked_ ? expand(problem_, name) : problem_; }
  /// Whether the problem was given as a MarkedProblem.
  bool hasFieldMarks() const { return marked_; }
  /// The problem as given (a MarkedProblem's marks kept): for a rethrow that adds to it, with
  /// hasFieldMarks() telling which constructor to give it to.
  const std::string& problemTemplate() const { return problem_; }

 private:
  static std::string expand(const std::string& problem, const FieldNamer& name) {
    std::string s;
    std::size_t from = 0;
    for (std::size_t at; (at = problem.find("${", from)) != std::string::npos;) {
      const std::size_t end = problem.find('}', at);
      if (end == std::string::npos) break;
      const std::string_view field(problem.data() + at + 2, end - at - 2);
      if (!isFieldMark(field)) {  // not a mark: "${" in the library's own text, kept
        s.append(problem, from, at + 2 - from);
        from = at + 2;
        continue;
      }
      s.append(problem, from, at - from);
      s += name ? name(field) : std::string(field);
      from = end + 1;
    }
    return s.append(problem, from);
  }
  // A mark's field, as the library's field names: a lower-case letter, then letters, digits, dots
  // and spaces, not ending in a space ("refine steps", "volumeOptions.bias").
  static bool isFieldMark(std::string_view field) {
    if (field.empty() || field.front() < 'a' || field.front() > 'z' || field.back() == ' ') return false;
    for (char c : field)
      if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' ' || c == '.'))
        return false;
    return true;
  }
  static std::string compose(const std::string& source, const std::string& field, const std::string& value,
                             const std::string& problem) {
    std::string s = source;
    if (!field.empty()) s += ": " + field;
    if (!value.empty()) s += " = " + value;
    s += ": " + problem;
    return s;
  }
  std::string source_, field_, value_, problem_;
  bool marked_ = false;
};

/// An option that contradicts another, or changes nothing without another (refinement's options
/// without refinement, blur's offset without blur): a usage error, exit 2 on the command line,
/// where an InputError about one option's value is bad input, exit 1.
class OptionConflict : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace shadowvol
