#include "json_text.h"

#include <set>
#include <string>
#include <vector>

#include "shadowvol/error.h"

namespace shadowvol {

using json = nlohmann::json;

namespace {

// "line L, column C" of a byte offset into text.
std::string lineColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, col = 1;
  for (std::size_t k = 0; k + 1 < byte && k < text.size(); ++k) {
    if (text[k] == '\n') { ++line; col = 1; } else { ++col; }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

// The shape rules of a JSON input, checked in one pass over its events without building
// anything: nesting at most kMaxJsonDepth deep, and no key twice in one object (it would silently
// keep the last value; refused, as unknown keys are). A separate pass because nlohmann's callback
// parser, which did this before, rescans the enclosing array at every object's end: a file of
// 160,000 objects took 8.5 s to parse, and 10 MB over a minute.
class JsonShapeCheck : public nlohmann::json_sax<json> {
 public:
  explicit JsonShapeCheck(const std::string& source) : source_(source) {}
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override {
    open();
    keys_.emplace_back();
    return true;
  }
  bool key(string_t& k) override {
    if (!keys_.back().insert(k).second) {
      std::string quoted = "\"";  // built with += (GCC 12 warns falsely on "..." + std::string)
      quoted += k;
      quoted += '"';
      throw InputError(source_, "", quoted, "a key given twice in one JSON object");
    }
    return true;
  }
  bool end_object() override {
    keys_.pop_back();
    --depth_;
    return true;
  }
  bool start_array(std::size_t) override {
    open();
    return true;
  }
  bool end_array() override {
    --depth_;
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
    return false;  // the DOM parse names it
  }

 private:
  static constexpr int kMaxJsonDepth = 64;
  void open() {
    if (++depth_ > kMaxJsonDepth)
      throw InputError(source_, "", "", "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  }
  const std::string& source_;
  int depth_ = 0;
  std::vector<std::set<std::string>> keys_;  // of each object being parsed, innermost last
};

}  // namespace

json parseJsonText(const std::string& text, const std::string& source) {
  // JSON text holds no NUL byte (a string spells it \u0000), and nlohmann's lexer would take one
  // for the end of the input, ignoring whatever follows it.
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
    throw InputError(source, "", "", "a NUL byte at " + lineColumn(text, nul + 1) + ": not JSON text");
  JsonShapeCheck shape(source);
  json::sax_parse(text, &shape);  // throws InputError for the shape; a syntax error is left to parse
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(source, "", "", "malformed JSON at " + lineColumn(text, e.byte) + ": " + e.what());
  } catch (const json::out_of_range& e) {
    // "... number overflow parsing '1e400'": find the token for its position.
    const std::string what = e.what();
    const auto q = what.find('\''), q2 = what.rfind('\'');
    const std::string token = q != std::string::npos && q2 > q ? what.substr(q + 1, q2 - q - 1) : "";
    const std::size_t at = token.empty() ? std::string::npos : text.find(token);
    throw InputError(source, "", token,
                     "a number beyond double precision's range" +
                         (at == std::string::npos ? std::string() : " at " + lineColumn(text, at + 1)));
  }
}

}  // namespace shadowvol
