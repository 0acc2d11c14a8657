// An enum's spellings, written once. Each enum that a user names in text (the command line, scene
// and depth files, reports, the Python module) has one table of its values' names beside its
// declaration (kCaptureModeNames, ...); its toString and parse functions, the command line's lists
// of choices and the messages that list them all read that table.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace shadowvol {

template <class E>
struct EnumName {
  E value;
  const char* name;
};

template <class E, std::size_t N>
using EnumNames = std::array<EnumName<E>, N>;

/// The name of `value` in `table`, or `absent` when the table has no entry for it.
template <class E, std::size_t N>
constexpr const char* nameIn(const EnumNames<E, N>& table, E value, const char* absent = "?") {
  for (const EnumName<E>& e : table)
    if (e.value == value) return e.name;
  return absent;
}

/// Sets `value` to the entry of `table` named exactly `text`; false, `value` untouched, when none is.
template <class E, std::size_t N>
bool parseIn(const EnumNames<E, N>& table, std::string_view text, E& value) {
  for (const EnumName<E>& e : table)
    if (text == e.name) {
      value = e.value;
      return true;
    }
  return false;
}

/// The names in the table's order, after `first` (choices that are no value of the enum, such as
/// the command line's "auto"), without those in `except`: a command line's list of choices.
template <class E, std::size_t N>
std::vector<std::string> namesIn(const EnumNames<E, N>& table, std::initializer_list<const char*> first = {},
                                 std::initializer_list<E> except = {}) {
  std::vector<std::string> names(first.begin(), first.end());
  for (const EnumName<E>& e : table) {
    bool skip = false;
    for (E x : except) skip = skip || x == e.value;
    if (!skip) names.emplace_back(e.name);
  }
  return names;
}

/// "a, b or c" for a message (each name in double quotes with `quoted`).
inline std::string choicesText(const std::vector<std::string>& names, bool quoted = false) {
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k) text += k + 1 == names.size() ? " or " : ", ";
    text += quoted ? "\"" + names[k] + "\"" : names[k];
  }
  return text;
}

}  // namespace shadowvol
