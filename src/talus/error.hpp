#pragma once
// The exceptions talus throws, in every engine. Neither engine prints: callers decide what the
// user sees.
#include <stdexcept>
#include <string>

namespace talus {

/// Bad input: a parameter out of its allowed range, an inconsistent setup.
class InvalidArgument : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

/// The run became numerically unstable; what() holds the diagnosis.
class InstabilityError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Throws InvalidArgument with `message` unless `condition` holds.
inline void require(bool condition, const std::string& message) {
  if (!condition) throw InvalidArgument(message);
}

} // namespace talus
