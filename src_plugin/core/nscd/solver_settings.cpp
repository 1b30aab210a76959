// SolverSettings (solver_settings.h).
#include "core/nscd/solver_settings.h"

#include <string>

#include "core/common/errors.h"
#include "core/common/validation.h"

namespace wiregrain {

void SolverSettings::validate() const {
  require_nonnegative("tolerance", tolerance);
  if (max_iterations < 1) {
    throw InvalidArgument("max_iterations", "max_iterations must be >= 1, got " +
                                                std::to_string(max_iterations));
  }
  if (!(relaxation > 0.0 && relaxation < 2.0)) {
    throw InvalidArgument("relaxation", "relaxation must be in (0, 2), got " +
                                            format_number(relaxation));
  }
  if (!(subspace_regularization > 0.0 && subspace_regularization < 1.0)) {
    throw InvalidArgument("subspace_regularization", "subspace_regularization must be in (0, 1), got " +
                                                         format_number(subspace_regularization));
  }
  if (!(subspace_closing >= 0.0 && subspace_closing <= 1.0)) {
    throw InvalidArgument("subspace_closing", "subspace_closing must be in [0, 1], got " + format_number(subspace_closing));
  }
  if (freeze < 0) throw InvalidArgument("freeze", "freeze must be >= 0 sweeps, got " + std::to_string(freeze));
  if (freeze > 0 && measure == ConvergenceMeasure::increment) {
    throw InvalidArgument("freeze", "freeze needs a measure with the Siconos error (natural_map or "
                                    "increment_then_natural_map): the increment does not see frozen contacts");
  }
}

}  // namespace wiregrain
