// The value of one characteristic from the fitted (or nominal) features: the definitions of
// docs/metrology.md §15.
#pragma once

#include <vector>

#include "imess/metrology/inspection.hpp"

namespace imess::metrology::detail {

// `fitted` holds one FeatureResult per plan feature, in plan order.
CharacteristicResult evaluate_characteristic(const Characteristic& c, const InspectionPlan& plan,
                                             const std::vector<FeatureResult>& fitted);

}  // namespace imess::metrology::detail
