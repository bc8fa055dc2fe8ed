// Bad input: a scene or study file, a --set value, or a scene built in code
// that breaks one of its rules. The message names where the value came from
// (file:line:column, or the --set that gave it) and the field.
#pragma once

#include <stdexcept>

namespace unfurl::input {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace unfurl::input
