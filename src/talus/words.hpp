#pragma once
// Numbers in words for what the laws report of themselves (their parameters, their errors), with
// the standard library alone: src/ has no formatting library.
#include <cstdio>
#include <string>

namespace talus {

/// printf's formatting of `values` into `format`, as a string (at most 255 characters).
template <class... Values> std::string format_words(const char* format, Values... values) {
  char out[256];
  std::snprintf(out, sizeof out, format, values...);
  return out;
}

} // namespace talus
