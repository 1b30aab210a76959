// Typed errors of the physics core. The core never prints or aborts; the LIGGGHTS
// adapters catch these and turn them into "ERROR: <style> (id X): ..." messages.
#pragma once

#include <stdexcept>
#include <string>

namespace wiregrain {

// A parameter or input outside its domain (negative stiffness, degenerate hull, ...).
// `argument` names the offending keyword or argument as the user wrote it.
class InvalidArgument : public std::invalid_argument {
 public:
  InvalidArgument(std::string argument, const std::string& what)
      : std::invalid_argument(what), argument_(std::move(argument)) {}
  const std::string& argument() const noexcept { return argument_; }

 private:
  std::string argument_;
};

// A state the numerics cannot continue from (NaN position, exploded velocity, ...).
class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace wiregrain
