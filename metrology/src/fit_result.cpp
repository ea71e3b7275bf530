// Names of the fit error codes (stable strings for logs and protocol replies).
#include "imess/metrology/fit_result.hpp"

namespace imess::metrology {

std::string_view to_string(FitErrorCode code) noexcept {
  switch (code) {
    case FitErrorCode::TooFewPoints: return "too_few_points";
    case FitErrorCode::NonFiniteInput: return "non_finite_input";
    case FitErrorCode::CoincidentPoints: return "coincident_points";
    case FitErrorCode::CollinearPoints: return "collinear_points";
    case FitErrorCode::CoplanarPoints: return "coplanar_points";
    case FitErrorCode::NotConverged: return "not_converged";
    case FitErrorCode::IllConditioned: return "ill_conditioned";
    case FitErrorCode::InconsistentApproach: return "inconsistent_approach";
    case FitErrorCode::InvalidArgument: return "invalid_argument";
    case FitErrorCode::NonPositiveSize: return "non_positive_size";
    case FitErrorCode::AmbiguousSolution: return "ambiguous_solution";
    case FitErrorCode::ConeIsCylinder: return "cone_is_cylinder";
  }
  return "unknown";
}

}  // namespace imess::metrology
