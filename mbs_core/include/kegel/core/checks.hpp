// Argument checks for validated value types.
//
// Every check throws std::invalid_argument with a message that names the type, the field,
// the offending value and what was expected, e.g.
//   "LubricantParameters.vogel_K_Pas = -0.1: expected a finite value > 0".
// nanobind turns std::invalid_argument into Python's ValueError.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace kegel::detail {

[[noreturn]] inline void fail(const char* owner, const char* field, double value,
                              const std::string& expected) {
  std::ostringstream os;
  os.precision(15);
  os << owner << "." << field << " = " << value << ": expected " << expected;
  throw std::invalid_argument(os.str());
}

inline void require_finite(const char* owner, const char* field, double value) {
  if (!std::isfinite(value)) fail(owner, field, value, "a finite value");
}

inline void require_positive(const char* owner, const char* field, double value) {
  if (!std::isfinite(value) || !(value > 0.0)) fail(owner, field, value, "a finite value > 0");
}

inline void require_nonnegative(const char* owner, const char* field, double value) {
  if (!std::isfinite(value) || value < 0.0) fail(owner, field, value, "a finite value >= 0");
}

inline void require_range(const char* owner, const char* field, double value, double lo,
                          double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    std::ostringstream os;
    os.precision(15);
    os << "a finite value in [" << lo << ", " << hi << "]";
    fail(owner, field, value, os.str());
  }
}

}  // namespace kegel::detail
